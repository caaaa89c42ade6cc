/// @file gap.cpp
/// Residual decomposition, effect fitting and ranking (see gap.hpp, docs/gap.md).
#include "hstmon_gap/gap.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "hstmon_gap/shrink.hpp"
#include "hstmon_ident/least_squares.hpp"
#include "autocorr.hpp"
#include "evidence.hpp"
#include "load_bins.hpp"
#include "noise_floor.hpp"
#include "steady_allowance.hpp"

namespace hstmon::gap {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<double, kChannels> kNoiseFloor = {500.0, 500.0, 500.0, 0.02};  // Pa, Pa, Pa, rad/s
constexpr host::Signal kChannelSignal[kChannels] = {host::Signal::kPMi, host::Signal::kPMo, host::Signal::kPPp,
                                                    host::Signal::kWm};

double median(std::vector<double> v) {
  if (v.empty()) return kNan;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// A log prepared for the analysis: inputs, measured channels, noise, masks.
struct Prepared {
  InputSeries u;
  std::vector<std::array<double, kChannels>> y;
  std::array<bool, kChannels> present{};
  std::array<double, kChannels> noise{};
  std::array<detail::NoiseEstimate, kChannels> noise_est{};
  std::vector<char> transient;
  double dt = 0;
  std::size_t n_resid = 0;  // number of weighted residuals
};

Prepared prepare(const host::LogData& log, const ThesisInputs<double>& defaults, double settle) {
  Prepared p;
  p.u = inputs_from_log(log, defaults);
  const std::size_t n = log.rows();
  std::vector<double> dts;
  for (std::size_t k = 1; k < n; ++k) dts.push_back(log.t[k] - log.t[k - 1]);
  p.dt = dts.empty() ? 0.0 : median(dts);
  p.transient.assign(n, 0);
  double t_change = -1e300;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) {
      auto changed = [](double a, double b) { return std::fabs(a - b) > 5e-3 * std::max(std::fabs(a), std::fabs(b)); };
      if (changed(p.u.kp[k], p.u.kp[k - 1]) || changed(p.u.Psupl[k], p.u.Psupl[k - 1]) ||
          changed(p.u.Pbp[k] + 1e5, p.u.Pbp[k - 1] + 1e5)) {
        t_change = log.t[k - 1];
      }
    }
    p.transient[k] = (log.t[k] - t_change <= settle + 1e-12) ? 1 : 0;
  }
  // The noise is read where the machine holds still (noise_floor.hpp); a log without a
  // steady stretch is read whole.
  std::vector<std::pair<std::size_t, std::size_t>> stretches;
  for (const auto& s : detail::settings_of(p.u, p.transient)) {
    if (s.steady() > 1) stretches.emplace_back(s.steady_from, s.end);
  }
  if (stretches.empty()) stretches.emplace_back(0, n);
  p.y.assign(n, {});
  for (int c = 0; c < kChannels; ++c) {
    const auto ci = static_cast<std::size_t>(c);
    p.present[ci] = log.has(kChannelSignal[c]);
    if (!p.present[ci]) continue;
    const auto& col = log.column(kChannelSignal[c]);
    for (std::size_t k = 0; k < n; ++k) p.y[k][ci] = col[k];
    p.noise_est[ci] = detail::estimate_noise(col, stretches, p.dt);
    p.noise[ci] = std::max(p.noise_est[ci].noise(), kNoiseFloor[ci]);
    p.n_resid += n;
  }
  return p;
}

// Each channel's RMS/noise against the moved model ym, and the significance on it.
void set_within(Where& w, const Prepared& p, const std::vector<std::array<double, kChannels>>& ym, double significance) {
  w.significant = false;
  for (std::size_t c = 0; c < kChannels; ++c) {
    auto& cs = w.channels[c];
    if (!cs.present || ym.size() != p.y.size() || p.y.empty()) continue;
    double ss = 0;
    for (std::size_t k = 0; k < p.y.size(); ++k) ss += std::pow((p.y[k][c] - ym[k][c]) / p.noise[c], 2);
    cs.rms_w_within = std::sqrt(ss / static_cast<double>(p.y.size()));
    if (cs.rms_w_within > significance) w.significant = true;
  }
}

// The steady settings of a log with their held inputs, for the evidence rule.
std::vector<detail::SettingEvidence> evidence_of(const Prepared& p) {
  std::vector<detail::SettingEvidence> out;
  for (const auto& s : detail::settings_of(p.u, p.transient)) {
    const std::size_t k = s.end - 1;
    out.push_back({s.steady(), {p.u.Psupl[k], p.u.Pbp[k], p.u.kp[k]}});
  }
  return out;
}

