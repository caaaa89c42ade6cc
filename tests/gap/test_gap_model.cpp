// One model: gap's simulator runs lib's thesis equations — the hand-written
// ThesisReducedModel by default, the engine's ThesisCircuitModel on request. With no effect
// its rates and outputs are lib's to rounding, its open-loop run settles on lib's steady
// state, and with effects on, the two implementations give the same run to 1e-5 of scale.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon/thesis_reduced.hpp"
#include "hstmon_gap/effects.hpp"

namespace {

using namespace hstmon;
using Model = ThesisReducedModel<double>;

// Table 2.2's inputs (supply 35 bar, booster 10 bar) on rows k = 0..last at `dt` [s]
// apart, the PRV's kp [m3/(s*Pa^0.5)] of each row from kp(k).
template <class Kp>
gap::InputSeries table_2_2_inputs(int last, double dt, Kp kp) {
  gap::InputSeries u;
  for (int k = 0; k <= last; ++k) {
    u.t.push_back(dt * k);
    u.Psupl.push_back(35e5);
    u.Ps.push_back(0.0);
    u.Pbp.push_back(10e5);
    u.kp.push_back(kp(k));
  }
  return u;
}

TEST(GapModel, NominalRatesAreLibsToRounding) {
  gap::ExtendedModel nominal;
  for (double kf_factor : {1.0, 0.8}) {
    nominal.nominal.kf = ThesisParams<double>{}.kf * kf_factor;
    Model lib(nominal.nominal);
    for (double kp : {2.2e-8, 4.41e-8, 8.8e-8}) {
      for (double psup : {0.0, 28e5, 35e5, 42e5}) {
        ThesisInputs<double> u;
        u.kp = kp;
        u.Psupl = psup;
        lib.set_inputs(u);
        for (const auto& x : {Model::State(1e6, 0.0), Model::State(17e6, 175.0), Model::State(25e6, 120.0),
                              Model::State(3e6, -5.0)}) {
          Model::Output y_lib;
          const Model::State d_lib = lib.derivative(x, &y_lib);
          std::array<double, gap::kChannels> y{};
          const auto d = gap::extended_rates(nominal, u, {x[0], x[1]}, &y);
          EXPECT_DOUBLE_EQ(d[0], d_lib[0]);
          EXPECT_DOUBLE_EQ(d[1], d_lib[1]);
          for (int c = 0; c < gap::kChannels; ++c) EXPECT_DOUBLE_EQ(y[static_cast<std::size_t>(c)], y_lib[c]);
          // On the engine: its DCV solve converges to its tolerance, not to the last bit.
          const auto de = gap::extended_rates(nominal, u, {x[0], x[1]}, &y, gap::ThesisImpl::kEngine);
          EXPECT_NEAR(de[0], d_lib[0], 1e-9 * (std::fabs(d_lib[0]) + 1e14 * 1e-6 * (std::fabs(x[1]) + 1.0)));
          EXPECT_NEAR(de[1], d_lib[1], 1e-9 * (std::fabs(d_lib[1]) + 3.5e6 * 7.96e-6 / 1e-3));
          for (int c = 0; c < gap::kChannels; ++c) {
            EXPECT_NEAR(y[static_cast<std::size_t>(c)], y_lib[c], 1e-9 * (std::fabs(y_lib[c]) + (c < 3 ? 1e5 : 1.0)));
          }
        }
      }
    }
  }
}

TEST(GapModel, OpenLoopRunSettlesOnLibsSteadyState) {
  gap::ExtendedModel nominal;
  gap::InputSeries u = table_2_2_inputs(200, 0.005, [](int) { return 4.41e-8; });
  u.start = gap::StartRule::kRest;
  const gap::SimResult s = gap::simulate(nominal, u);
  ASSERT_TRUE(s.ok) << s.error;
  EXPECT_EQ(s.start, "rest");
  ThesisInputs<double> in;
  in.Pbp = 10e5;
  double y[4];
  ASSERT_TRUE(Model::steady_outputs(nominal.nominal, in, y));
  for (std::size_t c = 0; c < 4; ++c) EXPECT_NEAR(s.y.back()[c], y[c], 1e-9 * std::fabs(y[c]) + 1e-9) << c;
}

TEST(GapModel, StartsFromTheFirstSampleByLibsRule) {
  gap::ExtendedModel nominal;
  gap::InputSeries u = table_2_2_inputs(2, 0.001, [](int) { return 4.41e-8; });
  u.y0 = {0.0, 0.0, 10e5, 0.0};  // at rest: supply just switched on
  u.y0_valid = 0xF;
  gap::SimResult s = gap::simulate(nominal, u);
  ASSERT_TRUE(s.ok);
  EXPECT_EQ(s.start, "measured");
  EXPECT_DOUBLE_EQ(s.y[0][3], 0.0);
  u.y0_valid = 0;  // no states measured: rest
  s = gap::simulate(nominal, u);
  EXPECT_EQ(s.start, "rest");
}

TEST(GapModel, EngineAndSpecialisationRunAlike) {
  // Effects on every equation, a start from rest and a kp step: what a fit integrates.
  gap::ExtendedModel m;
  m.effects = {gap::default_effect(gap::Effect::kCoulombFriction), gap::default_effect(gap::Effect::kSupplyFlowLimit),
               gap::default_effect(gap::Effect::kPrvCracking), gap::default_effect(gap::Effect::kMotorLeakage)};
  gap::InputSeries u = table_2_2_inputs(400, 0.005, [](int k) { return k < 200 ? 4.41e-8 : 2.2e-8; });
  u.start = gap::StartRule::kRest;
  gap::SimOptions on_engine;
  on_engine.thesis = gap::ThesisImpl::kEngine;
  const gap::SimResult a = gap::simulate(m, u);
  const gap::SimResult b = gap::simulate(m, u, on_engine);
  ASSERT_TRUE(a.ok) << a.error;
  ASSERT_TRUE(b.ok) << b.error;
  double worst[gap::kChannels] = {};
  for (std::size_t k = 0; k < a.y.size(); ++k) {
    for (std::size_t c = 0; c < gap::kChannels; ++c) {
      const double scale = c < 3 ? 35e5 : 200.0;  // supply pressure; the speed's range [rad/s]
      worst[c] = std::fmax(worst[c], std::fabs(a.y[k][c] - b.y[k][c]) / scale);
    }
  }
  std::printf("gap simulate, engine vs specialisation: worst |difference| / scale %.2e %.2e %.2e %.2e\n", worst[0],
              worst[1], worst[2], worst[3]);
  // The engine's DCV solve converges to its tolerance, which the ROS2 step's finite-
  // difference Jacobian (step 1e-7 of the state) amplifies: measured 8e-7 of 35 bar on
  // Ppp (3 Pa, 1/1700 of the sensor noise σ), 2e-8 on the DCV pressures.
  for (double w : worst) EXPECT_LT(w, 1e-5);
}

}  // namespace
