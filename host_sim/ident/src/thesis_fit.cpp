/// @file thesis_fit.cpp
/// Steady-state regression of the thesis model (see thesis_fit.hpp).
#include "hstmon_ident/thesis_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon_sensors/sensor_presets.hpp"

namespace hstmon::ident {

namespace {

constexpr const char* kKfUnit = "m^3/(s*Pa^0.5)";
constexpr const char* kRwUnit = "N*m*s/rad";
constexpr const char* kRUnit = "Pa*s/m^3";

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

// Layout of the parameter vector: ln kf, ln Rw, ln kp[0..S), then the free leakages.
struct Layout {
  std::size_t settings = 0;
  bool fit_rlkg = false;
  bool fit_ripl = false;
  std::size_t size() const { return 2 + settings + (fit_rlkg ? 1 : 0) + (fit_ripl ? 1 : 0); }
  std::size_t rlkg() const { return 2 + settings; }
  std::size_t ripl() const { return 2 + settings + (fit_rlkg ? 1 : 0); }
};

struct Problem {
  const std::vector<OperatingPoint>* points = nullptr;
  ThesisParams<double> prior{};
  std::array<double, 4> sigma{};
  Layout layout{};
  std::size_t residuals = 0;

  // Parameters and kp of setting s from x.
  ThesisParams<double> params(const std::vector<double>& x) const {
    ThesisParams<double> p = prior;
    p.kf = std::exp(x[0]);
    const double rw = std::exp(x[1]);
    const double rw0 = prior.Rf + prior.Rbl;
    p.Rf = rw * prior.Rf / rw0;
    p.Rbl = rw * prior.Rbl / rw0;
    if (layout.fit_rlkg) p.Rlkg = std::exp(x[layout.rlkg()]);
    if (layout.fit_ripl) p.Ripl = std::exp(x[layout.ripl()]);
    return p;
  }

  bool predict(const std::vector<double>& x, std::vector<std::array<double, 4>>& out) const {
    const ThesisParams<double> p = params(x);
    out.resize(points->size());
    for (std::size_t w = 0; w < points->size(); ++w) {
      const OperatingPoint& pt = (*points)[w];
      ThesisInputs<double> u = pt.u;
      u.kp = std::exp(x[2 + pt.setting]);
      if (!thesis_steady_outputs(p, u, out[w])) return false;
    }
    return true;
  }