std::size_t count_settings(const Prepared& p) {
  std::size_t n = 0;
  for (const auto& s : evidence_of(p)) n += s.samples >= detail::kMinSamples ? 1 : 0;
  return n;
}

// Weighted residuals (data − model)/noise, channel-major, present channels only.
void weighted_residuals(const Prepared& p, const std::vector<std::array<double, kChannels>>& model,
                        std::vector<double>& r) {
  r.resize(p.n_resid);
  std::size_t i = 0;
  for (int c = 0; c < kChannels; ++c) {
    const auto ci = static_cast<std::size_t>(c);
    if (!p.present[ci]) continue;
    for (std::size_t k = 0; k < p.y.size(); ++k) r[i++] = (p.y[k][ci] - model[k][ci]) / p.noise[ci];
  }
}

double pooled_rms_w(const Prepared& p, const std::vector<std::array<double, kChannels>>& model) {
  std::vector<double> r;
  weighted_residuals(p, model, r);
  double s = 0;
  for (double v : r) s += v * v;
  return r.empty() ? 0.0 : std::sqrt(s / static_cast<double>(r.size()));
}

PartStats part(const Prepared& p, const std::vector<std::array<double, kChannels>>& res_w, const std::string& label,
               const std::vector<char>& mask) {
  PartStats s;
  s.label = label;
  std::size_t cnt = 0;
  std::array<double, kChannels> acc{};
  for (std::size_t k = 0; k < mask.size(); ++k) {
    if (!mask[k]) continue;
    ++cnt;
    for (std::size_t c = 0; c < kChannels; ++c) acc[c] += res_w[k][c] * res_w[k][c];
  }
  s.fraction = mask.empty() ? 0.0 : static_cast<double>(cnt) / static_cast<double>(mask.size());
  for (std::size_t c = 0; c < kChannels; ++c) {
    s.rms_w[c] = (cnt > 0 && p.present[c]) ? std::sqrt(acc[c] / static_cast<double>(cnt)) : kNan;
  }
  return s;
}

Where decompose(const Prepared& p, const std::vector<std::array<double, kChannels>>& model, double significance,
                const ThesisParams<double>& params) {
  Where w;
  // A gap the parameters make within their uncertainty is no gap (steady_allowance.hpp).
  const auto within = detail::thesis_allowance(params, p.u, p.y, model, p.present, p.noise, p.transient);
  w.uncertainty_z = within.a.z;
  w.parameter_moves = within.moves;
  const std::size_t n = p.y.size();
  w.sample_period = p.dt;
  std::vector<std::array<double, kChannels>> rw(n);
  double pooled = 0;
  int used = 0;
  for (std::size_t c = 0; c < kChannels; ++c) {
    auto& cs = w.channels[c];
    cs.present = p.present[c];
    if (!cs.present) {
      for (std::size_t k = 0; k < n; ++k) rw[k][c] = 0;
      continue;
    }
    double s = 0, s2 = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double r = p.y[k][c] - model[k][c];
      s += r;
      s2 += r * r;
      rw[k][c] = r / p.noise[c];
    }
    cs.mean = s / static_cast<double>(n);
    cs.rms = std::sqrt(s2 / static_cast<double>(n));
    cs.noise = p.noise[c];
    cs.rms_w = cs.rms / cs.noise;
    cs.rms_w_within = within.rms_w_within[c];
    cs.noise_white = p.noise_est[c].white;
    cs.adc_step = p.noise_est[c].step;
    cs.noise_spread = p.noise_est[c].spread;
    pooled += cs.rms_w * cs.rms_w;
    ++used;
    if (cs.rms_w_within > significance) w.significant = true;
  }
  w.rms_w_total = used > 0 ? std::sqrt(pooled / used) : 0.0;
  for (const auto& lb : detail::load_bins(p.u.kp)) w.load_bins.push_back(part(p, rw, lb.label, lb.mask));
  std::vector<char> st(n), tr(n);
  for (std::size_t k = 0; k < n; ++k) {
    tr[k] = p.transient[k];
    st[k] = !p.transient[k];
  }
  w.phases.push_back(part(p, rw, "steady", st));
  w.phases.push_back(part(p, rw, "transient", tr));
  // Bands: centred 0.5 s moving mean (slow) and the rest (fast).
  const std::size_t half = p.dt > 0 ? static_cast<std::size_t>(std::floor(0.25 / p.dt)) : 0;
  std::vector<std::array<double, kChannels>> slow(n), fast(n);
  for (std::size_t c = 0; c < kChannels; ++c) {
    std::vector<double> cum(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k) cum[k + 1] = cum[k] + rw[k][c];
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = k >= half ? k - half : 0, b = std::min(n, k + half + 1);
      slow[k][c] = (cum[b] - cum[a]) / static_cast<double>(b - a);
      fast[k][c] = rw[k][c] - slow[k][c];
    }
  }
  std::vector<char> all(n, 1);
  w.bands.push_back(part(p, slow, "slow (< ~2 Hz)", all));
  w.bands.push_back(part(p, fast, "fast", all));
  return w;
}

