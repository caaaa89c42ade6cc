// A host_sim log whose inputs (PRV settings) are logged, replayed with matching
// parameters: residuals are at the sensor noise level. A log whose fault is not logged
// (the PRV blockage) shows the thesis's signature in the residual means.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"
#include "hstmon_sim/log_layout.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace {

using hstmon::host::ReplayResult;

// Writes the scenario through the sensor chain to CSV text and reads it back: the same
// path a real log takes.
hstmon::host::LogData round_trip(const hstmon::sim::ThesisScenario& sc, const hstmon::sim::SensorConfig& sensors) {
  const auto ms = hstmon::sim::measure(sc, sensors, 7);
  std::ostringstream os;
  hstmon::sim::LogUnits units;
  units.speed = hstmon::sim::SpeedUnit::kRpm;
  hstmon::sim::write_log(os, ms, units);
  auto log = hstmon::host::read_log_from_memory(os.str(), "sim.csv", {});
  EXPECT_TRUE(log.ok()) << (log.error ? log.error->to_string() : "");
  return log;
}

ReplayResult run(const hstmon::host::LogData& log) {
  hstmon::host::ReplayOptions opt;
  opt.keep_trace = true;
  return hstmon::host::replay(log, {}, {}, opt);
}

// Mean and RMS of channel c over rows at least `settle` seconds after any setting change
// (the transducer lags make the transients themselves differ from the lag-free model).
std::pair<double, double> settled_stats(const ReplayResult& r, const std::vector<double>& changes, int c, double settle) {
  double s = 0, m = 0;
  std::size_t n = 0;
  for (const auto& row : r.trace) {
    bool near = false;
    for (double tc : changes) near |= (row.t >= tc && row.t < tc + settle);
    if (near || !std::isfinite(row.r[static_cast<std::size_t>(c)])) continue;
    m += row.r[static_cast<std::size_t>(c)];
    s += row.r[static_cast<std::size_t>(c)] * row.r[static_cast<std::size_t>(c)];
    ++n;
  }
  return {m / static_cast<double>(n), std::sqrt(s / static_cast<double>(n))};
}

TEST(ReplayNoise, LoggedSettingsGiveResidualsAtNoiseLevel) {
  const auto sc = hstmon::sim::thesis_prv_staircase(2.0);
  const auto sensors = hstmon::sim::thesis_fast_sensors(1000.0);
  const auto log = round_trip(sc, sensors);
  const auto r = run(log);
  ASSERT_EQ(r.rows, log.rows());
  EXPECT_EQ(r.health, 0u);
  std::vector<double> changes;
  for (const auto& step : sc.schedule) changes.push_back(step.t_start);
  for (int c = 0; c < 4; ++c) {
    const auto& spec = sensors.channels[static_cast<std::size_t>(c)];
    // Noise plus uniform quantisation error.
    const double sigma = std::sqrt(spec.noise_std * spec.noise_std + spec.quant_step * spec.quant_step / 12.0);
    const auto [mean, rms] = settled_stats(r, changes, c, 0.5);
    EXPECT_LT(rms, 1.2 * sigma) << "channel " << c;
    EXPECT_GT(rms, 0.8 * sigma) << "channel " << c;
    // Unbiased: 8000 settled samples give a standard error of σ/90.
    EXPECT_LT(std::fabs(mean), 0.1 * sigma) << "channel " << c;
  }
}

TEST(ReplayNoise, DasRateLogReplaysWithTicksBetweenSamples) {
  // The thesis DAS samples every 4 s: the observer ticks at 10 ms in between.
  const auto log = round_trip(hstmon::sim::thesis_prv_staircase(40.0), hstmon::sim::thesis_das_sensors());
  const auto r = run(log);
  EXPECT_NEAR(r.tick, 10e-3, 1e-12);
  EXPECT_EQ(r.ticks, static_cast<std::uint64_t>(std::lround((r.t_last - r.t_first) / r.tick)) + 1);
  for (int c = 0; c < 4; ++c) {
    // Steady samples only (4 s apart): residual within a few noise+quantisation sigmas.
    EXPECT_LT(r.channels[static_cast<std::size_t>(c)].rms(), c == 3 ? 2.0 : 0.1e5) << "channel " << c;
  }
}

TEST(ReplayNoise, UnloggedBlockageShowsThesisSignature) {
  const auto log = round_trip(hstmon::sim::thesis_prv_blockage(), hstmon::sim::thesis_fast_sensors(100.0));
  const auto r = run(log);
  ASSERT_NE(r.start, hstmon::InitialState::kRest) << "the log begins in operation";
  // Residual means after t = 80 s carry the kp− signature: Pmi+, Pmo−, Ppp+, ωm−.
  double mean[4] = {0, 0, 0, 0};
  std::size_t n = 0;
  for (const auto& row : r.trace) {
    if (row.t < 85.0) continue;
    for (int c = 0; c < 4; ++c) mean[c] += row.r[static_cast<std::size_t>(c)];
    ++n;
  }
  for (double& m : mean) m /= static_cast<double>(n);
  EXPECT_GT(mean[0], 1e5);    // Pmi up ≈ 1.25 bar
  EXPECT_LT(mean[1], -1e5);   // Pmo down ≈ 1.25 bar
  EXPECT_GT(mean[2], 50e5);   // Ppp up ≈ 56 bar
  EXPECT_LT(mean[3], -70.0);  // ωm down ≈ 74 rad/s
}

}  // namespace
