#include "hstmon_gap/circuit_gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// Residuals of c with effect e of magnitude m at the points; an offset subtracts m (in σ)
// from its channel's residuals. Empty when some point has no steady state.
std::vector<double> effect_residuals(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m,
                                     const std::vector<ident::CircuitOperatingPoint>& points) {
  std::vector<double> res;
  if (e.kind == CircuitEffect::Kind::kOffset) {
    if (!ident::circuit_point_residuals(c, c.values.params, points, res)) return {};
    std::size_t k = 0;
    for (const auto& pt : points) {
      for (std::size_t ch = 0; ch < pt.mean.size(); ++ch) {
        if (!std::isfinite(pt.mean[ch])) continue;
        if (static_cast<int>(ch) == e.index) res[k] -= m;
        ++k;
      }
    }
    return res;
  }
  const circuit_tools::LoadedCircuit a = with_effect(c, e, m);
  if (!ident::circuit_point_residuals(a, a.values.params, points, res)) return {};
  return res;
}

double rms_or_inf(const std::vector<double>& r) { return r.empty() ? std::numeric_limits<double>::infinity() : rms(r); }

// The magnitude a·reference minimising the fit RMS: a scan of log10 a over [−6, 1] by
// halves, then golden section between the best scan point's neighbours.
double fit_magnitude(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e,
                     const std::vector<ident::CircuitOperatingPoint>& points) {
  auto cost = [&](double lg) { return rms_or_inf(effect_residuals(c, e, e.reference * std::pow(10.0, lg), points)); };
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

circuit_tools::LoadedCircuit with_effect(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m) {
  circuit_tools::LoadedCircuit a = c;
  if (e.kind == CircuitEffect::Kind::kOffset) return a;
  host::HostCircuit& d = a.file.circuit;
  if (d.n_params >= host::CircuitCap::kParams || d.n_elements >= host::CircuitCap::kElements) return a;
  const int p = d.n_params++;
  circuit::Element el;
  switch (e.kind) {
    case CircuitEffect::Kind::kLeak: {
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
      el.kind = ElementKind::kLaminar;
      el.a = static_cast<std::uint8_t>(e.index);
      el.b = static_cast<std::uint8_t>(tank);
      el.r[circuit::kR] = circuit::param_ref(p);
      a.values.params.v[p] = 1.0 / m;
      a.file.params.push_back({"gap_leak_R", host::CircuitQuantity::kResistance, 1.0 / m, false, e.name});
      break;
    }
    case CircuitEffect::Kind::kFriction:
      el.kind = ElementKind::kFriction;
      el.shaft = static_cast<std::int8_t>(e.index);
      el.r[circuit::kC] = circuit::param_ref(p);
      a.values.params.v[p] = m;
      a.file.params.push_back({"gap_friction", host::CircuitQuantity::kDamping, m, false, e.name});
      break;
    case CircuitEffect::Kind::kTorqueLoss:
      el.kind = ElementKind::kTorque;
      el.shaft = static_cast<std::int8_t>(e.index);
      el.r[circuit::kTau] = circuit::param_ref(p);
      a.values.params.v[p] = m;
      a.file.params.push_back({"gap_torque", host::CircuitQuantity::kTorque, m, false, e.name});
      break;
    case CircuitEffect::Kind::kOffset:
      break;
  }
  d.elements[d.n_elements++] = el;
  a.file.elements.push_back(e.name);
  return a;
}

CircuitGapResult circuit_gap(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& fit,
                             const circuit_tools::CircuitLog& check) {
  CircuitGapResult r;
  const auto fit_pts = ident::circuit_operating_points(c, {fit}, 0.2);
  const auto check_pts = ident::circuit_operating_points(c, {check}, 0.2);
  r.fit_points = fit_pts.size();
  r.check_points = check_pts.size();
  if (fit_pts.empty() || check_pts.empty()) {
    r.error = "no steady operating point in the " + std::string(fit_pts.empty() ? "fit" : "check") +
              " log (held inputs for longer than 5 time constants + 0.2 s)";
    return r;
  }
  std::vector<double> base;
  if (!ident::circuit_point_residuals(c, c.values.params, fit_pts, base)) {
    r.error = "no steady state at some operating point of the fit log";
    return r;
  }
  r.rms_fit = rms(base);
  std::vector<double> base_check;
  (void)ident::circuit_point_residuals(c, c.values.params, check_pts, base_check);
  r.rms_check = rms_or_inf(base_check);
  // Where the gap lies: the mean residual of each channel over the fit log's points.
  const std::size_t channels = c.file.sensors.size();
  r.mean_fit.assign(channels, 0.0);
  std::vector<std::size_t> count(channels, 0);
  std::size_t k = 0;
  for (const auto& pt : fit_pts) {
    for (std::size_t ch = 0; ch < channels; ++ch) {
      if (!std::isfinite(pt.mean[ch])) continue;
      r.mean_fit[ch] += base[k++];
      ++count[ch];
    }
  }
  for (std::size_t ch = 0; ch < channels; ++ch) {
    r.channels.push_back(c.file.sensors[ch].name);
    r.mean_fit[ch] = count[ch] ? r.mean_fit[ch] / static_cast<double>(count[ch]) : std::nan("");
  }

  for (const CircuitEffect& e : circuit_effects(c)) {
    CircuitEffectResult er;
    er.effect = e;
    if (e.kind == CircuitEffect::Kind::kOffset) {
      er.magnitude = count[static_cast<std::size_t>(e.index)] ? r.mean_fit[static_cast<std::size_t>(e.index)] : 0.0;
    } else {
      er.magnitude = fit_magnitude(c, e, fit_pts);
    }
    er.rms_fit = rms_or_inf(effect_residuals(c, e, er.magnitude, fit_pts));
    er.rms_check = rms_or_inf(effect_residuals(c, e, er.magnitude, check_pts));
    er.ok = std::isfinite(er.rms_fit) && std::isfinite(er.rms_check);
    // An offset is reported in the channel's unit: reading = true + o, residual = −o/σ.
    if (e.kind == CircuitEffect::Kind::kOffset) {
      const auto& s = c.file.sensors[static_cast<std::size_t>(e.index)];
      er.magnitude = -er.magnitude * (s.noise > 0.0 ? s.noise : 1.0);
    }
    r.ranked.push_back(er);
  }
  std::stable_sort(r.ranked.begin(), r.ranked.end(), [](const CircuitEffectResult& a, const CircuitEffectResult& b) {
    return a.ok != b.ok ? a.ok : a.rms_check < b.rms_check;
  });
  // Verdict: no gap when the model already meets the fit log within 2σ of a sample;
  // an effect when it halves the check log's residual and leads the runner-up by 1.5×.
  if (r.rms_fit <= 2.0) {
    r.verdict = "none";
  } else if (!r.ranked.empty() && r.ranked[0].ok && r.ranked[0].rms_check <= 0.5 * r.rms_check) {
    const bool clear = r.ranked.size() < 2 || r.ranked[1].rms_check >= 1.5 * r.ranked[0].rms_check;
    r.verdict = clear ? r.ranked[0].effect.name : "ambiguous: " + r.ranked[0].effect.name + " or " + r.ranked[1].effect.name;
  } else {
    r.verdict = "unexplained";
  }
  return r;
}

}  // namespace hstmon::gap
