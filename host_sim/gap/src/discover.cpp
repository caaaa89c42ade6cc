/// @file discover.cpp
/// STLSQ on the located equation's imbalance (see discover.hpp, docs/gap.md): the thesis
/// rig's candidate terms; the regression itself is stlsq.hpp's.
#include "hstmon_gap/discover.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "stlsq.hpp"

namespace hstmon::gap {

namespace {

constexpr std::size_t kMi = 0, kMo = 1, kPp = 2, kW = 3;
constexpr double kOmega0 = 0.5;  // tanh regularisation speed of a Coulomb term [rad/s], as the library's

// One candidate term: its form, coefficient unit, what a term of this form means
// physically, and its value (derivative terms: the equation's own state derivative).
struct Candidate {
  std::string form, unit, meaning;
  std::function<double(const TermInputs&)> value;
  bool derivative = false;
};

TermInputs row_inputs(const ArrData& a, std::size_t i) {
  TermInputs t;
  t.Pmi = a.y[i][kMi];
  t.Pmo = a.y[i][kMo];
  t.Ppp = a.y[i][kPp];
  t.w = a.y[i][kW];
  t.dPpp = a.dPpp[i];
  t.dw = a.dw[i];
  t.t = a.t_since_start[i];
  t.Psupl = a.Psupl[i];
  t.Ps = a.Ps[i];
  t.Pbp = a.Pbp[i];
  t.kp = a.kp[i];
  return t;
}

double sroot(double d) { return d < 0 ? -std::sqrt(-d) : std::sqrt(d); }

std::vector<Candidate> candidates(int eq) {
  using X = const TermInputs&;
  std::vector<Candidate> c;
  const auto t = [](X x) { return x.t; };
  const auto w = [](X x) { return x.w; };
  const auto one = [](X) { return 1.0; };
  if (eq == kEqTorque) {
    // Coulomb before the constant: for a shaft that always turns one way they coincide,
    // and the physical reading is friction.
    c.push_back({"tanh(w_m/0.5)", "N*m", "coulomb", [](X x) { return std::tanh(x.w / kOmega0); }});
    c.push_back({"1", "N*m", "const", one});
    c.push_back({"w_m", "N*m*s/rad", "viscous", w});
    c.push_back({"p_mi-p_mo", "m^3/rad", "motor_dp", [](X x) { return x.Pmi - x.Pmo; }});
    c.push_back({"p_pp-Pbp", "m^3/rad", "pump_dp", [](X x) { return x.Ppp - x.Pbp; }});
    c.push_back({"w_m^2", "N*m*s^2/rad^2", "windage", [](X x) { return x.w * std::fabs(x.w); }});
    c.push_back({"(p_mi-p_mo)*w_m", "m^3*s/rad^2", "generic", [](X x) { return (x.Pmi - x.Pmo) * x.w; }});
    c.push_back({"dw_m/dt", "kg*m^2", "inertia", [](X x) { return x.dw; }, true});
    c.push_back({"t", "N*m/s", "drift", t});
    return c;
  }
  const std::string P = eq == kEqFlowMi ? "p_mi" : (eq == kEqFlowMo ? "p_mo" : "p_pp");
  c.push_back({"1", "m^3/s", "const", one});
  if (eq == kEqFlowMi) c.push_back({P, "m^3/(s*Pa)", "leak", [](X x) { return x.Pmi; }});
  if (eq == kEqFlowMo) c.push_back({P, "m^3/(s*Pa)", "leak", [](X x) { return x.Pmo; }});
  if (eq == kEqFlowPp) c.push_back({P, "m^3/(s*Pa)", "leak", [](X x) { return x.Ppp; }});
  c.push_back({"w_m", "m^3/rad", "displacement", w});
  if (eq == kEqFlowPp) {
    c.push_back({"kp*sqrt(p_pp-Pbp)", "1", "orifice", [](X x) { return x.kp * sroot(x.Ppp - x.Pbp); }});
    c.push_back({"p_pp-Pbp", "m^3/(s*Pa)", "laminar", [](X x) { return x.Ppp - x.Pbp; }});
    c.push_back({"p_pp*w_m", "m^3/(Pa*rad)", "generic", [](X x) { return x.Ppp * x.w; }});
    c.push_back({"dp_pp/dt", "m^3/Pa", "compliance", [](X x) { return x.dPpp; }, true});
  } else {
    c.push_back({"p_mi-p_mo", "m^3/(s*Pa)", "cross", [](X x) { return x.Pmi - x.Pmo; }});
    if (eq == kEqFlowMi) {
      c.push_back({"sqrt(Psupl-p_mi)", "m^3/(s*sqrt(Pa))", "orifice", [](X x) { return sroot(x.Psupl - x.Pmi); }});
      c.push_back({"p_mi*w_m", "m^3/(Pa*rad)", "generic", [](X x) { return x.Pmi * x.w; }});
    } else {
      c.push_back({"sqrt(p_mo-Ps)", "m^3/(s*sqrt(Pa))", "orifice", [](X x) { return sroot(x.Pmo - x.Ps); }});
      c.push_back({"p_mo*w_m", "m^3/(Pa*rad)", "generic", [](X x) { return x.Pmo * x.w; }});
    }
  }
  c.push_back({"t", "m^3/s^2", "drift", t});
  return c;
}

// Weighted design matrix (rows / σ) of the chosen candidates, and the weighted target.
void design(const ArrData& a, int eq, const std::vector<Candidate>& c, Eigen::MatrixXd& X, Eigen::VectorXd& y) {
  const auto e = static_cast<std::size_t>(eq);
  const std::size_t n = a.rows.size();
  X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(c.size()));
  y.resize(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double wt = 1.0 / a.sigma[e][i];
    const TermInputs ti = row_inputs(a, i);
    y[static_cast<Eigen::Index>(i)] = a.r[e][i] * wt;
    for (std::size_t j = 0; j < c.size(); ++j) {
      X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = c[j].value(ti) * wt;
    }
  }
}

std::string node_name(int eq) {
  return eq == kEqFlowMi ? "motor-inlet" : (eq == kEqFlowMo ? "motor-outlet" : "loading-pump");
}

// The physical reading of the leading term, in words.
std::string reading(int eq, const Candidate& c, double v) {
  char b[320];
  const bool flow = eq != kEqTorque;
  const std::string node = node_name(eq);
  if (c.meaning == "leak" && v > 0) {
    std::snprintf(b, sizeof b, "a flow loss at the %s node proportional to %s: leakage to drain, R = %.3g Pa*s/m^3",
                  node.c_str(), c.form.c_str(), 1.0 / v);
  } else if (c.meaning == "leak") {
    std::snprintf(b, sizeof b, "a flow gain at the %s node proportional to %s (%.3g m^3/(s*Pa)): an inflow the model lacks",
                  node.c_str(), c.form.c_str(), -v);
  } else if (c.meaning == "const" && flow) {
    std::snprintf(b, sizeof b, "a constant flow %s at the %s node of %.3g m^3/s (%.3g L/min)", v > 0 ? "loss" : "gain",
                  node.c_str(), std::fabs(v), std::fabs(v) * 6e4);
  } else if (c.meaning == "displacement") {
    std::snprintf(b, sizeof b, "a flow %s at the %s node proportional to the speed: %.3g m^3/rad (a displacement or volumetric efficiency error)",
                  v > 0 ? "loss" : "gain", node.c_str(), std::fabs(v));
  } else if (c.meaning == "orifice") {
    if (eq == kEqFlowPp) {
      std::snprintf(b, sizeof b, "the PRV passes %.3g times the model's flow (kp off by %+.1f %%)", 1.0 + v, 100.0 * v);
    } else {
      std::snprintf(b, sizeof b, "the DCV %s orifice's coefficient kf is off by %+.3g m^3/(s*sqrt(Pa))",
                    eq == kEqFlowMi ? "inlet" : "outlet", eq == kEqFlowMi ? -v : v);
    }
  } else if (c.meaning == "cross") {
    std::snprintf(b, sizeof b, "a cross-port leakage proportional to p_mi - p_mo: R = %.3g Pa*s/m^3", 1.0 / std::fabs(v));
  } else if (c.meaning == "laminar") {
    std::snprintf(b, sizeof b, "a flow %s at the loading-pump node proportional to p_pp - Pbp: a laminar path across the PRV, R = %.3g Pa*s/m^3",
                  v > 0 ? "loss" : "gain", 1.0 / std::fabs(v));
  } else if (c.meaning == "compliance") {
    std::snprintf(b, sizeof b, "a compliance the model lacks at the loading-pump node: %.3g m^3/Pa", v);
  } else if (c.meaning == "coulomb" || (c.meaning == "const" && !flow)) {
    std::snprintf(b, sizeof b, "a %s torque on the shaft: Coulomb friction Tc = %.3g N*m", v > 0 ? "braking" : "driving",
                  std::fabs(v));
  } else if (c.meaning == "viscous") {
    std::snprintf(b, sizeof b, "a torque loss proportional to the speed: extra viscous friction %.3g N*m*s/rad", v);
  } else if (c.meaning == "motor_dp") {
    std::snprintf(b, sizeof b, "a torque loss proportional to the motor pressure difference: mechanical efficiency off by %.3g m^3/rad", v);
  } else if (c.meaning == "pump_dp") {
    std::snprintf(b, sizeof b, "a torque proportional to the loading-pump pressure rise: pump displacement or efficiency off by %.3g m^3/rad", v);
  } else if (c.meaning == "windage") {
    std::snprintf(b, sizeof b, "a torque loss proportional to the speed squared (churning, windage): %.3g N*m*s^2/rad^2", v);
  } else if (c.meaning == "inertia") {
    std::snprintf(b, sizeof b, "an inertia error: J off by %.3g kg*m^2", v);
  } else if (c.meaning == "drift") {
    std::snprintf(b, sizeof b, "an imbalance drifting with time since start: %.3g %s", v, c.unit.c_str());
  } else {
    std::snprintf(b, sizeof b, "an imbalance proportional to %s: %.3g %s", c.form.c_str(), v, c.unit.c_str());
  }
  return b;
}

}  // namespace