  bool residual(const std::vector<double>& x, std::vector<double>& r) const {
    std::vector<std::array<double, 4>> yhat;
    if (!predict(x, yhat)) return false;
    std::size_t i = 0;
    for (std::size_t w = 0; w < points->size(); ++w) {
      const OperatingPoint& pt = (*points)[w];
      const double sq_n = std::sqrt(static_cast<double>(pt.n));
      for (std::size_t c = 0; c < 4; ++c) {
        if (!std::isfinite(pt.y[c])) continue;
        r[i++] = sq_n * (yhat[w][c] - pt.y[c]) / sigma[c];
      }
    }
    return i == r.size();
  }
};

std::string fmt_g(double v) { return fmt::format("{:.4g}", v); }

// Why the points cannot be fitted (finite values, valid setting indices, settings that have data,
// enough settings, a valid prior), or nothing when they can; notes the points assumed steady.
std::optional<std::string> data_error(const std::vector<OperatingPoint>& points, const std::vector<std::string>& settings,
                                      const ThesisFitOptions& o, std::vector<std::string>& notes) {
  const std::size_t S = settings.size();
  if (points.empty()) return "no steady operating points to fit";
  std::vector<std::size_t> per_setting(S, 0);
  for (const OperatingPoint& p : points) {
    if (p.setting >= S) return p.source + ": setting index out of range";
    ++per_setting[p.setting];
    bool any = false;
    for (std::size_t c = 0; c < 4; ++c) {
      if (std::isnan(p.y[c])) continue;
      any = true;
      if (!std::isfinite(p.y[c]) || !std::isfinite(p.ss[c])) return p.source + ": non-finite measurement (NaN or Inf)";
    }
    if (!any) return p.source + ": no measured channel";
    if (!std::isfinite(p.u.Psupl) || !std::isfinite(p.u.Ps) || !std::isfinite(p.u.Pbp)) {
      return p.source + ": non-finite input (p_sup, p_s or p_bp)";
    }
    if (p.n == 0) return p.source + ": window without samples";
    if (p.assumed) notes.push_back(p.source + ": steadiness assumed (fewer than 3 samples)");
  }
  for (std::size_t s = 0; s < S; ++s) {
    if (per_setting[s] == 0) return "PRV setting " + settings[s] + " has no steady operating point";
  }
  if (S < o.min_settings) {
    return fmt::format("too few operating points: {} PRV setting{} with a steady window, at least {} needed "
                       "(the regression needs several loads)",
                       S, S == 1 ? "" : "s", o.min_settings);
  }
  if (!ThesisCircuitModel<double>::params_valid(o.prior)) return "prior parameters are invalid (non-finite or non-positive)";
  return std::nullopt;
}

// Noise σ per channel: the option's, else the pooled within-window scatter, else the thesis DAS's.
void estimate_noise(const std::vector<OperatingPoint>& points, const ThesisFitOptions& o, ThesisFitResult& res) {
  for (std::size_t c = 0; c < 4; ++c) {
    double ss = 0.0, dof = 0.0;
    for (const OperatingPoint& p : points) {
      if (!std::isfinite(p.y[c])) continue;
      ss += p.ss[c];
      dof += static_cast<double>(p.n - 1);
    }
    const double floor = c == 3 ? 1e-4 : 1.0;
    if (o.noise[c] > 0.0) {
      res.noise[c] = o.noise[c];
      res.noise_source[c] = "option";
    } else if (dof >= 3.0) {
      res.noise[c] = std::max(std::sqrt(ss / dof), floor);
      res.noise_source[c] = "within-window scatter";
    } else {
      res.noise[c] = thesis_das_noise()[c];
      res.noise_source[c] = "thesis DAS default";
    }
  }
}

// Start values (ln kf, ln Rw, ln kp per setting) from the data where the channels allow, else the prior.
std::vector<double> start_values(const std::vector<OperatingPoint>& points, std::size_t S, const ThesisParams<double>& P) {
  std::vector<double> kf0, rw0;
  std::vector<std::vector<double>> kp0(S);
  for (const OperatingPoint& p : points) {
    const double Pmi = p.y[0], Pmo = p.y[1], Ppp = p.y[2], w = p.y[3];
    if (std::isfinite(w) && w > 0.0) {
      if (std::isfinite(Ppp) && Ppp - p.u.Pbp > 0.0) kp0[p.setting].push_back(P.Dp * w / std::sqrt(Ppp - p.u.Pbp));
      if (std::isfinite(Pmi) && std::isfinite(Pmo)) {
        const double dp = 0.5 * ((p.u.Psupl - Pmi) + (Pmo - p.u.Ps));
        if (dp > 0.0) kf0.push_back(P.Dm * w / std::sqrt(dp));
        if (std::isfinite(Ppp)) {
          const double rw = (P.Dm * (Pmi - Pmo) - P.Dp * (Ppp - p.u.Pbp)) / w;
          if (rw > 0.0) rw0.push_back(rw);
        }
      }
    }
  }
  std::vector<double> x0(2 + S);
  const double kf_start = kf0.empty() ? P.kf : median(kf0);
  const double rw_start = rw0.empty() ? P.Rf + P.Rbl : median(rw0);
  x0[0] = std::log(kf_start);
  x0[1] = std::log(rw_start);
  for (std::size_t s = 0; s < S; ++s) x0[2 + s] = std::log(kp0[s].empty() ? ThesisInputs<double>{}.kp : median(kp0[s]));
  return x0;
}

// The regression around the problem: its size, the within-window scatter the residuals add to,
// the solve and the statistics at an estimate.
struct Regression {
  Problem pb;
  std::size_t samples = 0;   ///< scalar samples behind the point means
  double ss_within = 0.0;    ///< within-window sum of squares, in noise σ²

  bool too_few_for(const Layout& lay) const { return pb.residuals < lay.size() || samples <= lay.size(); }

  std::string too_few() const {
    return fmt::format("too few observations: {} scalar samples ({} point-channel means) for {} unknowns",
                       samples, pb.residuals, pb.layout.size());
  }

