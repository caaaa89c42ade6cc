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

namespace {

constexpr double kLmStep = 1e-6;     // central-difference step of the solver's Jacobian [ln units]
constexpr double kStatsStep = 1e-4;  // … and of the statistics' at the optimum (beyond the solver's noise)

// The unknowns of a fit and the residuals they give: x = the fitted parameters'
// ln(p/p₀), then per operating point its window inputs' ln(u/u₀) (or (u − u₀)/scale where
// u₀ ≤ 0). Residuals run in point then channel order; row0[k] is point k's first.
struct FitProblem {
  const circuit_tools::LoadedCircuit& c;
  host::HostCircuit desc;
  std::vector<int> idx;                        // fitted parameters
  std::vector<double> start;                   // their start values [SI]
  std::vector<int> wi;                         // window inputs
  std::vector<double> wscale;                  // per window input: the step unit where u₀ ≤ 0 [SI]
  std::vector<CircuitOperatingPoint>& points;  // with window_start filled
  std::vector<std::size_t> row0;

  std::size_t m() const { return row0.back(); }
  std::size_t n() const { return idx.size() + points.size() * wi.size(); }
  std::size_t col(std::size_t point, std::size_t k) const { return idx.size() + point * wi.size() + k; }

  Model::Params params(const std::vector<double>& x) const {
    Model::Params p = c.values.params;
    for (std::size_t j = 0; j < idx.size(); ++j) p.v[idx[j]] = start[j] * std::exp(x[j]);
    return p;
  }
  double window_value(std::size_t point, std::size_t k, double xk) const {
    const double u0 = points[point].window_start[k];
    return u0 > 0.0 ? u0 * std::exp(xk) : u0 + xk * wscale[k];
  }
  // Point `point`'s residuals into out[0 …]; false when it has no steady state.
  bool point_residuals(const Model::Params& p, std::size_t point, const std::vector<double>& x, double* out) const {
    const CircuitOperatingPoint& pt = points[point];
    Model::Inputs u = c.values.inputs;
    for (std::size_t i = 0; i < pt.inputs.size(); ++i) u.v[i] = pt.inputs[i];
    for (std::size_t k = 0; k < wi.size(); ++k) u.v[wi[k]] = window_value(point, k, x[col(point, k)]);
    const Model model(desc, p, u);
    Model::Output y;
    if (!model.valid() || !circuit::steady_outputs(model, y)) return false;
    for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
      if (!std::isfinite(pt.mean[ch])) continue;
      *out++ = (pt.mean[ch] - y[static_cast<int>(ch)]) / circuit_tools::sensor_sigma(c.file.sensors[ch]);
    }
    return true;
  }
  bool residuals(const std::vector<double>& x, std::vector<double>& res) const {
    res.resize(m());
    const Model::Params p = params(x);
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (!point_residuals(p, k, x, res.data() + row0[k])) return false;
    }
    return true;
  }
  // Central differences by block: a parameter's column from whole residuals, a window
  // input's from its own point's rows only (the rest of its column is 0).
  bool jacobian(const std::vector<double>& x, double h, DenseMatrix& jac) const {
    jac = DenseMatrix(m(), n());
    std::vector<double> rp, rm, xs = x;
    for (std::size_t j = 0; j < idx.size(); ++j) {
      xs[j] = x[j] + h;
      if (!residuals(xs, rp)) return false;
      xs[j] = x[j] - h;
      if (!residuals(xs, rm)) return false;
      xs[j] = x[j];
      for (std::size_t i = 0; i < m(); ++i) jac(i, j) = (rp[i] - rm[i]) / (2.0 * h);
    }
    const Model::Params p = params(x);
    rp.resize(c.file.sensors.size());
    rm.resize(c.file.sensors.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      for (std::size_t q = 0; q < wi.size(); ++q) {
        const std::size_t j = col(k, q);
        xs[j] = x[j] + h;
        if (!point_residuals(p, k, xs, rp.data())) return false;
        xs[j] = x[j] - h;
        if (!point_residuals(p, k, xs, rm.data())) return false;
        xs[j] = x[j];
        for (std::size_t i = row0[k]; i < row0[k + 1]; ++i) jac(i, j) = (rp[i - row0[k]] - rm[i - row0[k]]) / (2.0 * h);
      }
    }
    for (double v : jac.data) {
      if (!std::isfinite(v)) return false;
    }
    return true;
  }
  // The residuals spread back per point and channel into `field` (NaN where not logged).
  void per_point(const std::vector<double>& res, std::vector<double> CircuitOperatingPoint::*field) const {
    for (std::size_t k = 0; k < points.size(); ++k) {
      std::vector<double> per(c.file.sensors.size(), std::nan(""));
      std::size_t r = row0[k];
      for (std::size_t ch = 0; ch < per.size(); ++ch) {
        if (std::isfinite(points[k].mean[ch])) per[ch] = res[r++];
      }
      points[k].*field = std::move(per);
    }
  }
};

