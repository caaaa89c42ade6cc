/// @file circuit_discover.cpp
/// The candidate terms of a circuit's balance equations and their reading in words
/// (circuit_discover.hpp); the regression is stlsq.hpp's.
#include "hstmon_gap/circuit_discover.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "stlsq.hpp"

namespace hstmon::gap {

namespace {

using Model = host::HostCircuitModel;
constexpr int kNodes = Model::kNodes;
constexpr double kOmega0 = 0.5;  // tanh regularisation speed of a Coulomb term [rad/s], as the thesis library's

/// One row of an evaluated log, as a candidate reads it.
struct Row {
  const std::vector<double>& z;     ///< full vector [Pa, rad/s]
  const std::vector<double>& zdot;  ///< slopes [Pa/s, rad/s²]
  double t;                         ///< time since the log's start [s]
};

/// One candidate term: its form, coefficient unit, physical meaning, the element it
/// belongs to (−1: none) and its value at a row.
struct Candidate {
  std::string form, unit, meaning;
  int element = -1;
  std::function<double(const Row&)> value;
};

double sroot(double d) { return d < 0 ? -std::sqrt(-d) : std::sqrt(d); }

// The name of full-vector entry z.
std::string name_of(const circuit_tools::LoadedCircuit& c, int z) {
  return z < kNodes ? c.file.nodes[static_cast<std::size_t>(z)] : c.file.shafts[static_cast<std::size_t>(z - kNodes)];
}

void add(std::vector<Candidate>& v, Candidate c) {
  if (std::none_of(v.begin(), v.end(), [&](const Candidate& o) { return o.form == c.form; })) v.push_back(std::move(c));
}

auto entry(int z) {
  const auto i = static_cast<std::size_t>(z);
  return [i](const Row& r) { return r.z[i]; };
}
auto difference(int a, int b) {
  const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
  return [i, j](const Row& r) { return r.z[i] - r.z[j]; };
}

std::vector<Candidate> node_candidates(const circuit_tools::LoadedCircuit& c, int node) {
  const host::HostCircuit& d = c.file.circuit;
  const std::string N = name_of(c, node);
  std::vector<Candidate> v;
  add(v, {"1", "m^3/s", "const", -1, [](const Row&) { return 1.0; }});
  add(v, {N, "m^3/(s*Pa)", "leak", -1, entry(node)});
  std::vector<int> shafts;
  for (int k = 0; k < d.n_elements; ++k) {
    const circuit::Element& el = d.elements[k];
    if (!circuit::has_ports(el.kind) || (el.a != node && el.b != node) || el.shaft < 0) continue;
    if (std::find(shafts.begin(), shafts.end(), el.shaft) != shafts.end()) continue;
    shafts.push_back(el.shaft);
    add(v, {name_of(c, kNodes + el.shaft), "m^3/rad", "displacement", k, entry(kNodes + el.shaft)});
  }
  for (int k = 0; k < d.n_elements; ++k) {
    const circuit::Element& el = d.elements[k];
    if (!circuit::has_ports(el.kind) || (el.a != node && el.b != node)) continue;
    const std::string ab = name_of(c, el.a) + "-" + name_of(c, el.b);
    add(v, {ab, "m^3/(s*Pa)", "laminar", k, difference(el.a, el.b)});
    if (el.kind == circuit::ElementKind::kOrifice || el.kind == circuit::ElementKind::kPoppet) {
      const auto dp = difference(el.a, el.b);
      add(v, {"sqrt(" + ab + ")", "m^3/(s*sqrt(Pa))", "orifice", k, [dp](const Row& r) { return sroot(dp(r)); }});
    }
  }
  for (int s : shafts) {
    const auto i = static_cast<std::size_t>(node), w = static_cast<std::size_t>(kNodes + s);
    add(v, {N + "*" + name_of(c, kNodes + s), "m^3/(Pa*rad)", "generic", -1,
            [i, w](const Row& r) { return r.z[i] * r.z[w]; }});
  }
  const auto i = static_cast<std::size_t>(node);
  add(v, {"d" + N + "/dt", "m^3/Pa", "compliance", -1, [i](const Row& r) { return r.zdot[i]; }});
  add(v, {"t", "m^3/s^2", "drift", -1, [](const Row& r) { return r.t; }});
  return v;
}

std::vector<Candidate> shaft_candidates(const circuit_tools::LoadedCircuit& c, int shaft) {
  const host::HostCircuit& d = c.file.circuit;
  const int zw = kNodes + shaft;
  const auto w = static_cast<std::size_t>(zw);
  const std::string W = name_of(c, zw);
  std::vector<Candidate> v;
  add(v, {"tanh(" + W + "/0.5)", "N*m", "coulomb", -1, [w](const Row& r) { return std::tanh(r.z[w] / kOmega0); }});
  add(v, {"1", "N*m", "const", -1, [](const Row&) { return 1.0; }});
  add(v, {W, "N*m*s/rad", "viscous", -1, entry(zw)});
  std::vector<int> machines;
  for (int k = 0; k < d.n_elements; ++k) {
    const circuit::Element& el = d.elements[k];
    if (!circuit::has_shaft(el.kind) || !circuit::has_ports(el.kind) || el.shaft != shaft) continue;
    machines.push_back(k);
    add(v, {name_of(c, el.a) + "-" + name_of(c, el.b), "m^3/rad", "machine_dp", k, difference(el.a, el.b)});
  }
  add(v,
      {W + "*|" + W + "|", "N*m*s^2/rad^2", "windage", -1, [w](const Row& r) { return r.z[w] * std::fabs(r.z[w]); }});
  for (int k : machines) {
    const circuit::Element& el = d.elements[k];
    const auto dp = difference(el.a, el.b);
    add(v, {"(" + name_of(c, el.a) + "-" + name_of(c, el.b) + ")*" + W, "m^3*s/rad^2", "generic", k,
            [dp, w](const Row& r) { return dp(r) * r.z[w]; }});
  }
  add(v, {"d" + W + "/dt", "kg*m^2", "inertia", -1, [w](const Row& r) { return r.zdot[w]; }});
  add(v, {"t", "N*m/s", "drift", -1, [](const Row& r) { return r.t; }});
  return v;
}

// Weighted design matrix (rows / σ) of the candidates, and the weighted target.
void design(const CircuitArrData& a, std::size_t eq, const std::vector<Candidate>& cand, Eigen::MatrixXd& X,
            Eigen::VectorXd& y) {
  const std::size_t n = a.rows.size();
  X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cand.size()));
  y.resize(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double wt = 1.0 / a.sigma[eq][i];
    const Row row{a.z[i], a.zdot[i], a.t_since_start[i]};
    y[static_cast<Eigen::Index>(i)] = a.r[eq][i] * wt;
    for (std::size_t j = 0; j < cand.size(); ++j) {
      X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = cand[j].value(row) * wt;
    }
  }
}

