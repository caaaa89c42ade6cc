#include "hstmon_ident/circuit_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_ident/least_squares.hpp"

namespace hstmon::ident {

namespace {

using Model = host::HostCircuitModel;

std::string percent(double rel) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g %%", 100.0 * rel);
  return buf;
}

/// What the fit may hand on: per fitted parameter its 95 % interval (Student's t on the
/// residual degrees of freedom, since s² is estimated from few points), whether the move
/// from the start lies beyond it, and the uncertainty the monitor's bound takes after
/// commissioning (kLeastUncertainty at least; never wider than it was known before).
void judge_fitted_values(const circuit_tools::LoadedCircuit& c, const std::vector<int>& idx, bool determined,
                         std::size_t m, CircuitFitResult& r) {
  const auto known = circuit_tools::circuit_uncertainty(c);
  const double t95 = m > idx.size() ? t_quantile(0.05, static_cast<double>(m - idx.size())) : 0.0;
  std::string kept, unmoved;
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const double prior = known.rel[idx[j]];
    const double ci = t95 * r.rel_se[j];
    const bool pinned = determined && std::isfinite(ci) && ci < prior;
    r.prior_uncertainty.push_back(prior);
    r.pinned.push_back(pinned);
    r.uncertainty.push_back(pinned ? std::max(ci, kLeastUncertainty) : prior);
    r.moved.push_back(std::isfinite(ci) && std::fabs(std::log(r.value[j] / r.start[j])) > ci);
    if (!pinned && prior > 0.0) kept += (kept.empty() ? "" : ", ") + r.names[j] + " (±" + percent(prior) + ")";
    if (!r.moved.back()) unmoved += (unmoved.empty() ? "" : ", ") + r.names[j];
  }
  if (!kept.empty()) {
    r.notes.push_back("the points do not pin " + kept +
                      " tighter than it was known: the monitor keeps that uncertainty for it (a wide bound)");
  }
  if (!unmoved.empty()) {
    r.notes.push_back("the data do not show a change of " + unmoved +
                      ": its start value lies within the fit's 95 % interval");
  }
}

}  // namespace

bool circuit_point_residuals(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel::Params& p,
                             const std::vector<CircuitOperatingPoint>& points, std::vector<double>& res) {
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = 0;
  res.clear();
  for (const auto& pt : points) {
    Model::Inputs u = c.values.inputs;
    for (std::size_t i = 0; i < pt.inputs.size(); ++i) u.v[i] = pt.inputs[i];
    const Model model(desc, p, u);
    Model::Output y;
    if (!model.valid() || !circuit::steady_outputs(model, y)) return false;
    for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
      if (!std::isfinite(pt.mean[ch])) continue;
      res.push_back((pt.mean[ch] - y[static_cast<int>(ch)]) / circuit_tools::sensor_sigma(c.file.sensors[ch]));
    }
  }
  return true;
}

