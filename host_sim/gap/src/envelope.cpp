/// @file envelope.cpp
/// Operating-point envelope of the model (see envelope.hpp, docs/gap.md).
#include "hstmon_gap/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace hstmon::gap {

namespace {

constexpr double kParamUncertainty = 0.05;  // ±5 % on parameters and logged inputs
constexpr double kMinDuration = 0.2;        // a setting shorter than this (after settling) is not steady [s]

using Y = std::array<double, kChannels>;

// Steady outputs of `m` under inputs `in` (simulate's steady start: nominal steady state,
// then a preroll with the effects).
std::optional<Y> steady(const ExtendedModel& m, const ThesisInputs<double>& in, ThesisImpl thesis) {
  InputSeries u;
  u.t = {0.0, 1e-3};
  u.Psupl = {in.Psupl, in.Psupl};
  u.Ps = {in.Ps, in.Ps};
  u.Pbp = {in.Pbp, in.Pbp};
  u.kp = {in.kp, in.kp};
  u.start = StartRule::kSteady;
  SimOptions o;
  o.preroll = 0.5;
  o.thesis = thesis;
  const SimResult r = simulate(m, u, o);
  if (!r.ok) return std::nullopt;
  return r.y[0];
}

ActiveEffect effect(Effect id, std::vector<double> v) {
  ActiveEffect a;
  a.id = id;
  a.values = std::move(v);
  return a;
}

// Shifts of the steady outputs, lower and upper sums over every perturbation.
void envelope_at(const ExtendedModel& nominal, const ThesisInputs<double>& in, const Y& y0, Y& lo, Y& hi,
                 ThesisImpl thesis) {
  lo.fill(0.0);
  hi.fill(0.0);
  auto add = [&](const ExtendedModel& m, const ThesisInputs<double>& u) {
    const auto y = steady(m, u, thesis);
    if (!y) return;
    for (std::size_t c = 0; c < kChannels; ++c) {
      const double d = (*y)[c] - y0[c];
      if (!std::isfinite(d)) continue;
      lo[c] += std::min(0.0, d);
      hi[c] += std::max(0.0, d);
    }
  };
  for (double s : {-1.0, 1.0}) {
    const double f = 1.0 + s * kParamUncertainty;
    for (int k = 0; k < 4; ++k) {
      ExtendedModel m = nominal;
      if (k == 0) m.nominal.Dm *= f;
      if (k == 1) m.nominal.Dp *= f;
      if (k == 2) m.nominal.kf *= f;
      if (k == 3) {
        m.nominal.Rf *= f;
        m.nominal.Rbl *= f;
      }
      add(m, in);
    }
    ThesisInputs<double> u = in;
    u.kp *= f;
    add(nominal, u);
    u = in;
    u.Psupl *= f;
    add(nominal, u);
  }
  // Library effects at the largest size a working rig plausibly shows.
  const double w = std::fabs(y0[3]);
  const double dPs = std::fabs(in.Psupl - in.Ps);
  const double flow = nominal.nominal.Dm * w;
  const double g = dPs > 0 ? 0.15 * flow / dPs : 0.0;  // each leakage path: 15 % of the motor flow
  std::vector<ActiveEffect> big = {
      effect(Effect::kCoulombFriction, {0.2 * nominal.nominal.Dm * dPs}),  // 20 % of the stall torque
      effect(Effect::kPressureTorqueLoss, {0.2}),                          // mechanical efficiency 80 %
      effect(Effect::kMotorLeakage, {g, g}),
      effect(Effect::kPrvCracking, {0.3 * std::max(0.0, y0[2] - in.Pbp)}),
      effect(Effect::kSupplyFlowLimit, {0.6 * flow, 0.2 * std::max(in.Psupl, 1e5)}),
  };
  for (const auto& a : big) {
    ExtendedModel m = nominal;
    m.effects = {a};
    add(m, in);
  }
}

// Sensor offset a channel may plausibly carry: `share` of the reading, at least `p_min`
// [Pa] for a pressure or `rpm_min` for the speed.
double offset_allowance(std::size_t c, double reading, double share, double p_min, double rpm_min) {
  return std::max(share * std::fabs(reading), c == 3 ? rpm_min * 2.0 * M_PI / 60.0 : p_min);
}

}  // namespace