// The parameters being fitted for one effect set: x ↔ model.
struct Layout {
  std::vector<ActiveEffect> effects;  // start values
  std::vector<std::pair<std::size_t, std::size_t>> index;  // (effect, value) per x entry
  bool refit = false;

  std::size_t size() const { return index.size() + (refit ? 2 : 0); }

  std::vector<double> x0() const {
    std::vector<double> x;
    for (const auto& [e, v] : index) {
      x.push_back(effects[e].values[v] / effect_info(effects[e].id).params[v].scale);
    }
    if (refit) {
      x.push_back(0.0);
      x.push_back(0.0);
    }
    return x;
  }

  ExtendedModel model(const ThesisParams<double>& nominal, const std::vector<double>& x) const {
    ExtendedModel m;
    m.nominal = nominal;
    m.effects = effects;
    for (std::size_t i = 0; i < index.size(); ++i) {
      const auto [e, v] = index[i];
      m.effects[e].values[v] = x[i] * effect_info(effects[e].id).params[v].scale;
    }
    if (refit) {
      m.nominal.kf *= std::exp(0.1 * x[index.size()]);
      const double f = std::exp(0.3 * x[index.size() + 1]);
      m.nominal.Rf *= f;
      m.nominal.Rbl *= f;
    }
    return m;
  }
};

Layout make_layout(const std::vector<ActiveEffect>& effects, bool refit) {
  Layout l;
  l.effects = effects;
  l.refit = refit;
  for (std::size_t e = 0; e < effects.size(); ++e) {
    for (std::size_t v = 0; v < effects[e].values.size(); ++v) l.index.emplace_back(e, v);
  }
  return l;
}

double bic(double ssr, std::size_t n, std::size_t k) {
  const double nn = static_cast<double>(n);
  return nn * std::log(std::max(ssr, 1e-300) / nn) + static_cast<double>(k) * std::log(nn);
}

std::string set_name(const std::vector<Effect>& s) {
  std::string n;
  for (Effect e : s) n += (n.empty() ? "" : "+") + effect_info(e).name;
  return n;
}

class Analysis {
 public:
  Analysis(const Prepared& a, const Prepared& b, const ThesisParams<double>& p, const GapOptions& o, GapResult& res)
      : A_(a), B_(b), p_(p), o_(o), res_(res) {}

  std::vector<std::array<double, kChannels>> sim(const ExtendedModel& m, const Prepared& d, bool& ok) {
    ++res_.simulations;
    SimResult s = simulate(m, d.u, o_.sim);
    ok = s.ok;
    // The first row is the initial condition, not evidence: the logged inputs may already
    // hold the supply that comes on just after it (a log that starts at rest reads 0 bar
    // where the quasi-steady Pmi is at supply). The start-up from it is compared.
    if (ok && !s.y.empty()) s.y[0] = d.y[0];
    start_ = s.start;
    return std::move(s.y);
  }

