#include "hstmon_gap/circuit_gap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "circuit_judge.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_ident/circuit_fit.hpp"

namespace hstmon::gap {

namespace {

using Model = host::HostCircuitModel;
using circuit::ElementKind;
using circuit::Ref;
using circuit::RefKind;

double value_of(const circuit_tools::LoadedCircuit& c, Ref r, double dflt) {
  if (r.kind == RefKind::kParam) return c.values.params.v[r.index];
  if (r.kind == RefKind::kInput) return c.values.inputs.v[r.index];
  return dflt;
}

double rms(const std::vector<double>& r) {
  if (r.empty()) return 0.0;
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s / static_cast<double>(r.size()));
}

// Residuals of c with effect e of magnitude m at the points; an offset m [channel SI:
// reading = true + m] is subtracted from its channel's residuals. Empty when some point has
// no steady state.
std::vector<double> effect_residuals(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m,
                                     const detail::PointSet& s) {
  std::vector<double> res;
  if (e.kind == CircuitEffect::Kind::kOffset) {
    if (!detail::point_residuals(c, c.values.params, s, res)) return {};
    std::size_t k = 0;
    for (const auto& pt : s.points) {
      for (std::size_t ch = 0; ch < pt.mean.size(); ++ch) {
        if (!std::isfinite(pt.mean[ch])) continue;
        if (static_cast<int>(ch) == e.index) res[k] -= m / s.sigma[ch];
        ++k;
      }
    }
    return res;
  }
  const circuit_tools::LoadedCircuit a = with_effect(c, e, m);
  if (!detail::point_residuals(a, a.values.params, s, res)) return {};
  return res;
}

double rms_or_inf(const std::vector<double>& r) { return r.empty() ? std::numeric_limits<double>::infinity() : rms(r); }

// How a candidate's fit residuals are scored: their RMS, or with the nominal parameters
// refit (CircuitGapOptions::refit_nominal) the allowance's z against the fit log's columns.
struct Scoring {
  bool refit = false;
  std::vector<std::vector<double>> columns;  ///< detail::allowance_columns on the fit log, at the file's values
  double operator()(const std::vector<double>& r) const {
    if (r.empty()) return std::numeric_limits<double>::infinity();
    return refit ? detail::parameter_allowance(r, columns).z : rms(r);
  }
};

// The magnitude a·reference minimising the fit score: a scan of log10 a over [−6, 1] by
// halves, then golden section between the best scan point's neighbours.
double fit_magnitude(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, const detail::PointSet& points,
                     const Scoring& score) {
  auto cost = [&](double lg) { return score(effect_residuals(c, e, e.reference * std::pow(10.0, lg), points)); };
  double best_lg = -6.0, best = cost(best_lg);
  for (double lg = -5.5; lg <= 1.0 + 1e-9; lg += 0.5) {
    const double v = cost(lg);
    if (v < best) {
      best = v;
      best_lg = lg;
    }
  }
  double lo = best_lg - 0.5, hi = best_lg + 0.5;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = cost(x1), f2 = cost(x2);
  for (int it = 0; it < 30; ++it) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = cost(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = cost(x2);
    }
  }
  const double lg = f1 < f2 ? x1 : x2;
  return e.reference * std::pow(10.0, std::min(f1, f2) <= best ? lg : best_lg);
}

}  // namespace

const char* effect_unit(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e) {
  switch (e.kind) {
    case CircuitEffect::Kind::kLeak: return "m3/(s*Pa)";
    case CircuitEffect::Kind::kFriction: return "N*m*s/rad";
    case CircuitEffect::Kind::kTorqueLoss: return "N*m";
    case CircuitEffect::Kind::kOffset:
      return host::circuit_si_unit(c.file.sensors[static_cast<std::size_t>(e.index)].quantity);
    case CircuitEffect::Kind::kParam: return "-";
  }
  return "";
}