// The fitted parameters' indices and start values into idx and r; false with r.error.
bool resolve_fitted(const circuit_tools::LoadedCircuit& c, const CircuitFitOptions& o, std::vector<int>& idx,
                    CircuitFitResult& r) {
  r.default_fit = o.fit.empty();
  const std::vector<std::string> names = r.default_fit ? default_fit_parameters(c) : o.fit;
  for (const std::string& name : names) {
    const int k = c.file.param_index(name);
    if (k < 0 || c.file.params[static_cast<std::size_t>(k)].literal) {
      r.error = "circuit " + c.file.name + " has no named parameter '" + name + "'";
      return false;
    }
    if (!(c.values.params.v[k] > 0.0)) {
      r.error = "parameter " + name + " is not positive: it cannot be fitted as a logarithm";
      return false;
    }
    idx.push_back(k);
    r.names.push_back(name);
    r.start.push_back(c.values.params.v[k]);
  }
  if (idx.empty()) {
    r.error = "nothing to fit: circuit " + c.file.name +
              " has no positive loss or opening parameter; name the parameters with --fit";
  }
  return !idx.empty();
}

// The window inputs (CircuitFitOptions::window_inputs) into wi and r.window_inputs;
// false with r.error.
bool resolve_window_inputs(const circuit_tools::LoadedCircuit& c, const std::vector<circuit_tools::CircuitLog>& logs,
                           const CircuitFitOptions& o, std::vector<int>& wi, CircuitFitResult& r) {
  if (!o.setting_per_window) return true;
  std::string all;
  for (const auto& in : c.file.inputs) all += (all.empty() ? "" : ", ") + in.name;
  for (const std::string& name : o.window_inputs) {
    const int k = c.file.input_index(name);
    if (k < 0) {
      r.error = "circuit " + c.file.name + " has no input '" + name + "' to fit per window (its inputs: " + all + ")";
      return false;
    }
    if (std::find(wi.begin(), wi.end(), k) == wi.end()) wi.push_back(k);
  }
  for (std::size_t i = 0; o.window_inputs.empty() && i < c.file.inputs.size(); ++i) {
    const bool logged = std::any_of(logs.begin(), logs.end(), [&](const circuit_tools::CircuitLog& l) {
      return i < l.inputs.size() && l.rows() > 0 && l.inputs[i].size() == l.rows();
    });
    if (!logged) wi.push_back(static_cast<int>(i));
  }
  if (wi.empty()) {
    r.error = "--setting-per-window: the logs have a column for every input of circuit " + c.file.name + " (" + all +
              "): name the one(s) that set the load with --window-input NAME (their logged values then only start "
              "the fit)";
    return false;
  }
  for (int k : wi) r.window_inputs.push_back(c.file.inputs[static_cast<std::size_t>(k)].name);
  return true;
}

// Too few points or measured values for the unknowns: r.error, and false.
bool enough_points(const CircuitFitOptions& o, const FitProblem& fp, CircuitFitResult& r) {
  if (o.min_settings > 0) {
    // Per window every point is a setting of its own; else count the held input settings.
    const std::size_t settings = fp.wi.empty() ? distinct_settings(r.points) : r.points.size();
    if (settings < o.min_settings) {
      r.error = std::to_string(settings) + " distinct operating point(s) (held input settings) in the logs, fewer than "
                "the " + std::to_string(o.min_settings) + " asked for (--min-settings): log more settings";
      return false;
    }
  }
  if (fp.m() >= fp.n()) return true;
  char rule[160];
  std::snprintf(rule, sizeof rule,
                " (a point is a stretch of held inputs, steady after the settle, of at least %g s and %zu rows: "
                "--min-duration, --min-samples)",
                o.assume_steady ? 0.0 : o.min_duration,
                o.assume_steady ? std::size_t{1} : std::max<std::size_t>(1, o.min_samples));
  const std::string unknowns = fp.wi.empty() ? std::to_string(fp.n()) + " parameters to fit"
                                             : std::to_string(fp.n()) + " unknowns (" + std::to_string(fp.idx.size()) +
                                                   " parameters and " + std::to_string(fp.wi.size()) +
                                                   " window input(s) per point)";
  r.error = std::to_string(r.points.size()) + " operating point(s), " + std::to_string(fp.m()) +
            " measured values: fewer than the " + unknowns + rule;
  return false;
}