  EffectFit fit(const std::vector<ActiveEffect>& start, double ssr_nominal_a, double rms_w_nominal_a,
                double rms_w_nominal_b, const std::vector<std::array<double, kChannels>>& nominal_b) {
    EffectFit f;
    for (const auto& a : start) {
      f.effects.push_back(a.id);
      if (a.id == Effect::kSensorOffset) f.offset_channel = a.channel;
    }
    f.name = set_name(f.effects);
    const Layout L = make_layout(start, o_.refit_nominal);
    const std::size_t m = A_.n_resid;
    ident::ResidualFn fn = [&](const std::vector<double>& x, std::vector<double>& r) {
      bool ok = false;
      const auto y = sim(L.model(p_, x), A_, ok);
      if (!ok) return false;
      weighted_residuals(A_, y, r);
      return true;
    };
    ident::LmOptions lo;
    lo.tolerance = 1e-7;
    lo.max_evaluations = static_cast<int>(40 + 30 * L.size());
    const ident::LmResult lm = ident::levenberg_marquardt(fn, m, L.x0(), lo);
    f.converged = lm.converged && lm.finite;
    f.evaluations = lm.evaluations;
    f.k = static_cast<int>(L.size());
    f.model = L.model(p_, lm.x);
    const double ssr = lm.finite ? lm.ssr : std::numeric_limits<double>::infinity();
    f.delta_bic_fit = bic(ssr, m, L.size()) - bic(ssr_nominal_a, m, 0);
    f.shrink_fit = shrink(rms_w_nominal_a, std::sqrt(ssr / static_cast<double>(m)));
    // Uncertainty: linearised covariance at the optimum.
    std::vector<double> se(L.size(), std::numeric_limits<double>::infinity());
    if (lm.finite) {
      std::vector<double> steps;
      for (double v : lm.x) steps.push_back(1e-4 * std::max(std::fabs(v), 0.01));
      ident::DenseMatrix jac;
      if (ident::central_jacobian(fn, m, lm.x, steps, jac)) {
        const auto st = ident::linear_stats(jac, ssr / static_cast<double>(m - L.size()));
        // Residuals of a model error are autocorrelated: n/τ effective samples.
        f.autocorrelation_time = detail::autocorrelation_time_blocks(lm.residuals, A_.y.size());
        se = st.se;
        for (double& v : se) v *= std::sqrt(f.autocorrelation_time);
      }
    }
    for (std::size_t i = 0; i < L.index.size(); ++i) {
      const auto [e, v] = L.index[i];
      const auto& info = effect_info(start[e].id);
      const auto& pi = info.params[v];
      ParamEstimate pe;
      pe.effect = info.name;
      pe.name = pi.name;
      pe.unit = pi.unit;
      if (start[e].id == Effect::kSensorOffset) {
        pe.unit = start[e].channel == 3 ? "rad/s" : "Pa";
        pe.name = std::string("offset_") + channel_names()[static_cast<std::size_t>(start[e].channel)];
      }
      const double val = lm.x[i] * pi.scale;
      pe.value = pi.positive ? std::fabs(val) : val;
      pe.se = se[i] * pi.scale;
      pe.identified = std::isfinite(pe.se) && pe.se < std::fabs(pe.value);
      f.params.push_back(pe);
    }
    if (o_.refit_nominal) {
      const std::size_t i = L.index.size();
      f.params.push_back({"nominal", "kf", "m^3/(s*sqrt(Pa))", f.model.nominal.kf,
                          p_.kf * 0.1 * se[i], std::isfinite(se[i])});
      f.params.push_back({"nominal", "Rf+Rbl", "N*m*s/rad", f.model.nominal.Rf + f.model.nominal.Rbl,
                          (p_.Rf + p_.Rbl) * 0.3 * se[i + 1], std::isfinite(se[i + 1])});
    }
    // Check log.
    bool ok = false;
    const auto yb = sim(f.model, B_, ok);
    f.rms_w_before_check = rms_w_nominal_b;
    if (ok) {
      f.rms_w_after_check = pooled_rms_w(B_, yb);
      for (std::size_t c = 0; c < kChannels; ++c) {
        if (!B_.present[c]) {
          f.rms_before_check[c] = f.rms_after_check[c] = kNan;
          continue;
        }
        double s0 = 0, s1 = 0;
        for (std::size_t k = 0; k < yb.size(); ++k) {
          s0 += std::pow(B_.y[k][c] - nominal_b[k][c], 2);
          s1 += std::pow(B_.y[k][c] - yb[k][c], 2);
        }
        f.rms_before_check[c] = std::sqrt(s0 / static_cast<double>(yb.size()));
        f.rms_after_check[c] = std::sqrt(s1 / static_cast<double>(yb.size()));
      }
    } else {
      f.rms_w_after_check = std::numeric_limits<double>::infinity();
    }
    f.shrink_check = shrink(rms_w_nominal_b, f.rms_w_after_check);
    if (!std::isfinite(f.shrink_check)) f.shrink_check = -1.0;
    return f;
  }

 private:
  const Prepared& A_;
  const Prepared& B_;
  ThesisParams<double> p_;
  const GapOptions& o_;
  GapResult& res_;

 public:
  std::string start_;  // how the last simulation started
};

// True when every effect of the set has a parameter the data pin down (SE < |value|): a
// pair needs evidence of both effects. Not every parameter: motor leakage that is all
// cross-port leaves its drain conductance at 0 ± its SE, which says that part is absent.
bool each_effect_identified(const EffectFit& f) {
  for (const ParamEstimate& q : f.params) {
    if (q.effect == "nominal") continue;
    const bool any = std::any_of(f.params.begin(), f.params.end(),
                                 [&q](const ParamEstimate& r) { return r.effect == q.effect && r.identified; });
    if (!any) return false;
  }
  return true;
}