std::vector<CircuitEffect> circuit_effects(const circuit_tools::LoadedCircuit& c) {
  const host::HostCircuit& d = c.file.circuit;
  const Model m(d, c.values.params, c.values.inputs);
  const double p_env = m.pressure_envelope(), w_env = m.speed_envelope();
  // Flow and torque scales of the circuit: its largest machine flow and torque.
  double q_scale = 0.0;
  std::vector<double> t_scale(static_cast<std::size_t>(d.n_shafts), 0.0);
  for (int k = 0; k < d.n_elements; ++k) {
    const circuit::Element& el = d.elements[k];
    if (el.kind == ElementKind::kMachine) {
      const double D = std::fabs(value_of(c, el.r[circuit::kD], 0.0));
      q_scale = std::max(q_scale, D * w_env);
      if (el.shaft >= 0) {
        auto& t = t_scale[static_cast<std::size_t>(el.shaft)];
        t = std::max(t, D * p_env);
      }
    } else if (el.kind == ElementKind::kCompPump) {
      q_scale = std::max(q_scale, std::fabs(value_of(c, el.r[circuit::kQ0], 0.0)));
    } else if (el.kind == ElementKind::kFlowSource) {
      q_scale = std::max(q_scale, std::fabs(value_of(c, el.r[circuit::kQ], 0.0)));
    }
  }
  if (!(q_scale > 0.0)) q_scale = 1e-4;
  std::vector<CircuitEffect> out;
  for (int i = 0; i < d.n_nodes; ++i) {
    if (d.nodes[i].kind != circuit::NodeKind::kVolume) continue;
    out.push_back({CircuitEffect::Kind::kLeak, i, "leak(" + c.file.nodes[static_cast<std::size_t>(i)] + ")",
                   q_scale / p_env});
  }
  for (int s = 0; s < d.n_shafts; ++s) {
    if (d.shafts[s].driven) continue;
    const double t = t_scale[static_cast<std::size_t>(s)] > 0.0 ? t_scale[static_cast<std::size_t>(s)] : 1.0;
    const std::string& n = c.file.shafts[static_cast<std::size_t>(s)];
    out.push_back({CircuitEffect::Kind::kFriction, s, "friction(" + n + ")", t / w_env});
    out.push_back({CircuitEffect::Kind::kTorqueLoss, s, "torque_loss(" + n + ")", t});
  }
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    out.push_back({CircuitEffect::Kind::kOffset, static_cast<int>(ch), "offset(" + c.file.sensors[ch].name + ")", 1.0});
  }
  return out;
}

namespace {

/// The element an effect adds to the circuit and its one new parameter.
struct EffectElement {
  ElementKind kind;
  circuit::Slot slot;              ///< the parameter's place in the element
  const char* param;               ///< the parameter's name in the circuit file
  host::CircuitQuantity quantity;  ///< what the parameter measures
};

/// For a leak (a laminar path to the tank), a friction or a torque loss on a shaft.
EffectElement effect_element(CircuitEffect::Kind k) {
  switch (k) {
    case CircuitEffect::Kind::kLeak:
      return {ElementKind::kLaminar, circuit::kR, "gap_leak_R", host::CircuitQuantity::kResistance};
    case CircuitEffect::Kind::kFriction:
      return {ElementKind::kFriction, circuit::kC, "gap_friction", host::CircuitQuantity::kDamping};
    default:
      return {ElementKind::kTorque, circuit::kTau, "gap_torque", host::CircuitQuantity::kTorque};
  }
}

}  // namespace