CircuitFitResult fit_circuit(const circuit_tools::LoadedCircuit& c, const std::vector<circuit_tools::CircuitLog>& logs,
                             const CircuitFitOptions& o) {
  CircuitFitResult r;
  std::vector<int> idx;
  for (const std::string& name : o.fit) {
    const int k = c.file.param_index(name);
    if (k < 0 || c.file.params[static_cast<std::size_t>(k)].literal) {
      r.error = "circuit " + c.file.name + " has no named parameter '" + name + "'";
      return r;
    }
    if (!(c.values.params.v[k] > 0.0)) {
      r.error = "parameter " + name + " is not positive: it cannot be fitted as a logarithm";
      return r;
    }
    idx.push_back(k);
    r.names.push_back(name);
    r.start.push_back(c.values.params.v[k]);
  }
  if (idx.empty()) {
    r.error = "nothing to fit: name the parameters with --fit";
    return r;
  }
  CircuitPointRules rules;
  rules.min_duration = o.min_duration;
  rules.min_samples = o.min_samples;
  rules.assume_steady = o.assume_steady;
  r.points = circuit_operating_points(c, logs, rules, &r.notes);
  if (o.min_settings > 0) {
    const std::size_t settings = distinct_settings(r.points);
    if (settings < o.min_settings) {
      r.error = std::to_string(settings) + " distinct operating point(s) (held input settings) in the logs, fewer than "
                "the " + std::to_string(o.min_settings) + " asked for (--min-settings): log more settings";
      return r;
    }
  }
  const std::size_t channels = c.file.sensors.size();
  std::size_t m = 0;
  for (const auto& p : r.points) {
    for (double v : p.mean) m += std::isfinite(v) ? 1u : 0u;
  }
  if (m < idx.size()) {
    char rule[160];
    std::snprintf(rule, sizeof rule,
                  " (a point is a stretch of held inputs, steady after the settle, of at least %g s and %zu rows: "
                  "--min-duration, --min-samples)",
                  o.assume_steady ? 0.0 : o.min_duration, o.assume_steady ? std::size_t{1} : std::max<std::size_t>(1, o.min_samples));
    r.error = std::to_string(r.points.size()) + " operating point(s), " + std::to_string(m) +
              " measured values: fewer than the " + std::to_string(idx.size()) + " parameters to fit" + rule;
    return r;
  }
  // Residuals (mean − model)/σ at every point and measured channel for the fitted
  // ln(p/p₀) x (circuit_point_residuals), and the same spread back per point and channel.
  auto residuals = [&](const std::vector<double>& x, std::vector<double>& res) {
    Model::Params p = c.values.params;
    for (std::size_t j = 0; j < idx.size(); ++j) p.v[idx[j]] = r.start[j] * std::exp(x[j]);
    return circuit_point_residuals(c, p, r.points, res);
  };
  auto per_point = [&](const std::vector<double>& res, std::vector<double> CircuitOperatingPoint::*field) {
    std::size_t k = 0;
    for (auto& pt : r.points) {
      std::vector<double> per(channels, std::nan(""));
      for (std::size_t ch = 0; ch < channels; ++ch) {
        if (std::isfinite(pt.mean[ch])) per[ch] = res[k++];
      }
      pt.*field = std::move(per);
    }
  };
  const std::vector<double> x0(idx.size(), 0.0);
  std::vector<double> res(m);
  if (!residuals(x0, res)) {
    r.error = "no steady state at some operating point with the starting values";
    return r;
  }
  per_point(res, &CircuitOperatingPoint::before);
  double ss = 0.0;
  for (double v : res) ss += v * v;
  r.rms_before = std::sqrt(ss / static_cast<double>(m));
  const ResidualFn f = [&](const std::vector<double>& x, std::vector<double>& out) { return residuals(x, out); };
  const LmResult lm = levenberg_marquardt(f, m, x0);
  r.status = lm.status_text;
  if (!lm.finite) {
    r.error = "the fit did not reach finite values (" + lm.status_text + ")";
    return r;
  }
  if (residuals(lm.x, res)) per_point(res, &CircuitOperatingPoint::after);
  r.rms_after = std::sqrt(lm.ssr / static_cast<double>(m));
  for (std::size_t j = 0; j < idx.size(); ++j) r.value.push_back(r.start[j] * std::exp(lm.x[j]));
  DenseMatrix jac;
  const std::vector<double> steps(idx.size(), 1e-4);
  r.rel_se.assign(idx.size(), std::nan(""));
  bool determined = false;
  if (m > idx.size() && central_jacobian(f, m, lm.x, steps, jac)) {
    const LinearStats st = linear_stats(jac, lm.ssr / static_cast<double>(m - idx.size()));
    for (std::size_t j = 0; j < idx.size(); ++j) r.rel_se[j] = st.se[j];  // d ln p = dp/p
    // A condition beyond 1e6 (of the column-scaled Jacobian) is a direction the points
    // do not see: the central differences leave its singular value at rounding, not 0.
    determined = st.rank == idx.size() && st.condition <= 1e6;
    if (!determined) {
      char cond[32];
      std::snprintf(cond, sizeof cond, "%.3g", st.condition);
      r.notes.push_back("the operating points do not tell the fitted parameters apart (condition " + std::string(cond) +
                        "): add operating points or fit fewer; the values along that direction are not determined");
    }
  }
  if (!lm.converged) r.notes.push_back("the solver stopped without converging: " + lm.status_text);
  judge_fitted_values(c, idx, determined && lm.converged, m, r);
  return r;
}

circuit_tools::LoadedCircuit fitted_circuit(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  circuit_tools::LoadedCircuit out = c;
  out.values.uncertainty.resize(c.file.params.size());
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const int k = c.file.param_index(r.names[j]);
    if (k < 0) continue;
    out.values.params.v[k] = r.value[j];
    if (j < r.uncertainty.size()) out.values.uncertainty[static_cast<std::size_t>(k)] = r.uncertainty[j];
  }
  return out;
}

std::string fitted_values_json(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < c.file.params.size(); ++k) {
    if (c.file.params[k].literal) continue;
    params[c.file.params[k].name] = c.values.params.v[k];
  }
  for (std::size_t j = 0; j < r.names.size(); ++j) params[r.names[j]] = r.value[j];
  nlohmann::ordered_json inputs = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) inputs[c.file.inputs[i].name] = c.values.inputs.v[i];
  nlohmann::ordered_json uncertainty = nlohmann::ordered_json::object();
  const auto& stated = c.values.uncertainty;
  for (std::size_t k = 0; k < stated.size() && k < c.file.params.size(); ++k) {
    if (stated[k]) uncertainty[c.file.params[k].name] = *stated[k];
  }
  for (std::size_t j = 0; j < r.names.size() && j < r.uncertainty.size(); ++j) {
    uncertainty[r.names[j]] = r.uncertainty[j];
  }
  std::string fitted;
  for (const auto& n : r.names) fitted += (fitted.empty() ? "" : ", ") + n;
  const nlohmann::ordered_json j = {
      {"circuit", c.file.name},
      {"description", "hstmon identify --circuit: " + fitted + " fitted to " + std::to_string(r.points.size()) +
                          " operating points; SI units; uncertainty: the fit's 95 % interval where it pins a value"},
      {"params", params},
      {"inputs", inputs},
      {"uncertainty", uncertainty}};
  return j.dump(2) + "\n";
}

}  // namespace hstmon::ident