  bool solve(const std::vector<double>& start, LmResult& lm) const {
    if (pb.residuals < pb.layout.size()) return false;
    const ResidualFn f = [this](const std::vector<double>& x, std::vector<double>& r) { return pb.residual(x, r); };
    lm = levenberg_marquardt(f, pb.residuals, start);
    return lm.finite;
  }

  // Jacobian J over the layout lay at the estimate x (the core of x, lay's leakages at x's values),
  // its linear statistics, the residual variance s2 and its degrees of freedom.
  bool stats(const std::vector<double>& x, const Layout& lay, DenseMatrix& J, LinearStats& st, double& s2,
             double& dof) const {
    Problem full = pb;
    full.layout = lay;
    std::vector<double> xf(lay.size());
    std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(2 + lay.settings), xf.begin());
    const ThesisParams<double> cur = pb.params(x);
    if (lay.fit_rlkg) xf[lay.rlkg()] = std::log(cur.Rlkg);
    if (lay.fit_ripl) xf[lay.ripl()] = std::log(cur.Ripl);
    std::vector<double> steps(lay.size(), 1e-5);
    // Leakage effects are ~1e-8 of the outputs: a large step keeps them above rounding.
    if (lay.fit_rlkg) steps[lay.rlkg()] = 0.5;
    if (lay.fit_ripl) steps[lay.ripl()] = 0.5;
    const ResidualFn f = [&full](const std::vector<double>& xx, std::vector<double>& r) { return full.residual(xx, r); };
    if (!central_jacobian(f, pb.residuals, xf, steps, J)) return false;
    std::vector<double> r(pb.residuals);
    if (!f(xf, r)) return false;
    double ssr = ss_within;
    for (double v : r) ssr += v * v;
    dof = static_cast<double>(samples) - static_cast<double>(lay.size());
    s2 = ssr / dof;
    st = linear_stats(J, s2);
    return true;
  }
};

Regression make_regression(const std::vector<OperatingPoint>& points, std::size_t S, const ThesisFitOptions& o,
                           const std::array<double, 4>& noise) {
  Regression g;
  g.pb.points = &points;
  g.pb.prior = o.prior;
  g.pb.sigma = noise;
  g.pb.layout.settings = S;
  for (const OperatingPoint& p : points) {
    for (std::size_t c = 0; c < 4; ++c) {
      if (!std::isfinite(p.y[c])) continue;
      ++g.pb.residuals;
      g.samples += p.n;
      g.ss_within += p.ss[c] / (noise[c] * noise[c]);
    }
  }
  return g;
}

// The leakage resistances judged on the Jacobian over core + both leakages at the core fit x.
struct LeakageTest {
  std::array<bool, 2> identifiable{false, false};  ///< Rlkg, Ripl
  std::array<ParameterEstimate, 2> estimate{};     ///< name, prior, and where judged: se_log, sensitivity
};

LeakageTest test_leakages(const Regression& g, const std::vector<double>& x, const ThesisFitOptions& o, double alpha) {
  LeakageTest lt;
  lt.estimate[0].name = "Rlkg";
  lt.estimate[1].name = "Ripl";
  lt.estimate[0].prior = o.prior.Rlkg;
  lt.estimate[1].prior = o.prior.Ripl;
  if (!o.try_leakage) return lt;
  Layout lay = g.pb.layout;
  lay.fit_rlkg = lay.fit_ripl = true;
  DenseMatrix J;
  LinearStats st;
  double s2 = 0.0, dof = 0.0;
  if (static_cast<double>(g.samples) > static_cast<double>(lay.size()) && g.pb.residuals >= lay.size() &&
      g.stats(x, lay, J, st, s2, dof)) {
    const double t = t_quantile(alpha, dof);
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t j = k == 0 ? lay.rlkg() : lay.ripl();
      lt.estimate[k].se_log = st.se[j];
      lt.estimate[k].sensitivity = st.column_norms[j] * std::log(2.0);
      lt.identifiable[k] = std::isfinite(st.se[j]) && t * st.se[j] <= o.max_log_halfwidth;
    }
  }
  return lt;
}