circuit_tools::LoadedCircuit with_effect(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m) {
  circuit_tools::LoadedCircuit a = c;
  if (e.kind == CircuitEffect::Kind::kOffset) return a;
  if (e.kind == CircuitEffect::Kind::kParam) {
    a.values.params.v[e.index] *= 1.0 + m;
    return a;
  }
  host::HostCircuit& d = a.file.circuit;
  if (d.n_params >= host::CircuitCap::kParams || d.n_elements >= host::CircuitCap::kElements) return a;
  const int p = d.n_params++;
  const EffectElement how = effect_element(e.kind);
  circuit::Element el;
  el.kind = how.kind;
  double value = m;
  if (e.kind == CircuitEffect::Kind::kLeak) {
    // To the boundary of lowest pressure (the tank).
    int tank = -1;
    double lowest = HUGE_VAL;
    for (int i = 0; i < d.n_nodes; ++i) {
      if (d.nodes[i].kind != circuit::NodeKind::kBoundary) continue;
      const double pb = value_of(c, d.nodes[i].pressure, 0.0);
      if (pb < lowest) {
        lowest = pb;
        tank = i;
      }
    }
    if (tank < 0) {
      --d.n_params;
      return a;
    }
    el.a = static_cast<std::uint8_t>(e.index);
    el.b = static_cast<std::uint8_t>(tank);
    value = 1.0 / m;  // a conductance's resistance
  } else {
    el.shaft = static_cast<std::int8_t>(e.index);
  }
  el.r[how.slot] = circuit::param_ref(p);
  a.values.params.v[p] = value;
  a.file.params.push_back({how.param, how.quantity, value, false, e.name});
  d.elements[d.n_elements++] = el;
  a.file.elements.push_back(e.name);
  return a;
}

namespace {

// True when parameter k is the law of a leak or friction candidate already (a laminar
// resistance from a volume to a boundary, a shaft's viscous friction): the effect names it.
bool same_law_as_effect(const host::HostCircuit& d, int k) {
  for (int i = 0; i < d.n_elements; ++i) {
    const circuit::Element& el = d.elements[i];
    if (el.kind == ElementKind::kLaminar && el.r[circuit::kR].kind == RefKind::kParam && el.r[circuit::kR].index == k) {
      const bool vol_a = d.nodes[el.a].kind == circuit::NodeKind::kVolume, vol_b = d.nodes[el.b].kind == circuit::NodeKind::kVolume;
      if (vol_a != vol_b) return true;
    }
    if (el.kind == ElementKind::kFriction && el.r[circuit::kC].kind == RefKind::kParam && el.r[circuit::kC].index == k) {
      return true;
    }
  }
  return false;
}

// parameter(<name>) candidates: every uncertain parameter no effect candidate duplicates.
std::vector<CircuitEffect> parameter_effects(const circuit_tools::LoadedCircuit& c) {
  std::vector<CircuitEffect> out;
  for (const auto& [k, e] : detail::uncertain_params(c)) {
    if (same_law_as_effect(c.file.circuit, k)) continue;
    out.push_back({CircuitEffect::Kind::kParam, k, "parameter(" + c.file.params[static_cast<std::size_t>(k)].name + ")", e});
  }
  return out;
}

// A parameter's relative change that best meets the fit log: one Gauss–Newton step from
// the file's value (the residuals are near linear in a few per cent), at most ×/÷ 3.
double fit_parameter(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, const detail::PointSet& s,
                     const std::vector<double>& base) {
  const std::vector<double> r1 = effect_residuals(c, e, e.reference, s);
  if (r1.size() != base.size()) return 0.0;
  double num = 0, den = 0;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const double j = r1[i] - base[i];
    num += j * base[i];
    den += j * j;
  }
  if (!(den > 0)) return 0.0;
  return std::clamp(-num / den * e.reference, -2.0 / 3.0, 2.0);
}

// The mean residual per channel over the points [σ].
std::vector<double> channel_means(const std::vector<double>& base, const detail::PointSet& s, std::size_t channels) {
  std::vector<double> mean(channels, 0.0);
  std::vector<std::size_t> count(channels, 0);
  std::size_t k = 0;
  for (const auto& pt : s.points) {
    for (std::size_t ch = 0; ch < channels; ++ch) {
      if (!std::isfinite(pt.mean[ch])) continue;
      mean[ch] += base[k++];
      ++count[ch];
    }
  }
  for (std::size_t ch = 0; ch < channels; ++ch) mean[ch] = count[ch] ? mean[ch] / static_cast<double>(count[ch]) : std::nan("");
  return mean;
}