// The solution x into r: values, standard errors (from the Jacobian at x), the window
// inputs per point, notes. `determined`: the Jacobian has full rank and a sane condition.
void take_solution(const FitProblem& fp, const LmResult& lm, CircuitFitResult& r, bool& determined) {
  const std::size_t n = fp.n(), m = fp.m();
  for (std::size_t j = 0; j < fp.idx.size(); ++j) r.value.push_back(r.start[j] * std::exp(lm.x[j]));
  std::vector<double> se(n, std::nan(""));
  determined = false;
  DenseMatrix jac;
  if (m > n && fp.jacobian(lm.x, kStatsStep, jac)) {
    const LinearStats st = linear_stats(jac, lm.ssr / static_cast<double>(m - n));
    se = st.se;
    r.correlation.assign(fp.idx.size(), std::vector<double>(fp.idx.size(), std::nan("")));
    for (std::size_t i = 0; i < fp.idx.size(); ++i) {
      for (std::size_t j = 0; j < fp.idx.size(); ++j) r.correlation[i][j] = st.correlation(i, j);
    }
    // A condition beyond 1e6 (of the column-scaled Jacobian) is a direction the points
    // do not see: the central differences leave its singular value at rounding, not 0.
    determined = st.rank == n && st.condition <= 1e6;
    if (!determined) {
      char cond[32];
      std::snprintf(cond, sizeof cond, "%.3g", st.condition);
      r.notes.push_back("the operating points do not tell the fitted " +
                        std::string(fp.wi.empty() ? "parameters" : "parameters and window inputs") +
                        " apart (condition " + cond +
                        "): add operating points or fit fewer; the values along that direction are not determined");
    }
  }
  for (std::size_t j = 0; j < fp.idx.size(); ++j) r.rel_se.push_back(se[j]);  // d ln p = dp/p
  for (std::size_t k = 0; k < fp.points.size(); ++k) {
    CircuitOperatingPoint& pt = fp.points[k];
    for (std::size_t q = 0; q < fp.wi.size(); ++q) {
      const std::size_t j = fp.col(k, q);
      const double u = fp.window_value(k, q, lm.x[j]);
      pt.window_value.push_back(u);
      pt.window_se.push_back(pt.window_start[q] > 0.0 ? u * se[j] : fp.wscale[q] * se[j]);
    }
  }
}

// The undetermined parameters out of fp and r into r.held (fit_circuit's comment); false
// with r.error when none is left. A start without a steady state leaves the set as it is
// (the fit reports it).
bool hold_undetermined(FitProblem& fp, CircuitFitResult& r) {
  constexpr double kMaxLogHalfwidth = 1.0;  // t·SE(ln p): the interval spans a factor e each way
  const std::size_t p = fp.idx.size();
  if (p == 0) return true;
  DenseMatrix jac;
  if (fp.m() <= fp.n() || !fp.jacobian(std::vector<double>(fp.n(), 0.0), kStatsStep, jac)) return true;
  // A point's residual is a mean of n readings: its noise is σ/√n, so its rows weigh √n.
  for (std::size_t k = 0; k < fp.points.size(); ++k) {
    const double w = std::sqrt(static_cast<double>(std::max<std::size_t>(fp.points[k].n, 1)));
    for (std::size_t i = fp.row0[k]; i < fp.row0[k + 1]; ++i) {
      for (std::size_t j = 0; j < fp.n(); ++j) jac(i, j) *= w;
    }
  }
  const LinearStats st = linear_stats(jac, 1.0);
  const double t95 = t_quantile(0.05, static_cast<double>(fp.m() - fp.n()));
  std::size_t drop = p;
  for (std::size_t j = 0; j < p; ++j) {
    if (t95 * st.se[j] <= kMaxLogHalfwidth) continue;
    if (drop == p || st.column_norms[j] < st.column_norms[drop]) drop = j;
  }
  if (drop == p) return true;
  // Its partners along the undetermined direction, where it lies on one (a condition
  // beyond 1e6, as take_solution judges: the central differences leave a null direction's
  // singular value at rounding, not 0).
  std::string partners;
  if (!(st.condition <= 1e6) && st.null_direction.size() == fp.n() && std::fabs(st.null_direction[drop]) > 0.1) {
    for (std::size_t j = 0; j < p; ++j) {
      if (j != drop && std::fabs(st.null_direction[j]) > 0.1) partners += (partners.empty() ? "" : ", ") + r.names[j];
    }
    for (std::size_t j = p; j < fp.n(); ++j) {
      if (std::fabs(st.null_direction[j]) > 0.1) {
        partners += std::string(partners.empty() ? "" : " and ") + "the window inputs";
        break;
      }
    }
  }
  std::string why;
  if (!partners.empty()) {
    why = "acts on these points only together with " + partners + ", which carries their joint effect";
  } else {
    // ln 2 · ‖column‖: how far doubling it moves the point means, in their noise.
    char text[160];
    std::snprintf(text, sizeof text,
                  "the points cannot determine it: doubling it moves the point means by %.3g of their noise (its "
                  "95 %% interval of ln p would be ±%.3g)",
                  std::log(2.0) * st.column_norms[drop], t95 * st.se[drop]);
    why = text;
  }
  r.held.push_back({r.names[drop], r.start[drop], why});
  const auto at = static_cast<std::ptrdiff_t>(drop);
  fp.idx.erase(fp.idx.begin() + at);
  fp.start.erase(fp.start.begin() + at);
  r.names.erase(r.names.begin() + at);
  r.start.erase(r.start.begin() + at);
  if (!fp.idx.empty()) return hold_undetermined(fp, r);
  std::string e = "the operating points determine none of the parameters asked for:";
  for (const auto& h : r.held) e += " " + h.name + ": " + h.why + ";";
  e.pop_back();
  r.error = e;
  return false;
}

}  // namespace