// The ranking: the check log's RMS after the set (as the plain ratio, so that the penalty
// of 0.005 per extra parameter weighs the same near the noise as far from it).
double score(const EffectFit& f) {
  return plain_shrink(f.rms_w_before_check, f.rms_w_after_check) - 0.005 * (f.k - 1);
}

// The logger's timing of input steps (InputSeries::step_lead): the nominal run at 0, ¼, ½,
// ¾ and 1 of a sample interval; the smallest residual wins, 0 unless another is 1 %
// better. Effects shift levels alike at every timing, so they hardly move the choice.
double estimate_step_lead(const Prepared& p, const ThesisParams<double>& params, const SimOptions& so, int& sims) {
  bool steps = false;
  for (std::size_t k = 1; k < p.u.size() && !steps; ++k) steps = input_step(p.u, k);
  if (!steps || !(p.dt > 0) || p.dt > 0.2) return 0.0;
  ExtendedModel nominal;
  nominal.nominal = params;
  double best = 0, best_rms = std::numeric_limits<double>::infinity();
  for (double lead : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    InputSeries u = p.u;
    u.step_lead = lead;
    SimResult s = simulate(nominal, u, so);
    ++sims;
    if (!s.ok) continue;
    s.y[0] = p.y[0];
    const double rms = pooled_rms_w(p, s.y);
    if (rms < (lead == 0.0 ? 1.0 : 0.99) * best_rms) {
      best_rms = rms;
      best = lead;
    }
  }
  return best;
}

// Why a log cannot be used (fewer than 10 rows, no measured channel), or "" for both usable.
std::string unusable_log(const host::LogData& fit_log, const host::LogData& check_log) {
  for (const auto* lg : {&fit_log, &check_log}) {
    if (!lg->ok() || lg->rows() < 10) return lg->path + ": log unusable (needs at least 10 rows)";
    if (!lg->has(host::Signal::kPMi) && !lg->has(host::Signal::kPMo) && !lg->has(host::Signal::kPPp) &&
        !lg->has(host::Signal::kWm)) {
      return lg->path + ": no measured channel (p_mi, p_mo, p_pp, w_m)";
    }
  }
  return "";
}

// The effects the sampling can see: one whose time scale is far below the sample period dt [s]
// only shows in transients the log does not resolve (listed in not_identifiable instead).
std::vector<Effect> visible_effects(const std::vector<Effect>& effects, double dt,
                                    std::vector<NotIdentifiable>& not_identifiable) {
  std::vector<Effect> candidates;
  for (Effect e : effects) {
    const auto& info = effect_info(e);
    if (info.transient_time_scale > 0 && dt > 20.0 * info.transient_time_scale) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "sample period %.3g s is far longer than the effect's time scale (~%.3g s): it only shows in "
                    "transients the log does not resolve",
                    dt, info.transient_time_scale);
      not_identifiable.push_back({e, buf});
      continue;
    }
    candidates.push_back(e);
  }
  return candidates;
}

// Where the single-effect fit of e starts: the library default, but a sensor offset on the
// channel whose mean residual explains most of the fit log (closed form) and a supply flow
// limit just above the largest flow the fit log shows.
ActiveEffect single_start(Effect e, const Prepared& A, const Where& where_fit, const ThesisParams<double>& params) {
  ActiveEffect a = default_effect(e);
  if (e == Effect::kSensorOffset) {
    double best = -1;
    for (int c = 0; c < kChannels; ++c) {
      const auto ci = static_cast<std::size_t>(c);
      if (!A.present[ci]) continue;
      const double gain = std::pow(where_fit.channels[ci].mean / A.noise[ci], 2);
      if (gain > best) {
        best = gain;
        a.channel = c;
        a.values[0] = where_fit.channels[ci].mean;
      }
    }
  } else if (e == Effect::kSupplyFlowLimit) {
    double qmax = 0;
    for (const auto& y : A.y) qmax = std::max(qmax, params.Dm * std::fabs(y[3]));
    if (!A.present[3]) qmax = 1.5e-3;
    a.values[0] = 1.02 * qmax;
  }
  return a;
}