// Candidate e fitted on the fit log's points F (base: their residuals at the file's values,
// mean_fit: per channel [σ]) and judged on the check log's C, scored by `score`.
CircuitEffectResult evaluate_candidate(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e,
                                       const detail::PointSet& F, const detail::PointSet& C,
                                       const std::vector<double>& base, const std::vector<double>& mean_fit,
                                       const Scoring& score) {
  CircuitEffectResult er;
  er.effect = e;
  if (e.kind == CircuitEffect::Kind::kOffset) {
    const double m = mean_fit[static_cast<std::size_t>(e.index)];
    er.magnitude = std::isfinite(m) ? m * F.sigma[static_cast<std::size_t>(e.index)] : 0.0;
  } else if (e.kind == CircuitEffect::Kind::kParam) {
    er.magnitude = fit_parameter(c, e, F, base);
  } else {
    er.magnitude = fit_magnitude(c, e, F, score);
  }
  const std::vector<double> fitted = effect_residuals(c, e, er.magnitude, F);
  // The check log at the fit's parameter values: the file's, or those refit with the effect.
  circuit_tools::LoadedCircuit judged = c;
  if (score.refit && !fitted.empty()) {
    const detail::Allowance a = detail::parameter_allowance(fitted, score.columns);
    er.rms_fit = rms(a.after);
    judged.values.params = detail::moved_params(c, a.delta);
  } else {
    er.rms_fit = rms_or_inf(fitted);
  }
  const std::vector<double> after = effect_residuals(judged, e, er.magnitude, C);
  er.rms_check = rms_or_inf(after);
  er.z_check = after.empty() ? er.rms_check : detail::circuit_allowance(c, C, after).z;
  er.ok = std::isfinite(er.rms_fit) && std::isfinite(er.rms_check);
  return er;
}

constexpr double kWithin = 2.0;  // z at or below: within noise and parameter uncertainty

// Verdict: no gap when both logs lie within noise and parameter uncertainty; an effect when
// it halves the check log's residual and leads the runner-up by 1.5×; two close ones are
// "ambiguous" only when the best leaves the check log within noise and uncertainty.
void decide(CircuitGapResult& r) {
  if (r.z_fit <= kWithin && r.z_check <= kWithin) {
    r.verdict = "none";
    return;
  }
  if (r.ranked.empty() || !r.ranked[0].ok || r.ranked[0].rms_check > 0.5 * r.rms_check) {
    r.verdict = "unexplained";
    return;
  }
  const auto& a = r.ranked[0];
  const bool clear = r.ranked.size() < 2 || r.ranked[1].rms_check >= 1.5 * a.rms_check;
  if (clear) {
    r.verdict = a.effect.name;
  } else if (a.z_check <= kWithin) {
    r.verdict = "ambiguous: " + a.effect.name + " or " + r.ranked[1].effect.name;
  } else {
    r.verdict = "unexplained";
    char b[200];
    std::snprintf(b, sizeof b, "%s and %s reduce the check log's gap alike but leave %.1f sigma beyond noise and uncertainty",
                  a.effect.name.c_str(), r.ranked[1].effect.name.c_str(), a.z_check);
    r.notes.push_back(b);
  }
}

// Where, by balance equation: the circuit's equations on both logs, the located one and
// its missing term (circuit_equations.hpp, circuit_discover.hpp).
void where_by_equation(CircuitGapResult& r, const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& fit,
                       const circuit_tools::CircuitLog& check, const detail::PointSet& F, const detail::PointSet& C) {
  const CircuitArrData a = evaluate_circuit_arrs(c, fit, F.sigma);
  const CircuitArrData b = evaluate_circuit_arrs(c, check, C.sigma);
  r.equations_fit = circuit_equation_stats(a);
  r.equations_check = circuit_equation_stats(b);
  for (std::size_t e = 0; e < a.equations.size(); ++e) {
    r.equations_missing.push_back(!a.missing[e].empty() ? a.missing[e] : b.missing[e]);
  }
  int eq = located_equation(r.equations_fit);
  if (eq < 0) eq = located_equation(r.equations_check);
  if (eq < 0) return;
  r.located_equation = a.equations[static_cast<std::size_t>(eq)].name;
  r.discovery = discover_circuit(c, a, b, eq);
}

}  // namespace