// The element's name, "" for none.
std::string element_name(const circuit_tools::LoadedCircuit& c, int k) {
  return k >= 0 && static_cast<std::size_t>(k) < c.file.elements.size() ? c.file.elements[static_cast<std::size_t>(k)]
                                                                        : "";
}

// An orifice's or poppet's change of flow coefficient the term says, in words.
std::string orifice_reading(const circuit_tools::LoadedCircuit& c, const CircuitEquation& q, const Candidate& cd,
                            double v) {
  const circuit::Element& el = c.file.circuit.elements[cd.element];
  // At port a the term is an outflow along the element, at port b an inflow.
  const double dk = el.a == q.z ? v : -v;
  const Model m(c.file.circuit, c.values.params, c.values.inputs);
  const double k = m.coeffs(cd.element).c[0];
  char b[320];
  if (k > 0) {
    std::snprintf(b, sizeof b,
                  "the flow through %s (%s) is off: its coefficient by %+.3g m^3/(s*sqrt(Pa)), %+.1f %% of the model's "
                  "at the file's inputs",
                  element_name(c, cd.element).c_str(), cd.form.c_str(), dk, 100.0 * dk / k);
  } else {
    std::snprintf(b, sizeof b, "a flow through %s (%s), shut in the model: coefficient %+.3g m^3/(s*sqrt(Pa))",
                  element_name(c, cd.element).c_str(), cd.form.c_str(), dk);
  }
  return b;
}