// Where the pair fits start. Pairs among the best few; the best with every other kept effect (a
// second effect fitted alone bends its parameter to absorb the first's gap, so it can rank far
// below what it does beside the first: PRV cracking beside Coulomb friction fits 2.4 of 5 bar
// alone and ranks fifth); and the best with a sensor offset on each channel (an offset
// ranked low alone, because the other effect hides it, would never be among the few).
// Not each of the few with every effect of the library: on a 15 s log beyond the library
// that is 1 400 simulations instead of 400, most in pair fits that find nothing.
std::vector<std::vector<ActiveEffect>> pair_starts(const std::vector<EffectFit>& useful, bool offset_allowed,
                                                   int pair_candidates, Analysis& an, const Prepared& A) {
  std::vector<std::vector<ActiveEffect>> starts;
  auto add_pair = [&starts](const EffectFit& a, const EffectFit& b) {
    std::vector<ActiveEffect> st;
    for (const auto* f : {&a, &b}) {
      for (const auto& ae : f->model.effects) st.push_back(ae);
    }
    starts.push_back(std::move(st));
  };
  const std::size_t np = std::min<std::size_t>(useful.size(), static_cast<std::size_t>(std::max(0, pair_candidates)));
  for (std::size_t i = 0; i < np; ++i) {
    for (std::size_t j = i + 1; j < np; ++j) add_pair(useful[i], useful[j]);
  }
  // The best with every other kept effect, from its single fit (offsets below).
  for (std::size_t j = np; np > 0 && j < useful.size(); ++j) {
    if (useful[j].effects.front() != Effect::kSensorOffset) add_pair(useful.front(), useful[j]);
  }
  if (offset_allowed && !useful.empty() && useful.front().effects.front() != Effect::kSensorOffset) {
    bool ok = false;
    const auto yf = an.sim(useful.front().model, A, ok);
    // One pair per measured channel: the best effect, fitted alone, bends its parameter
    // to absorb part of an offset, so its residual need not point at the right channel.
    for (int c = 0; ok && c < kChannels; ++c) {
      const auto ci = static_cast<std::size_t>(c);
      if (!A.present[ci]) continue;
      ActiveEffect off = default_effect(Effect::kSensorOffset, c);
      double m = 0;
      for (std::size_t k = 0; k < yf.size(); ++k) m += A.y[k][ci] - yf[k][ci];
      off.values[0] = m / static_cast<double>(yf.size());
      std::vector<ActiveEffect> st = useful.front().model.effects;
      st.push_back(off);
      const bool dup = std::any_of(starts.begin(), starts.end(), [&](const std::vector<ActiveEffect>& x) {
        return std::any_of(x.begin(), x.end(),
                           [&](const ActiveEffect& q) { return q.id == Effect::kSensorOffset && q.channel == c; }) &&
               std::any_of(x.begin(), x.end(), [&](const ActiveEffect& q) { return q.id == st.front().id; });
      });
      if (!dup) starts.push_back(std::move(st));
    }
  }
  return starts;
}

// Whether pair pf earns its place beside the best single effect bi: better on the fit log (BIC)
// and on the check log — 0.05 more of the plain ratio 1 − a/b, or a third less of what the
// best single leaves (near noise the latter cannot happen) — with each of its effects identified.
bool pair_needed(const EffectFit& pf, const EffectFit& bi) {
  const bool better_check = plain_shrink(pf.rms_w_before_check, pf.rms_w_after_check) >=
                                plain_shrink(bi.rms_w_before_check, bi.rms_w_after_check) + 0.05 ||
                            pf.rms_w_after_check <= 0.7 * bi.rms_w_after_check;
  return better_check && pf.delta_bic_fit < bi.delta_bic_fit - 10.0 && each_effect_identified(pf);
}

// Another set (not containing the best's effects) doing as well: the data cannot tell them apart.
void note_indistinguishable(GapResult& res) {
  const EffectFit& best = res.ranking.front();
  for (std::size_t i = 1; i < res.ranking.size(); ++i) {
    const EffectFit& f = res.ranking[i];
    const bool disjoint = std::none_of(f.effects.begin(), f.effects.end(), [&](Effect e) {
      return std::find(best.effects.begin(), best.effects.end(), e) != best.effects.end();
    });
    const double lead = plain_shrink(best.rms_w_before_check, best.rms_w_after_check) -
                        plain_shrink(f.rms_w_before_check, f.rms_w_after_check);
    if (disjoint && lead < 0.02 && f.delta_bic_fit - best.delta_bic_fit < 10.0) {
      if (res.cannot_tell_apart.empty()) res.cannot_tell_apart.push_back(best.name);
      res.cannot_tell_apart.push_back(f.name);
    }
  }
}