std::optional<Discovery> discover(const ArrData& fit, const ArrData& check, int eq) {
  if (eq < 0 || eq >= kEquations) return std::nullopt;
  const auto e = static_cast<std::size_t>(eq);
  if (!fit.available[e] || !check.available[e] || fit.rows.size() < 20 || check.rows.size() < 20) return std::nullopt;
  std::vector<Candidate> all = candidates(eq);
  const std::optional<detail::StlsqChoice> ch = detail::stlsq_choose_on(
      fit, check, [&](const ArrData& a, Eigen::MatrixXd& X, Eigen::VectorXd& y) { design(a, eq, all, X, y); });
  if (!ch) return std::nullopt;
  Discovery d;
  d.equation = equation_names()[e];
  detail::take_judgement(*ch, d);
  for (std::size_t j = 0; j < ch->active.size(); ++j) {
    const Candidate& c = all[static_cast<std::size_t>(ch->active[j])];
    d.terms.push_back({c.form, c.unit, ch->coefficient[j], ch->std_error[j]});
    d.model_terms.push_back({eq, ch->coefficient[j], c.value, c.derivative});
  }
  d.reading = reading(eq, all[static_cast<std::size_t>(ch->active.front())], d.terms.front().coefficient);
  return d;
}

}  // namespace hstmon::gap
