// One model: gap's simulator runs lib's ThesisReducedModel. With no effect its rates and
// outputs are lib's to rounding, and its open-loop run settles on lib's steady state.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon/thesis_reduced.hpp"
#include "hstmon_gap/effects.hpp"

namespace {

using namespace hstmon;
using Model = ThesisReducedModel<double>;

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
        }
      }
    }
  }
}

TEST(GapModel, OpenLoopRunSettlesOnLibsSteadyState) {
  gap::ExtendedModel nominal;
  gap::InputSeries u;
  for (int k = 0; k <= 200; ++k) {
    u.t.push_back(0.005 * k);
    u.Psupl.push_back(35e5);
    u.Ps.push_back(0.0);
    u.Pbp.push_back(10e5);
    u.kp.push_back(4.41e-8);
  }
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
  gap::InputSeries u;
  for (int k = 0; k < 3; ++k) {
    u.t.push_back(0.001 * k);
    u.Psupl.push_back(35e5);
    u.Ps.push_back(0.0);
    u.Pbp.push_back(10e5);
    u.kp.push_back(4.41e-8);
  }
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

}  // namespace