// Beyond the library: the located equation eq's missing term from the balance equations of both
// logs; for a state equation, the nominal model run with it on the check log B (rmsw_b: its RMS before).
void discover_missing_term(GapResult& res, int eq, const ArrData& arr_a, const ArrData& arr_b,
                           const ExtendedModel& nominal, Analysis& an, const Prepared& B, double rmsw_b) {
  auto d = discover(arr_a, arr_b, eq);
  if (!d) return;
  // State equations: simulate the nominal model with the terms on the check log.
  if (eq == kEqFlowPp || eq == kEqTorque) {
    ExtendedModel m = nominal;
    m.terms = d->model_terms;
    bool ok = false;
    const auto y = an.sim(m, B, ok);
    if (ok) {
      d->simulated = true;
      d->model_shrink_check = shrink(rmsw_b, pooled_rms_w(B, y));
      for (std::size_t c = 0; c < kChannels; ++c) {
        double s2 = 0;
        for (std::size_t k = 0; k < y.size(); ++k) s2 += std::pow(B.y[k][c] - y[k][c], 2);
        d->channel_rms_w_after_check[c] =
            B.present[c] ? std::sqrt(s2 / static_cast<double>(y.size())) / B.noise[c] : kNan;
      }
    }
  }
  res.discovered.push_back(std::move(*d));
}

}  // namespace

InputSeries inputs_from_log(const host::LogData& log, const ThesisInputs<double>& d) {
  InputSeries u;
  const std::size_t n = log.rows();
  u.t = log.t;
  auto col = [&](host::Signal s, double def) {
    return log.has(s) ? log.column(s) : std::vector<double>(n, def);
  };
  u.Psupl = col(host::Signal::kPSup, d.Psupl);
  u.Ps = col(host::Signal::kPS, d.Ps);
  u.Pbp = col(host::Signal::kPBp, d.Pbp);
  u.kp = col(host::Signal::kKp, d.kp);
  // The first sample, for the initial state (choose_initial_state, as replay).
  u.start = StartRule::kFirstSample;
  for (int c = 0; c < kChannels; ++c) {
    if (n == 0 || !log.has(kChannelSignal[c])) continue;
    const double v = log.column(kChannelSignal[c])[0];
    if (!std::isfinite(v)) continue;
    u.y0[static_cast<std::size_t>(c)] = v;
    u.y0_valid = static_cast<std::uint8_t>(u.y0_valid | (1u << c));
  }
  return u;
}

