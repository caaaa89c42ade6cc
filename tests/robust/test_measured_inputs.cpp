// Measured inputs. A log's input columns are settings on the thesis rig (the PRV's kp,
// the supply's set point), but a test stand logs its drive speed, and a plant may log its
// supply pressure: measured, so every row differs by the transducer's noise. The monitor
// must treat that as one operating point — no alarm, the same diagnosis as with clean
// inputs, and its model bound (about 20 steady solves) not recomputed every tick — while
// a real input step still moves the bound (Config::input_tolerance, input_change.hpp).
// The same holds for a tank pressure measured around 0: the thesis rig's pressures share
// one scale, the largest of them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/input_change.hpp"
#include "hstmon/monitor.hpp"

namespace {

using Mon = hstmon::Monitor<double>;
using Model = Mon::Model;
using Inputs = hstmon::ThesisInputs<double>;

constexpr double kTick = 1e-3;       // [s]
constexpr double kSigmaP = 5e3;      // pressure transducer noise, 0.05 bar [Pa]
constexpr double kSigmaW = 0.05236;  // speed pick-up noise, 0.5 rpm [rad/s]

TEST(InputChange, WithinTolerance) {
  Inputs a, b;
  EXPECT_TRUE(hstmon::inputs_close(a, a, 0.0));
  b.kp *= 1.009;
  EXPECT_TRUE(hstmon::inputs_close(a, b, 0.01));
  b.kp = a.kp * 1.011;
  EXPECT_FALSE(hstmon::inputs_close(a, b, 0.01));
  EXPECT_FALSE(hstmon::inputs_close(a, b, 0.0));  // 0: any change counts
  b = a;
  b.Ps = 3e4;  // a tank pressure 0.3 bar off 0: 0.9 % of the supply's 35 bar
  EXPECT_TRUE(hstmon::inputs_close(a, b, 0.01));
  b.Ps = 4e4;
  EXPECT_FALSE(hstmon::inputs_close(a, b, 0.01));
  b = a;
  b.Psupl = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(hstmon::inputs_close(a, b, 0.01));
}

/// The thesis monitor at Table 2.2's steady state for 2·t_fault at 1 kHz, its supply
/// pressure logged with sigma_supply [Pa] of noise, the PRV half blocked at t_fault [s]
/// (0.2 s first-order approach).
struct Outcome {
  double detected = -1.0, isolated = -1.0;
  std::string first;
  int alarms_before = 0;      ///< detections before the blockage
  int bound_changes = 0;      ///< ticks after the first on which model_bound() changed
};

Outcome run(double sigma_supply, double tolerance, double t_fault = 30.0, double sigma_tank = 0.0) {
  static Mon mon;
  Mon::Config c;
  c.observer.tick = kTick;
  c.input_tolerance = tolerance;
  EXPECT_EQ(mon.configure({}, c, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount), hstmon::Status::kOk);
  const Inputs u;
  Inputs blocked = u;
  blocked.kp *= 0.5;
  Model::State x0, x1;
  Model m0({}, u), m1({}, blocked);
  EXPECT_TRUE(m0.steady_state(x0) && m1.steady_state(x1));
  const Model::Output y0 = m0.outputs(x0), y1 = m1.outputs(x1);
  EXPECT_EQ(mon.reset_steady(u), hstmon::Status::kOk);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n;
  Outcome r;
  double bound[4] = {};
  const int ticks = static_cast<int>(2.0 * t_fault / kTick);
  for (int k = 0; k < ticks; ++k) {
    const double t = k * kTick;
    const double a = t < t_fault ? 0.0 : 1.0 - std::exp(-(t - t_fault) / 0.2);
    Mon::Measurement s;
    s.valid = 0x0F;
    for (int i = 0; i < 4; ++i) s.y[i] = y0[i] + a * (y1[i] - y0[i]) + (i == 3 ? kSigmaW : kSigmaP) * n(rng);
    Inputs logged = u;
    logged.Psupl += sigma_supply * n(rng);
    logged.Ps += sigma_tank * n(rng);
    mon.step(t, logged, s);
    bool changed = false;
    for (int i = 0; i < 4; ++i) {
      changed = changed || mon.model_bound()[i] != bound[i];
      bound[i] = mon.model_bound()[i];
    }
    if (changed && k > 0) ++r.bound_changes;
    Mon::Event e;
    while (mon.pop_event(e)) {
      if (e.kind == hstmon::MatchEventKind::kDetected) {
        if (e.time < t_fault) ++r.alarms_before;
        if (r.detected < 0 && e.time >= t_fault) r.detected = e.time;
      }
      if (e.kind == hstmon::MatchEventKind::kIsolated && r.isolated < 0 && e.time >= t_fault) {
        r.isolated = e.time;
        r.first = e.count > 0 ? e.candidate[0].name : "";
      }
    }
  }
  return r;
}

TEST(MeasuredInputs, NoisySupplyIsOneOperatingPoint) {
  const Outcome clean = run(0.0, 0.01);
  // The supply and the tank logged by 0.05 bar transducers: 0.14 % of 35 bar each.
  const Outcome noisy = run(kSigmaP, 0.01, 30.0, kSigmaP);
  std::printf("clean: detected %.3f s, isolated %.3f s (%s), %d bound changes\n", clean.detected, clean.isolated,
              clean.first.c_str(), clean.bound_changes);
  std::printf("noisy supply: detected %.3f s, isolated %.3f s (%s), %d bound changes\n", noisy.detected,
              noisy.isolated, noisy.first.c_str(), noisy.bound_changes);
  EXPECT_EQ(clean.alarms_before, 0);
  EXPECT_EQ(noisy.alarms_before, 0);
  EXPECT_EQ(clean.first, "kp-");
  EXPECT_EQ(noisy.first, "kp-");
  // The noise moves the model a little (Psupl drives the DCV), so the matcher's
  // statistics differ by the noise; not its timing beyond a few samples.
  EXPECT_NEAR(noisy.detected, clean.detected, 0.02);
  EXPECT_NEAR(noisy.isolated, clean.isolated, 0.05);
  EXPECT_EQ(noisy.bound_changes, 0) << "the bound was recomputed for input noise";
}

TEST(MeasuredInputs, ExactComparisonRecomputesEveryTick) {
  // input_tolerance = 0 is the old behaviour: every row an input change, a bound each.
  const Outcome noisy = run(kSigmaP, 0.0, 1.0);
  EXPECT_GT(noisy.bound_changes, 1900);
}

TEST(MeasuredInputs, AnInputStepMovesTheBound) {
  Mon mon;
  Mon::Config c;
  c.observer.tick = kTick;
  ASSERT_EQ(mon.configure({}, c, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount), hstmon::Status::kOk);
  Inputs u;
  ASSERT_EQ(mon.reset_steady(u), hstmon::Status::kOk);
  const Mon::Measurement none{};
  mon.step(0.0, u, none);
  const double before = mon.model_bound()[hstmon::kChPpp];
  u.Psupl *= 1.006;  // inside the tolerance (1 %): the bound stays
  mon.step(kTick, u, none);
  EXPECT_EQ(mon.model_bound()[hstmon::kChPpp], before);
  u.Psupl *= 1.006;  // 1.2 % from the bound's inputs: recomputed
  mon.step(2 * kTick, u, none);
  EXPECT_NE(mon.model_bound()[hstmon::kChPpp], before);
  const double after = mon.model_bound()[hstmon::kChPpp];
  u.kp *= 1.3;  // a load step
  mon.step(3 * kTick, u, none);
  EXPECT_GT(std::fabs(mon.model_bound()[hstmon::kChPpp] - after), 1e-3 * after);
}

}  // namespace