std::vector<CircuitEffect> chosen_effects(const circuit_tools::LoadedCircuit& c, const std::vector<std::string>& effects,
                                          std::string& error) {
  std::vector<CircuitEffect> all = circuit_effects(c);
  for (const auto& e : parameter_effects(c)) all.push_back(e);
  error.clear();
  if (effects.empty()) return all;
  // A name is a candidate's own ("leak(p_b)") or its kind, the part before the parenthesis.
  auto named = [](const CircuitEffect& e, const std::string& want) {
    return e.name == want || e.name.compare(0, e.name.find('('), want) == 0;
  };
  for (const std::string& want : effects) {
    if (std::any_of(all.begin(), all.end(), [&](const CircuitEffect& e) { return named(e, want); })) continue;
    std::string names;
    for (const CircuitEffect& e : all) names += (names.empty() ? "" : ", ") + e.name;
    error = "--effects: '" + want + "' is none of circuit " + c.file.name + "'s candidates (" + names +
            ") nor a kind of them (leak, friction, torque_loss, offset, parameter)";
    return {};
  }
  std::vector<CircuitEffect> out;
  for (const CircuitEffect& e : all) {
    if (std::any_of(effects.begin(), effects.end(), [&](const std::string& want) { return named(e, want); })) {
      out.push_back(e);
    }
  }
  return out;
}

CircuitGapResult circuit_gap(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& fit,
                             const circuit_tools::CircuitLog& check, const CircuitGapOptions& o) {
  CircuitGapResult r;
  std::string effects_error;
  const std::vector<CircuitEffect> candidates = chosen_effects(c, o.effects, effects_error);
  if (!effects_error.empty()) {
    r.error = effects_error;
    return r;
  }
  const detail::PointSet F = detail::circuit_point_set(c, fit), C = detail::circuit_point_set(c, check);
  r.fit_points = F.points.size();
  r.check_points = C.points.size();
  r.noise_fit = F.sigma;
  r.noise_check = C.sigma;
  where_by_equation(r, c, fit, check, F, C);
  r.evidence_missing = detail::circuit_evidence("fit", F);
  if (r.evidence_missing.empty()) r.evidence_missing = detail::circuit_evidence("check", C);
  if (!r.evidence_missing.empty()) {
    r.verdict = "insufficient_data";
    return r;
  }
  std::vector<double> base, base_check;
  if (!detail::point_residuals(c, c.values.params, F, base)) {
    r.error = "no steady state at some operating point of the fit log";
    return r;
  }
  r.rms_fit = rms(base);
  (void)detail::point_residuals(c, c.values.params, C, base_check);
  r.rms_check = rms_or_inf(base_check);
  r.z_fit = detail::circuit_allowance(c, F, base).z;
  r.z_check = base_check.empty() ? r.rms_check : detail::circuit_allowance(c, C, base_check).z;
  const std::size_t channels = c.file.sensors.size();
  r.mean_fit = channel_means(base, F, channels);
  for (std::size_t ch = 0; ch < channels; ++ch) r.channels.push_back(c.file.sensors[ch].name);

  Scoring score;
  if (o.refit_nominal) {
    score = {true, detail::allowance_columns(c, F, base)};
    // Without an effect: the parameters alone refit, the check log at their values.
    const detail::Allowance a = detail::parameter_allowance(base, score.columns);
    r.rms_fit = rms(a.after);
    std::vector<double> moved_check;
    r.rms_check = detail::point_residuals(c, detail::moved_params(c, a.delta), C, moved_check) ? rms(moved_check)
                                                                                               : r.rms_check;
    r.notes.push_back("--refit-nominal: each candidate fitted together with the " +
                      std::to_string(score.columns.size()) +
                      " uncertain parameters, each move charged against its stated uncertainty; the check log judged "
                      "at the fit log's values");
  }
  for (const CircuitEffect& e : candidates) r.ranked.push_back(evaluate_candidate(c, e, F, C, base, r.mean_fit, score));
  std::stable_sort(r.ranked.begin(), r.ranked.end(), [](const CircuitEffectResult& a, const CircuitEffectResult& b) {
    return a.ok != b.ok ? a.ok : a.rms_check < b.rms_check;
  });
  decide(r);
  return r;
}

}  // namespace hstmon::gap