std::vector<std::string> default_fit_parameters(const circuit_tools::LoadedCircuit& c) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < c.file.params.size(); ++k) {
    const auto& par = c.file.params[k];
    using Q = host::CircuitQuantity;
    const bool loss = par.quantity == Q::kResistance || par.quantity == Q::kConductance ||
                      par.quantity == Q::kDamping || par.quantity == Q::kOrifice || par.quantity == Q::kArea;
    if (loss && !par.literal && c.values.params.v[static_cast<int>(k)] > 0.0) out.push_back(par.name);
  }
  return out;
}

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
  std::vector<int> idx, wi;
  if (!resolve_fitted(c, o, idx, r) || !resolve_window_inputs(c, logs, o, wi, r)) return r;
  CircuitPointRules rules;
  rules.min_duration = o.min_duration;
  rules.min_samples = o.min_samples;
  rules.assume_steady = o.assume_steady;
  rules.steps_are_settings = !wi.empty();
  r.points = circuit_operating_points(c, logs, rules, &r.notes);
  FitProblem fp{c, c.file.circuit, idx, r.start, wi, {}, r.points, {0}};
  fp.desc.stiff_mask = 0;
  for (int k : wi) {
    const double nominal = std::fabs(c.values.inputs.v[k]);
    fp.wscale.push_back(nominal > 0.0 ? nominal : 1.0);
  }
  for (auto& p : r.points) {
    for (int k : wi) p.window_start.push_back(p.inputs[static_cast<std::size_t>(k)]);
    std::size_t measured = 0;
    for (double v : p.mean) measured += std::isfinite(v) ? 1u : 0u;
    fp.row0.push_back(fp.row0.back() + measured);
  }
  if (!enough_points(o, fp, r) || !hold_undetermined(fp, r)) return r;
  idx = fp.idx;
  const std::size_t m = fp.m();
  const std::vector<double> x0(fp.n(), 0.0);
  std::vector<double> res;
  if (!fp.residuals(x0, res)) {
    r.error = "no steady state at some operating point with the starting values";
    return r;
  }
  fp.per_point(res, &CircuitOperatingPoint::before);
  double ss = 0.0;
  for (double v : res) ss += v * v;
  r.rms_before = std::sqrt(ss / static_cast<double>(m));
  const ResidualFn f = [&](const std::vector<double>& x, std::vector<double>& out) { return fp.residuals(x, out); };
  const JacobianFn df = [&](const std::vector<double>& x, DenseMatrix& jac) { return fp.jacobian(x, kLmStep, jac); };
  const LmResult lm = levenberg_marquardt(f, df, m, x0);
  r.status = lm.status_text;
  if (!lm.finite) {
    r.error = "the fit did not reach finite values (" + lm.status_text + ")";
    return r;
  }
  if (fp.residuals(lm.x, res)) fp.per_point(res, &CircuitOperatingPoint::after);
  r.rms_after = std::sqrt(lm.ssr / static_cast<double>(m));
  bool determined = false;
  take_solution(fp, lm, r, determined);
  if (!lm.converged) r.notes.push_back("the solver stopped without converging: " + lm.status_text);
  // The window inputs use degrees of freedom as parameters do: judge on what is left.
  judge_fitted_values(c, idx, determined && lm.converged, m - (fp.n() - idx.size()), r);
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