GapResult run_gap(const host::LogData& fit_log, const host::LogData& check_log, const ThesisParams<double>& params,
                  const ThesisInputs<double>& defaults, const GapOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  GapResult res;
  auto t_stage = t0;
  // Wall time of the stage that ends here (GapResult::stage_seconds).
  auto stage = [&](const char* name) {
    const auto now = std::chrono::steady_clock::now();
    res.stage_seconds.emplace_back(name, std::chrono::duration<double>(now - t_stage).count());
    t_stage = now;
  };
  res.error = unusable_log(fit_log, check_log);
  if (!res.error.empty()) return res;
  Prepared A = prepare(fit_log, defaults, o.settle_time);
  Prepared B = prepare(check_log, defaults, o.settle_time);
  res.step_lead_fit = A.u.step_lead = estimate_step_lead(A, params, o.sim, res.simulations);
  res.step_lead_check = B.u.step_lead = estimate_step_lead(B, params, o.sim, res.simulations);
  Analysis an(A, B, params, o, res);
  ExtendedModel nominal;
  nominal.nominal = params;
  bool ok_a = false, ok_b = false;
  const auto ya = an.sim(nominal, A, ok_a);
  res.start_fit = an.start_;
  const auto yb = an.sim(nominal, B, ok_b);
  res.start_check = an.start_;
  if (!ok_a || !ok_b) {
    res.error = "the nominal model cannot be simulated with these inputs";
    return res;
  }
  stage("nominal_run");
  res.where_fit = decompose(A, ya, o.significance, params);
  res.where_check = decompose(B, yb, o.significance, params);
  // The gap left once the parameters take their most likely values within their
  // uncertainty, transients included: the moved model run again.
  for (auto [P, W] : {std::pair<const Prepared*, Where*>{&A, &res.where_fit}, {&B, &res.where_check}}) {
    ExtendedModel moved = nominal;
    moved.nominal = detail::moved_params(params, W->parameter_moves);
    bool ok = false;
    const auto ym = an.sim(moved, *P, ok);
    if (ok) set_within(*W, *P, ym, o.significance);
  }
  // Where at equation level: the balance equations on the measured signals alone.
  const ArrData arr_a = evaluate_arrs(params, A.u, A.y, A.present, A.noise);
  const ArrData arr_b = evaluate_arrs(params, B.u, B.y, B.present, B.noise);
  res.where_fit.equations = equation_stats(arr_a);
  res.where_check.equations = equation_stats(arr_b);
  res.where_fit.located = located_equation(res.where_fit.equations);
  res.where_check.located = located_equation(res.where_check.equations);
  stage("where_and_equations");
  res.t_check = check_log.t;
  res.kp_check = B.u.kp;
  res.data_check = B.y;
  res.nominal_check = yb;
  res.best_check = yb;
  res.t_fit = fit_log.t;
  res.kp_fit = A.u.kp;
  res.data_fit = A.y;
  res.nominal_fit = ya;
  res.ok = true;
  res.where_fit.steady_settings = count_settings(A);
  res.where_check.steady_settings = count_settings(B);
  res.evidence_missing = detail::missing_evidence("fit", evidence_of(A));
  if (res.evidence_missing.empty()) res.evidence_missing = detail::missing_evidence("check", evidence_of(B));
  if (!res.evidence_missing.empty()) {
    decide_verdict(res);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }

  // Which effects can the sampling see?
  const double dt = std::max(A.dt, B.dt);
  const std::vector<Effect> candidates = visible_effects(o.effects, dt, res.not_identifiable);

  if (!res.where_fit.significant && !res.where_check.significant) {
    decide_verdict(res);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }
  // Out of envelope: the machine is not the model's kind; no effect is fitted or named.
  add_envelope_segments(res.envelope, nominal, A.u, A.y, ya, A.present, A.noise, o.settle_time, o.sim.thesis);
  add_envelope_segments(res.envelope, nominal, B.u, B.y, yb, B.present, B.noise, o.settle_time, o.sim.thesis);
  finish_envelope(res.envelope);
  stage("envelope");
  if (res.envelope.out) {
    decide_verdict(res);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }
  std::vector<double> ra;
  weighted_residuals(A, ya, ra);
  double ssr0 = 0;
  for (double v : ra) ssr0 += v * v;
  const double rmsw_a = std::sqrt(ssr0 / static_cast<double>(ra.size()));
  const double rmsw_b = pooled_rms_w(B, yb);

  // Single effects.
  std::vector<EffectFit> singles;
  for (Effect e : candidates) {
    singles.push_back(an.fit({single_start(e, A, res.where_fit, params)}, ssr0, rmsw_a, rmsw_b, yb));
  }
  std::vector<EffectFit> useful;
  for (auto& f : singles) {
    if (f.delta_bic_fit < -10.0 && f.shrink_check > 0.0) {
      useful.push_back(std::move(f));
    } else {
      res.rejected.push_back(std::move(f));
    }
  }
  std::sort(useful.begin(), useful.end(), [](const EffectFit& x, const EffectFit& y) { return score(x) > score(y); });

  stage("single_effects");
  const bool offset_allowed = std::find(candidates.begin(), candidates.end(), Effect::kSensorOffset) != candidates.end();
  const std::vector<std::vector<ActiveEffect>> starts = pair_starts(useful, offset_allowed, o.pair_candidates, an, A);
  std::vector<EffectFit> pairs;
  for (const auto& st : starts) {
    EffectFit pf = an.fit(st, ssr0, rmsw_a, rmsw_b, yb);
    if (pair_needed(pf, useful.front())) {  // beside the best single effect overall
      pairs.push_back(std::move(pf));
    } else {
      res.rejected.push_back(std::move(pf));
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const EffectFit& x, const EffectFit& y) { return score(x) > score(y); });
  for (auto& f : pairs) res.ranking.push_back(std::move(f));
  for (auto& f : useful) res.ranking.push_back(std::move(f));

  stage("pairs");
  if (!res.ranking.empty()) {
    note_indistinguishable(res);
    bool ok = false;
    res.best_check = an.sim(res.ranking.front().model, B, ok);
    if (!ok) res.best_check = yb;
  }
  decide_verdict(res);
  // Beyond the library: when no library set brings the check log to noise, propose the
  // located equation's missing term.
  if (res.verdict != "explained" && res.verdict != "explained_by_pair") {
    const int eq = res.where_fit.located >= 0 ? res.where_fit.located : res.where_check.located;
    if (eq >= 0) discover_missing_term(res, eq, arr_a, arr_b, nominal, an, B, rmsw_b);
    decide_verdict(res);
  }
  stage("verdict_and_discovery");
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace hstmon::gap