// Parameter j of the fit x (ln-parameters) with its interval; not identifiable when the interval is too wide.
ParameterEstimate fitted_estimate(const std::string& name, const char* unit, double prior, std::size_t j,
                                  const std::vector<double>& x, const LinearStats& st, double t_value,
                                  double max_log_halfwidth) {
  ParameterEstimate e;
  e.name = name;
  e.unit = unit;
  e.prior = prior;
  e.value = std::exp(x[j]);
  e.se_log = st.se[j];
  e.se = e.value * e.se_log;
  e.ci_lo = std::exp(x[j] - t_value * e.se_log);
  e.ci_hi = std::exp(x[j] + t_value * e.se_log);
  e.sensitivity = st.column_norms[j] * std::log(2.0);
  if (!std::isfinite(e.se_log) || t_value * e.se_log > max_log_halfwidth) {
    e.status = ParamStatus::kNotIdentifiable;
    e.note = std::isfinite(e.se_log) ? fmt::format("95 % interval spans a factor {:.3g}", std::exp(2 * t_value * e.se_log))
                                     : "Jacobian column is rank deficient";
  }
  return e;
}

// Why the core parameters are not identifiable (the design is singular), or nothing when they are.
// With a kp per steady window there can be thousands: name a few, count the rest.
std::optional<std::string> singular_design(const std::vector<ParameterEstimate>& params,
                                           const std::vector<std::string>& fitted, const LinearStats& st,
                                           std::size_t unknowns) {
  constexpr std::size_t kNamed = 4;
  std::string bad;
  std::size_t n_bad = 0;
  for (const ParameterEstimate& e : params) {
    if (e.status != ParamStatus::kNotIdentifiable) continue;
    if (++n_bad <= kNamed) bad += (bad.empty() ? "" : ", ") + e.name + " (" + e.note + ")";
  }
  if (n_bad > kNamed) bad += fmt::format(" and {} more", n_bad - kNamed);
  if (bad.empty() && st.rank >= unknowns) return std::nullopt;
  std::string combo;
  std::size_t n_combo = 0;
  for (std::size_t j = 0; j < st.null_direction.size() && j < fitted.size(); ++j) {
    if (std::fabs(st.null_direction[j]) > 0.1 && ++n_combo <= kNamed) {
      combo += fmt::format("{}{:+.2f}·ln {}", combo.empty() ? "" : " ", st.null_direction[j], fitted[j]);
    }
  }
  if (n_combo > kNamed) combo += fmt::format(" and {} more terms", n_combo - kNamed);
  return fmt::format("singular design: the data cannot determine {} (Jacobian rank {} of {}, condition {:.3g}; "
                     "least-determined combination {}). Record more loads or all four channels.",
                     bad.empty() ? "every parameter" : bad, st.rank, unknowns, st.condition, combo);
}

// A leakage resistance not fitted: held at its prior, with why.
ParameterEstimate held_leakage(ParameterEstimate e, bool tested) {
  e.unit = kRUnit;
  e.value = e.prior;
  e.se = std::numeric_limits<double>::infinity();
  e.ci_lo = 0.0;
  e.ci_hi = std::numeric_limits<double>::infinity();
  e.status = ParamStatus::kNotIdentifiable;
  const double q_leak = 3e6 / e.prior;  // flow at ≈ 30 bar [m³/s]
  e.note = tested
               ? fmt::format("not identifiable: leakage flow ≈ {} m³/s at 30 bar against ≈ 1e-3 m³/s through the motor; "
                             "doubling {} moves the fit by {} noise σ (SE of ln {} would be {}); held at prior",
                             fmt_g(q_leak), e.name, fmt_g(e.sensitivity), e.name, fmt_g(e.se_log))
               : "not tested; held at prior";
  return e;
}

}  // namespace