// The physical reading of the leading term, in words, with the circuit's names.
std::string reading(const circuit_tools::LoadedCircuit& c, const CircuitEquation& q, const Candidate& cd, double v) {
  char b[320];
  const std::string at = q.name.substr(q.name.find(':') + 1);
  const char* more = v > 0 ? "loss" : "gain";
  const std::string& m = cd.meaning;
  if (m == "orifice") return orifice_reading(c, q, cd, v);
  if (m == "leak" && v > 0) {
    std::snprintf(b, sizeof b, "a flow loss at node %s proportional to %s: leakage to drain, R = %.3g Pa*s/m^3",
                  at.c_str(), cd.form.c_str(), 1.0 / v);
  } else if (m == "leak") {
    std::snprintf(b, sizeof b, "a flow gain at node %s proportional to %s (%.3g m^3/(s*Pa)): an inflow the model lacks",
                  at.c_str(), cd.form.c_str(), -v);
  } else if (m == "const" && !q.shaft) {
    std::snprintf(b, sizeof b, "a constant flow %s at node %s of %.3g m^3/s (%.3g L/min)", more, at.c_str(),
                  std::fabs(v), std::fabs(v) * 6e4);
  } else if (m == "displacement") {
    std::snprintf(b, sizeof b,
                  "a flow %s at node %s proportional to the speed of %s: %.3g m^3/rad (a displacement or volumetric "
                  "efficiency error of %s)",
                  more, at.c_str(), cd.form.c_str(), std::fabs(v), element_name(c, cd.element).c_str());
  } else if (m == "laminar") {
    std::snprintf(b, sizeof b, "a flow %s at node %s proportional to %s (across %s): a laminar path, R = %.3g Pa*s/m^3",
                  more, at.c_str(), cd.form.c_str(), element_name(c, cd.element).c_str(), 1.0 / std::fabs(v));
  } else if (m == "compliance") {
    std::snprintf(b, sizeof b, "a compliance the model lacks at node %s: %.3g m^3/Pa", at.c_str(), v);
  } else if (m == "coulomb" || (m == "const" && q.shaft)) {
    std::snprintf(b, sizeof b, "a %s torque on shaft %s: Coulomb friction Tc = %.3g N*m", v > 0 ? "braking" : "driving",
                  at.c_str(), std::fabs(v));
  } else if (m == "viscous") {
    std::snprintf(b, sizeof b,
                  "a torque %s on shaft %s proportional to its speed: extra viscous friction %.3g N*m*s/rad", more,
                  at.c_str(), v);
  } else if (m == "machine_dp") {
    std::snprintf(b, sizeof b,
                  "a torque %s on shaft %s proportional to the pressure difference across %s (%s): its displacement or "
                  "mechanical efficiency off by %.3g m^3/rad",
                  more, at.c_str(), element_name(c, cd.element).c_str(), cd.form.c_str(), v);
  } else if (m == "windage") {
    std::snprintf(b, sizeof b,
                  "a torque %s on shaft %s proportional to its speed squared (churning, windage): %.3g N*m*s^2/rad^2",
                  more, at.c_str(), v);
  } else if (m == "inertia") {
    std::snprintf(b, sizeof b, "an inertia error on shaft %s: J off by %.3g kg*m^2", at.c_str(), v);
  } else if (m == "drift") {
    std::snprintf(b, sizeof b, "an imbalance of %s drifting with time since start: %.3g %s", q.name.c_str(), v,
                  cd.unit.c_str());
  } else {
    std::snprintf(b, sizeof b, "an imbalance of %s proportional to %s: %.3g %s", q.name.c_str(), cd.form.c_str(), v,
                  cd.unit.c_str());
  }
  return b;
}

}  // namespace

std::optional<CircuitDiscovery> discover_circuit(const circuit_tools::LoadedCircuit& c, const CircuitArrData& fit,
                                                 const CircuitArrData& check, int eq) {
  if (eq < 0 || static_cast<std::size_t>(eq) >= fit.equations.size() ||
      fit.equations.size() != check.equations.size()) {
    return std::nullopt;
  }
  const auto e = static_cast<std::size_t>(eq);
  if (!fit.available[e] || !check.available[e] || fit.rows.size() < 20 || check.rows.size() < 20) return std::nullopt;
  const CircuitEquation& q = fit.equations[e];
  const std::vector<Candidate> all = q.shaft ? shaft_candidates(c, q.z - kNodes) : node_candidates(c, q.z);
  const std::optional<detail::StlsqChoice> ch = detail::stlsq_choose_on(
      fit, check, [&](const CircuitArrData& a, Eigen::MatrixXd& X, Eigen::VectorXd& y) { design(a, e, all, X, y); });
  if (!ch) return std::nullopt;
  CircuitDiscovery d;
  d.equation = q.name;
  detail::take_judgement(*ch, d);
  for (std::size_t j = 0; j < ch->active.size(); ++j) {
    const Candidate& cd = all[static_cast<std::size_t>(ch->active[j])];
    d.terms.push_back({cd.form, cd.unit, ch->coefficient[j], ch->std_error[j]});
  }
  d.reading = reading(c, q, all[static_cast<std::size_t>(ch->active.front())], d.terms.front().coefficient);
  return d;
}

}  // namespace hstmon::gap
