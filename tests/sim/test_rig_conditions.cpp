// Rig conditions of the sensor chain and scenario generator, each switchable alone:
// load shapes, start from rest with a delayed supply, start/stop cycles, NE 43 output
// band, loop break, input faults over a schedule, parameter error, rig_fast preset.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon_sim/machine_error.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/param_fault.hpp"
#include "hstmon_sim/rig_run.hpp"

namespace hstmon::sim {
namespace {

constexpr double kKp0 = kThesisKpNominal;

TEST(LoadProfile, StepsHoldThenJumpWithinRange) {
  LoadProfile p;
  p.shape = LoadShape::kSteps;
  p.period = 2.0;
  const auto s = load_setpoints(p, kKp0, 11.0);
  ASSERT_EQ(s.size(), 6u);  // 0, 2, 4, 6, 8, 10
  EXPECT_EQ(s[0].first, 0.0);
  EXPECT_EQ(s[0].second, kKp0);
  for (std::size_t k = 1; k < s.size(); ++k) {
    EXPECT_DOUBLE_EQ(s[k].first, 2.0 * static_cast<double>(k));
    EXPECT_GE(s[k].second, 0.65 * kKp0);
    EXPECT_LE(s[k].second, 1.6 * kKp0);
  }
}

TEST(LoadProfile, RampAndSineStayInRangeAndMoveByUpdates) {
  for (LoadShape shape : {LoadShape::kRamp, LoadShape::kSine}) {
    LoadProfile p;
    p.shape = shape;
    p.period = 5.0;
    p.update = 0.1;
    const auto s = load_setpoints(p, kKp0, 20.0);
    EXPECT_GT(s.size(), 150u) << to_string(shape);
    double lo = 1e9, hi = 0;
    for (std::size_t k = 1; k < s.size(); ++k) {
      EXPECT_GT(s[k].first, s[k - 1].first);
      EXPECT_LT(std::fabs(s[k].second - s[k - 1].second), 0.1 * kKp0) << "a ramp, not a step";
      lo = std::fmin(lo, s[k].second);
      hi = std::fmax(hi, s[k].second);
    }
    EXPECT_NEAR(lo / kKp0, 0.65, 0.02) << to_string(shape);
    EXPECT_NEAR(hi / kKp0, 1.6, 0.02) << to_string(shape);
  }
}

TEST(RigRun, LoggerBeforeSupplyThenStartStopCycles) {
  RigRun r;
  r.duration = 10.0;
  r.supply_on = 0.5;
  r.run_time = 3.0;
  r.stop_time = 2.0;
  const ThesisScenario sc = thesis_rig_run(r);
  EXPECT_EQ(sc.initial, InitialCondition::kRest);
  // Off until 0.5, on to 3.5, off to 5.5, on to 8.5, off.
  const double on = ThesisInputs<double>{}.Psupl;
  EXPECT_EQ(inputs_at(sc, 0.0).Psupl, 0.0);
  EXPECT_EQ(inputs_at(sc, 0.5).Psupl, on);
  EXPECT_EQ(inputs_at(sc, 3.4).Psupl, on);
  EXPECT_EQ(inputs_at(sc, 3.5).Psupl, 0.0);
  EXPECT_EQ(inputs_at(sc, 5.5).Psupl, on);
  EXPECT_EQ(inputs_at(sc, 8.6).Psupl, 0.0);
  // The machine comes to rest while the supply is off, and runs again after.
  const auto log = measure(sc, ideal_sensors(rig_fast_sensors(100.0)), 1);
  auto at = [&](double t) { return log.at(static_cast<std::size_t>(std::lround(t * 100.0))).y; };
  EXPECT_NEAR(at(0.4)[3], 0.0, 1e-9);
  EXPECT_GT(at(3.0)[3], 100.0);
  EXPECT_LT(std::fabs(at(5.4)[3]), 1.0) << "coasted down";
  EXPECT_GT(at(8.0)[3], 100.0);
  EXPECT_EQ(log.at(10).u.Psupl, 0.0) << "the log records the supply as switched";
}

TEST(RigRun, RigFastFirstSampleAtRestThenSupply) {
  RigRun r;
  r.duration = 0.01;
  const auto log = measure(thesis_rig_run(r), rig_fast_sensors(1000.0), 3);
  EXPECT_LT(std::fabs(log[0].y[0]), 0.2e5);       // Pmi ≈ 0 bar, noise not clipped at 0
  EXPECT_NEAR(log[0].y[2], 10e5, 0.2e5);          // Ppp at the booster
  EXPECT_NEAR(log[1].y[0], 35e5, 0.5e5);          // supply on at t = 0: Pmi follows at once
  EXPECT_GT(log[1].y[3], 10.0);                   // the shaft starts
}

TEST(SensorChainBand, Ne43BandAndLoopBreakLevel) {
  ChannelSpec c;
  c.range_lo = 0.0;
  c.range_hi = 200e5;
  c.under_range = kNe43Under;
  c.over_range = kNe43Over;
  EXPECT_DOUBLE_EQ(clip_and_quantise(-1e5, c), -1e5);  // inside the band
  EXPECT_DOUBLE_EQ(clip_and_quantise(-10e5, c), -2.5e5);
  EXPECT_DOUBLE_EQ(clip_and_quantise(300e5, c), 206.25e5);
  SensorConfig cfg = rig_fast_sensors(100.0);
  ThesisMeasurements ms(3);
  for (std::size_t k = 0; k < ms.size(); ++k) {
    ms[k].t = static_cast<double>(k);
    ms[k].y = {30e5, 2e5, 170e5, 170.0};
  }
  SensorFault f;
  f.channel = 0;
  f.kind = SensorFaultKind::kLoopBreak;
  f.t_start = 1.0;
  inject_sensor_fault(ms, cfg, f);
  EXPECT_EQ(ms[0].y[0], 30e5);
  EXPECT_DOUBLE_EQ(ms[2].y[0], -5e5);  // 3.6 mA on 0–200 bar
}

TEST(InputFault, ScalesTheTruthFromTheFaultOnLogKeepsSettings) {
  RigRun r;
  r.duration = 10.0;
  r.load.shape = LoadShape::kSteps;
  const ThesisScenario sc = thesis_rig_run(r);
  const ThesisScenario f = with_input_fault(sc, &ThesisInputs<double>::kp, 0.5, 3.0);
  EXPECT_EQ(inputs_at(f, 2.9).kp, inputs_at(sc, 2.9).kp);
  EXPECT_DOUBLE_EQ(inputs_at(f, 3.0).kp, 0.5 * inputs_at(sc, 3.0).kp);
  EXPECT_DOUBLE_EQ(inputs_at(f, 9.0).kp, 0.5 * inputs_at(sc, 9.0).kp);
  EXPECT_EQ(logged_inputs_at(f, 9.0).kp, inputs_at(sc, 9.0).kp);
}

TEST(MachineError, SeededWithinSpreadAndZeroIsTable) {
  const ThesisParams<double> t, a = perturbed_params(5, 0.02), b = perturbed_params(5, 0.02);
  EXPECT_EQ(a.Dm, b.Dm);
  EXPECT_NE(a.Dm, t.Dm);
  EXPECT_LE(std::fabs(a.Rbl / t.Rbl - 1.0), 0.02);
  EXPECT_EQ(perturbed_params(5, 0.0).Dm, t.Dm);
}

}  // namespace
}  // namespace hstmon::sim