void add_envelope_segments(Envelope& env, const ExtendedModel& nominal, const InputSeries& u,
                           const std::vector<std::array<double, kChannels>>& y,
                           const std::vector<std::array<double, kChannels>>& model_y,
                           const std::array<bool, kChannels>& present, const std::array<double, kChannels>& noise,
                           double settle, ThesisImpl thesis) {
  const std::size_t n = u.size();
  std::size_t a = 0;
  while (a < n) {
    std::size_t b = a + 1;
    while (b < n && u.kp[b] == u.kp[a] && u.Psupl[b] == u.Psupl[a] && u.Ps[b] == u.Ps[a] && u.Pbp[b] == u.Pbp[a]) ++b;
    // Rows [a, b): one setting. Average its second half, after the settling time.
    const double t_start = std::max(u.t[a] + settle, 0.5 * (u.t[a] + u.t[b - 1]));
    EnvelopeSegment s;
    std::size_t cnt = 0;
    for (std::size_t k = a; k < b; ++k) {
      if (u.t[k] < t_start || k == 0) continue;
      if (cnt == 0) s.t0 = u.t[k];
      s.t1 = u.t[k];
      for (std::size_t c = 0; c < kChannels; ++c) {
        s.measured[c] += y[k][c];
        s.model[c] += model_y[k][c];
      }
      ++cnt;
    }
    if (cnt > 0 && u.t[b - 1] - u.t[a] >= settle + kMinDuration) {
      for (std::size_t c = 0; c < kChannels; ++c) {
        s.measured[c] /= static_cast<double>(cnt);
        s.model[c] /= static_cast<double>(cnt);
      }
      ThesisInputs<double> in;
      in.Psupl = u.Psupl[a];
      in.Ps = u.Ps[a];
      in.Pbp = u.Pbp[a];
      in.kp = u.kp[a];
      s.Psupl = in.Psupl;
      s.kp = in.kp;
      const auto y0 = steady(nominal, in, thesis);
      if (y0) {
        envelope_at(nominal, in, *y0, s.lo, s.hi, thesis);
        // Outside when two channels are, with sensor offsets of 2 % of the reading (at
        // least 0.5 bar / 20 rpm): the operating point is Ppp, ωm and the pressures together.
        // One channel alone is outside only beyond what a sensor could be off by — 15 % of
        // the reading, at least 12.5 bar / 150 rpm (5 % of a 250 bar or 3000 rpm range):
        // a single channel off is a sensor's matter, for the effect fits to judge.
        int n_out = 0;
        bool one_far = false;
        for (std::size_t c = 0; c < kChannels; ++c) {
          if (!present[c]) continue;
          s.margin[c] = 3.0 * noise[c] + 0.01 * std::fabs(s.model[c]);
          const double small = offset_allowance(c, (*y0)[c], 0.02, 0.5e5, 20.0);
          const double big = offset_allowance(c, (*y0)[c], 0.15, 12.5e5, 150.0);
          s.lo[c] -= small;
          s.hi[c] += small;
          const double d = s.measured[c] - s.model[c];
          const double out = std::max(s.lo[c] - s.margin[c] - d, d - s.hi[c] - s.margin[c]);
          if (out > 0) ++n_out;
          if (out > big - small) one_far = true;
          const double ex = out / (s.hi[c] - s.lo[c] + s.margin[c]);
          if (out > 0 && ex > s.excess) {
            s.excess = ex;
            s.worst_channel = static_cast<int>(c);
          }
        }
        s.outside = n_out >= 2 || one_far;
        env.segments.push_back(s);
      }
    }
    a = b;
  }
}

void finish_envelope(Envelope& env) {
  env.outside = 0;
  const EnvelopeSegment* worst = nullptr;
  for (const auto& s : env.segments) {
    if (!s.outside) continue;
    ++env.outside;
    if (worst == nullptr || s.excess > worst->excess) worst = &s;
  }
  env.out = !env.segments.empty() && 2 * env.outside >= static_cast<int>(env.segments.size());
  if (worst == nullptr) {
    env.text = "every steady setting lies within what parameter uncertainty and the library's effects can reach";
    return;
  }
  const double rpm = 60.0 / (2.0 * M_PI);
  char b[600];
  std::snprintf(b, sizeof b,
                "%d of %zu steady settings lie outside what +-5 %% parameter error and every library effect together "
                "could reach; worst at p_sup = %.4g bar, kp = %.4g: the machine runs at Pmi %.4g, Pmo %.4g, Ppp %.4g "
                "bar, %.0f rpm where the model predicts %.4g, %.4g, %.4g bar, %.0f rpm",
                env.outside, env.segments.size(), worst->Psupl * 1e-5, worst->kp, worst->measured[0] * 1e-5,
                worst->measured[1] * 1e-5, worst->measured[2] * 1e-5, worst->measured[3] * rpm, worst->model[0] * 1e-5,
                worst->model[1] * 1e-5, worst->model[2] * 1e-5, worst->model[3] * rpm);
  env.text = b;
}

}  // namespace hstmon::gap