bool thesis_steady_outputs(const ThesisParams<double>& p, const ThesisInputs<double>& u, std::array<double, 4>& y) {
  if (!ThesisCircuitModel<double>::params_valid(p) || !ThesisCircuitModel<double>::inputs_valid(u)) return false;
  ThesisCircuitModel<double> m(p);
  m.set_inputs(u);
  ThesisCircuitModel<double>::State x;
  if (!m.steady_state(x)) return false;
  const auto out = m.outputs(x);
  for (int c = 0; c < 4; ++c) y[static_cast<std::size_t>(c)] = out[c];
  for (double v : y) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

std::array<double, 4> thesis_das_noise() {
  const sim::SensorConfig cfg = sim::thesis_das_sensors();
  std::array<double, 4> s{};
  for (std::size_t c = 0; c < 4; ++c) {
    const sim::ChannelSpec& ch = cfg.channels.at(c);
    s[c] = std::sqrt(ch.noise_std * ch.noise_std + ch.quant_step * ch.quant_step / 12.0);
  }
  return s;
}

ThesisFitResult fit_thesis_steady(const std::vector<OperatingPoint>& points, const std::vector<std::string>& settings,
                                  const ThesisFitOptions& o) {
  ThesisFitResult res;
  res.points = points;
  res.settings = settings;
  const std::size_t S = settings.size();
  res.error = data_error(points, settings, o, res.notes);
  if (res.error) return res;
  estimate_noise(points, o, res);
  Regression g = make_regression(points, S, o, res.noise);
  res.samples = g.samples;
  const std::vector<double> x0 = start_values(points, S, o.prior);
  if (g.too_few_for(g.pb.layout)) {
    res.error = g.too_few();
    return res;
  }
  LmResult lm;
  if (!g.solve(x0, lm)) {
    res.error = "the fit diverged (model not evaluable at the estimate): " + lm.status_text;
    return res;
  }

  const double alpha = 1.0 - o.confidence;
  const LeakageTest leak = test_leakages(g, lm.x, o, alpha);
  if (leak.identifiable[0] || leak.identifiable[1]) {
    // Refit with the identifiable leakage(s) free.
    g.pb.layout.fit_rlkg = leak.identifiable[0];
    g.pb.layout.fit_ripl = leak.identifiable[1];
    std::vector<double> xs = lm.x;
    if (g.pb.layout.fit_rlkg) xs.push_back(std::log(o.prior.Rlkg));
    if (g.pb.layout.fit_ripl) xs.push_back(std::log(o.prior.Ripl));
    if (g.too_few_for(g.pb.layout)) {
      res.error = g.too_few();
      return res;
    }
    if (!g.solve(xs, lm)) {
      res.error = "the fit with leakage resistances diverged: " + lm.status_text;
      return res;
    }
  }
  res.lm_status = lm.status_text;
  res.evaluations = lm.evaluations;
  if (!lm.converged) res.notes.push_back("Levenberg–Marquardt: " + lm.status_text);

  DenseMatrix J;
  LinearStats st;
  if (!g.stats(lm.x, g.pb.layout, J, st, res.s2, res.dof)) {
    res.error = "the model cannot be evaluated around the estimate (Jacobian failed)";
    return res;
  }
  res.t_value = t_quantile(alpha, res.dof);
  res.condition = st.condition;
  res.rank = st.rank;
  res.correlation = st.correlation;
  const ThesisParams<double> est = g.pb.params(lm.x);

  auto fitted = [&](const std::string& name, const char* unit, double prior, std::size_t j) {
    res.fitted.push_back(name);
    return fitted_estimate(name, unit, prior, j, lm.x, st, res.t_value, o.max_log_halfwidth);
  };
  res.params.push_back(fitted("kf", kKfUnit, o.prior.kf, 0));
  res.params.push_back(fitted("Rf+Rbl", kRwUnit, o.prior.Rf + o.prior.Rbl, 1));
  for (std::size_t s = 0; s < S; ++s) {
    res.params.push_back(fitted(fmt::format("kp[{}]", s + 1), kKfUnit, std::exp(x0[2 + s]), 2 + s));
    res.kp.push_back(std::exp(lm.x[2 + s]));
  }
  // Core parameters must be identifiable: otherwise the design is singular.
  res.error = singular_design(res.params, res.fitted, st, g.pb.layout.size());
  if (res.error) return res;
  for (std::size_t k = 0; k < 2; ++k) {
    const bool free = k == 0 ? g.pb.layout.fit_rlkg : g.pb.layout.fit_ripl;
    if (free) {
      res.params.push_back(fitted(k == 0 ? "Rlkg" : "Ripl", kRUnit, k == 0 ? o.prior.Rlkg : o.prior.Ripl,
                                  k == 0 ? g.pb.layout.rlkg() : g.pb.layout.ripl()));
    } else {
      res.params.push_back(held_leakage(leak.estimate[k], o.try_leakage));
    }
  }

  res.fitted_params = est;
  if (!g.pb.predict(lm.x, res.predicted)) {
    res.error = "the model has no steady state at the estimate";
    return res;
  }
  res.validation = validation_table(points, res.predicted);
  return res;
}

}  // namespace hstmon::ident
