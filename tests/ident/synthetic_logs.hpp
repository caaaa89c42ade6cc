#pragma once
// Synthetic thesis logs for the identification tests: steady states of
// ThesisReducedModel<double> at the PRV staircase settings passed through the sensor
// chain's noise, clipping and quantisation (sim::SensorChain with settled lags), sampled
// like the thesis DAS. Generating steady samples directly replaces a full stiff simulation
// per seed (the lags and transients settle in < 0.1 s, far below the 4 s DAS period).
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "hstmon/thesis_reduced.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::ident::testing {

// Log of `per_setting` DAS samples (period cfg.sample_period) at each kp factor, with the
// input columns p_sup, p_s, p_bp and kp (the logged setting).
inline host::LogData steady_staircase_log(std::uint64_t seed, const ThesisParams<double>& p = {},
                                          std::size_t per_setting = 10,
                                          const sim::SensorConfig& cfg = sim::thesis_das_sensors(),
                                          const std::vector<double>& factors = {1.6, 1.3, 1.0, 0.8, 0.65, 0.5}) {
  using host::Signal;
  host::LogData log;
  log.path = "synthetic-seed-" + std::to_string(seed) + ".csv";
  for (Signal s : {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp, Signal::kPMi, Signal::kPMo, Signal::kPPp,
                   Signal::kWm}) {
    log.present[host::index(s)] = true;
  }
  sim::SensorChain chain(cfg.channels, seed);
  double t = 0.0;
  for (double f : factors) {
    ThesisInputs<double> u;
    u.kp = f * sim::kThesisKpNominal;
    ThesisReducedModel<double> m(p);
    m.set_inputs(u);
    ThesisReducedModel<double>::State x;
    if (!m.steady_state(x)) continue;
    const auto y = m.outputs(x);
    const double truth[4] = {y[0], y[1], y[2], y[3]};
    chain.reset(truth);
    for (std::size_t k = 0; k < per_setting; ++k) {
      double out[4];
      chain.measure(out);
      log.t.push_back(t);
      t += cfg.sample_period;
      log.values[host::index(Signal::kPSup)].push_back(u.Psupl);
      log.values[host::index(Signal::kPS)].push_back(u.Ps);
      log.values[host::index(Signal::kPBp)].push_back(u.Pbp);
      log.values[host::index(Signal::kKp)].push_back(u.kp);
      log.values[host::index(Signal::kPMi)].push_back(out[0]);
      log.values[host::index(Signal::kPMo)].push_back(out[1]);
      log.values[host::index(Signal::kPPp)].push_back(out[2]);
      log.values[host::index(Signal::kWm)].push_back(out[3]);
    }
  }
  return log;
}

// The log as thesis CSV text (pressures in bar, speed in rad/s, kp in SI), as a rig writes it.
inline std::string thesis_log_csv(const host::LogData& log) {
  using host::Signal;
  std::ostringstream f;
  f.precision(10);
  f << "t[s],p_sup[bar],p_s[bar],p_bp[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rad/s]\n";
  const Signal cols[] = {Signal::kPSup, Signal::kPS,  Signal::kPBp, Signal::kKp,
                         Signal::kPMi,  Signal::kPMo, Signal::kPPp, Signal::kWm};
  for (std::size_t i = 0; i < log.rows(); ++i) {
    f << log.t[i];
    for (Signal s : cols) {
      const double v = log.column(s)[i];
      f << ',' << (s == Signal::kKp || s == Signal::kWm ? v : v * 1e-5);
    }
    f << '\n';
  }
  return f.str();
}

}  // namespace hstmon::ident::testing
