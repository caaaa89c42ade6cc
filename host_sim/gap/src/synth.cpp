/// @file synth.cpp
/// Synthetic truth logs (see synth.hpp).
#include "hstmon_gap/synth.hpp"

#include <cmath>
#include <random>

namespace hstmon::gap {

InputSeries staircase_profile(char profile, double duration, double rate, const ThesisInputs<double>& base) {
  // (kp factor, p_sup [bar]) per segment.
  static const double kA[][2] = {{1.0, 35}, {1.6, 35}, {0.7, 30}, {1.3, 40}, {0.55, 35}, {1.15, 28}, {0.85, 42}};
  static const double kB[][2] = {{0.8, 38}, {1.45, 32}, {0.6, 36}, {1.2, 30}, {0.95, 40}};
  const auto* seg = profile == 'B' ? kB : kA;
  const std::size_t nseg = profile == 'B' ? std::size(kB) : std::size(kA);
  InputSeries u;
  u.start = StartRule::kSteady;
  const auto n = static_cast<std::size_t>(std::floor(duration * rate)) + 1;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) / rate;
    const auto s = std::min(nseg - 1, static_cast<std::size_t>(t / duration * static_cast<double>(nseg)));
    u.t.push_back(t);
    u.kp.push_back(base.kp * seg[s][0]);
    u.Psupl.push_back(seg[s][1] * 1e5);
    u.Ps.push_back(base.Ps);
    u.Pbp.push_back(base.Pbp);
  }
  return u;
}

host::LogData synth_log(const ExtendedModel& truth, const InputSeries& u, const SynthNoise& noise, std::uint64_t seed,
                        const std::string& name) {
  host::LogData log;
  log.path = name;
  SimOptions so;
  so.max_step = 1e-4;
  const SimResult s = simulate(truth, u, so);
  if (!s.ok) {
    host::LogError e;
    e.message = "synthetic log: " + s.error;
    log.error = e;
    return log;
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  log.t = u.t;
  auto put = [&](host::Signal sig, std::vector<double> v) {
    log.values[host::index(sig)] = std::move(v);
    log.present[host::index(sig)] = true;
  };
  put(host::Signal::kPSup, u.Psupl);
  put(host::Signal::kKp, u.kp);
  put(host::Signal::kPBp, u.Pbp);
  log.present[host::index(host::Signal::kT)] = true;
  const host::Signal ch[kChannels] = {host::Signal::kPMi, host::Signal::kPMo, host::Signal::kPPp, host::Signal::kWm};
  for (int c = 0; c < kChannels; ++c) {
    std::vector<double> v(u.size());
    const double sd = c == 3 ? noise.speed : noise.pressure;
    for (std::size_t k = 0; k < u.size(); ++k) v[k] = s.y[k][static_cast<std::size_t>(c)] + sd * g(rng);
    put(ch[c], std::move(v));
  }
  return log;
}

}  // namespace hstmon::gap
