// measure(): sample times of the presets, sensor effects on a simulated run, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/simulate.hpp"

namespace hstmon::sim {
namespace {

TEST(Measure, ThesisDasSampleTimes) {
  const ThesisMeasurements ms = measure(thesis_prv_blockage(), thesis_das_sensors(), 1);
  ASSERT_EQ(ms.size(), 31u);  // 0, 4, …, 120 s
  for (std::size_t k = 0; k < ms.size(); ++k) EXPECT_EQ(ms[k].t, 4.0 * static_cast<double>(k));
  // The blockage is a fault, not a setting: the log keeps the nominal kp, while the
  // measurements show the fault (Ppp up from 80 s).
  EXPECT_EQ(ms[19].u.kp, 4.41e-8);  // 76 s
  EXPECT_EQ(ms[20].u.kp, 4.41e-8);  // 80 s
  EXPECT_GT(ms[21].y[2], ms[19].y[2] + 40e5);
}

TEST(Measure, SettingChangesAreLogged) {
  auto sc = thesis_prv_blockage();
  sc.logged.clear();  // log the true inputs
  const ThesisMeasurements ms = measure(sc, thesis_das_sensors(), 1);
  EXPECT_EQ(ms[20].u.kp, 0.5 * 4.41e-8);
}

TEST(Measure, FastSampleTimesAreExactMultiples) {
  const ThesisMeasurements ms = measure(thesis_start_from_rest(0.5), thesis_fast_sensors(1000.0), 3);
  ASSERT_EQ(ms.size(), 501u);
  for (std::size_t k = 0; k < ms.size(); ++k) EXPECT_EQ(ms[k].t, static_cast<double>(k) * 1e-3);
}

TEST(Measure, NoiseFreeSamplesAreTheQuantisedTruthAtSteadyState) {
  const SensorConfig cfg = without_noise(thesis_das_sensors());
  const ThesisMeasurements ms = measure(thesis_prv_blockage(), cfg, 1);
  const ThesisState<double> before = thesis_steady_state(ThesisInputs<double>{});
  ThesisInputs<double> blocked;
  blocked.kp *= 0.5;
  const ThesisState<double> after = thesis_steady_state(blocked);
  const double b[4] = {before.Pmi, before.Pmo, before.Ppp, before.w_m};
  const double a[4] = {after.Pmi, after.Pmo, after.Ppp, after.w_m};
  for (int i = 0; i < 4; ++i) {
    const double half = 0.5 * cfg.channels[static_cast<std::size_t>(i)].quant_step;
    EXPECT_NEAR(ms[10].y[static_cast<std::size_t>(i)], b[i], half * (1 + 1e-9)) << i;   // 40 s
    EXPECT_NEAR(ms[30].y[static_cast<std::size_t>(i)], a[i], half * (1 + 1e-9)) << i;   // 120 s
  }
  EXPECT_NEAR(ms[30].y[3] / kRadPerSecPerRpm, 973.0, 0.5);  // 101.91 rad/s
}

TEST(Measure, IdealSensorsReproduceTheReference) {
  const ThesisScenario sc = thesis_start_from_rest(0.05);
  const ThesisMeasurements ms = measure(sc, ideal_sensors(thesis_fast_sensors(1000.0)), 1);
  const ThesisTrajectory tr = simulate(sc, uniform_times(sc.duration, 1e-3));
  ASSERT_EQ(ms.size(), tr.size());
  for (std::size_t k = 0; k < ms.size(); ++k) {
    EXPECT_EQ(ms[k].t, tr[k].t);
    EXPECT_EQ(ms[k].y[0], tr[k].x.Pmi);
    EXPECT_EQ(ms[k].y[3], tr[k].x.w_m);
  }
}

TEST(Measure, LagDelaysTheStartTransient) {
  // The 10 ms speed lag holds the measured speed below the true one while ωm rises.
  const ThesisScenario sc = thesis_start_from_rest(0.05);
  SensorConfig cfg = ideal_sensors(thesis_fast_sensors(1000.0));
  cfg.channels[3].tau = 10e-3;
  const ThesisMeasurements ms = measure(sc, cfg, 1);
  const ThesisTrajectory tr = simulate(sc, uniform_times(sc.duration, 1e-3));
  EXPECT_LT(ms[5].y[3], 0.8 * tr[5].x.w_m);
  EXPECT_GT(ms[5].y[3], 0.0);
}

TEST(Measure, DeterministicBySeedAndNoiseFreeIsSeedFree) {
  const ThesisScenario sc = thesis_start_from_rest(0.2);
  const SensorConfig cfg = thesis_fast_sensors(200.0);
  auto ys = [&](const SensorConfig& c, std::uint64_t seed) {
    std::vector<double> v;
    for (const auto& m : measure(sc, c, seed)) v.insert(v.end(), m.y.begin(), m.y.end());
    return v;
  };
  EXPECT_EQ(ys(cfg, 5), ys(cfg, 5));
  EXPECT_NE(ys(cfg, 5), ys(cfg, 6));
  EXPECT_EQ(ys(without_noise(cfg), 5), ys(without_noise(cfg), 6));
}

TEST(Measure, PaperLoggerEvery2ms) {
  const PaperMeasurements ms = measure(paper_start(0.1), paper_logger_sensors(), 1);
  ASSERT_EQ(ms.size(), 51u);
  EXPECT_NEAR(ms.back().t, 0.1, 1e-15);
  EXPECT_EQ(ms[0].u.A_dcv, 5e-6);
  EXPECT_EQ(ms[0].u.A_prv, 3.525e-6);
}

}  // namespace
}  // namespace hstmon::sim
