// Observer behaviour that needs no reference simulator: convergence to the true steady
// state at 1 ms and 10 ms (which a false fixed point of an unstable step would miss),
// residuals, masks, injection, and health flags on bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hstmon/hstmon.hpp"
#include "newton_reference.hpp"

namespace {

template <typename T>
using Obs = hstmon::Observer<hstmon::ThesisReducedModel<T>>;

template <typename T>
Obs<T> make_observer(T tick) {
  Obs<T> o;
  typename Obs<T>::Config c;
  c.tick = tick;
  EXPECT_EQ(o.configure(hstmon::ThesisReducedModel<T>{}, c), hstmon::Status::kOk);
  return o;
}

template <typename T>
void expect_true_fixed_point(T tick, long double kp_scale) {
  Obs<T> o = make_observer<T>(tick);
  hstmon::ThesisInputs<T> u;
  u.kp = static_cast<T>(u.kp * static_cast<T>(kp_scale));
  ASSERT_EQ(o.reset_rest(u), hstmon::Status::kOk);
  typename Obs<T>::Measurement none;
  const int n = static_cast<int>(std::lround(3.0 / static_cast<double>(tick)));
  for (int i = 0; i < n; ++i) o.step(u, none);
  hstmon::test::NewtonInputs nu;
  nu.kp *= kp_scale;
  const auto ref = hstmon::test::newton_steady_state({}, nu, {3.3e6L, 1.9e5L, 1.7e7L, 175.0L});
  const auto y = o.model().outputs(o.state());
  // A false fixed point is 1.5–10 % off; float state is compensated, so 1e-5 holds.
  const double tol = sizeof(T) == 4 ? 1e-5 : 1e-8;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(static_cast<double>(y[i]) / static_cast<double>(ref[static_cast<std::size_t>(i)]), 1.0, tol)
        << "channel " << i << " tick " << tick;
  }
  EXPECT_EQ(o.health(), 0u);
}

TEST(Observer, ReachesTrueSteadyStateFromRest) {
  expect_true_fixed_point<double>(1e-3, 1.0L);
  expect_true_fixed_point<double>(10e-3, 1.0L);
  expect_true_fixed_point<float>(1e-3f, 1.0L);
  expect_true_fixed_point<float>(10e-3f, 1.0L);
  expect_true_fixed_point<double>(10e-3, 0.5L);
  expect_true_fixed_point<float>(10e-3f, 0.5L);
}

TEST(Observer, SubstepsFollowStiffness) {
  Obs<double> o = make_observer<double>(10e-3);
  hstmon::ThesisInputs<double> u;
  o.reset_rest(u);
  o.step(u, {});
  const int at_rest = o.substeps();
  for (int i = 0; i < 300; ++i) o.step(u, {});
  EXPECT_GT(at_rest, 50);         // start from rest: the PRV mode is very fast
  EXPECT_LE(o.substeps(), 6);     // at the operating point: |λ| ≈ 384 1/s
  EXPECT_GE(o.substeps(), 4);
}

TEST(Observer, ResidualIsMeasurementMinusEstimateOnValidChannels) {
  Obs<double> o = make_observer<double>(1e-3);
  hstmon::ThesisInputs<double> u;
  ASSERT_EQ(o.reset_steady(u), hstmon::Status::kOk);
  Obs<double>::Measurement m;
  m.y = o.model().outputs(o.state());
  m.y[hstmon::kChPpp] += 2e5;
  m.valid = 0b0111;  // no speed channel
  o.step(u, m);
  EXPECT_NEAR(o.residual()[hstmon::kChPpp], 2e5, 1e-3);
  EXPECT_NEAR(o.residual()[hstmon::kChPmi], 0.0, 1e-3);
  EXPECT_EQ(o.residual()[hstmon::kChWm], 0.0);
  EXPECT_EQ(o.residual_valid(), 0b0111);
  EXPECT_EQ(o.last_health(), 0u);
}

TEST(Observer, NonFiniteMeasurementIsFlaggedAndMasked) {
  Obs<double> o = make_observer<double>(1e-3);
  hstmon::ThesisInputs<double> u;
  o.reset_steady(u);
  Obs<double>::Measurement m;
  m.y = o.model().outputs(o.state());
  m.y[hstmon::kChPmo] = std::numeric_limits<double>::quiet_NaN();
  m.valid = 0b1111;
  const auto flags = o.step(u, m);
  EXPECT_TRUE(flags & hstmon::kHealthMeasNonFinite);
  EXPECT_EQ(o.residual_valid(), 0b1101);
  EXPECT_TRUE(o.state().allFinite());
}

TEST(Observer, NonFiniteInputHoldsLastGoodInputs) {
  Obs<double> o = make_observer<double>(1e-3);
  hstmon::ThesisInputs<double> u;
  o.reset_steady(u);
  const auto before = o.state();
  auto bad = u;
  bad.kp = std::numeric_limits<double>::infinity();
  const auto flags = o.step(bad, {});
  EXPECT_TRUE(flags & hstmon::kHealthInputNonFinite);
  EXPECT_NEAR(o.state()[1] / before[1], 1.0, 1e-9);  // still at the old steady state
  EXPECT_DOUBLE_EQ(o.model().inputs().kp, u.kp);
}

TEST(Observer, OutputInjectionPullsTowardsMeasurement) {
  // A model whose kp is wrong by 10 %: with speed injection the residual shrinks.
  auto run = [](double gain) {
    hstmon::ThesisReducedModel<double> truth;
    hstmon::ThesisInputs<double> u_true;
    u_true.kp *= 0.9;
    truth.set_inputs(u_true);
    hstmon::ThesisReducedModel<double>::State xt = hstmon::ThesisReducedModel<double>::State::Zero();
    EXPECT_TRUE(truth.steady_state(xt));
    Obs<double> o;
    Obs<double>::Config c;
    c.gain(1, hstmon::kChWm) = gain;
    c.gain(0, hstmon::kChPpp) = gain;
    EXPECT_EQ(o.configure(hstmon::ThesisReducedModel<double>{}, c), hstmon::Status::kOk);
    hstmon::ThesisInputs<double> u;  // nominal kp: the model is wrong
    o.reset_steady(u);
    Obs<double>::Measurement m;
    m.y = truth.outputs(xt);
    m.valid = 0b1111;
    for (int i = 0; i < 2000; ++i) o.step(u, m);
    return std::fabs(o.residual()[hstmon::kChWm]);
  };
  EXPECT_LT(run(0.2), 0.5 * run(0.0));
}

TEST(Observer, RejectsBadConfig) {
  Obs<double> o;
  Obs<double>::Config c;
  c.tick = 0;
  EXPECT_EQ(o.configure(hstmon::ThesisReducedModel<double>{}, c), hstmon::Status::kInvalidConfig);
  c.tick = 1e-3;
  c.lambda_h_max = 3.0;  // beyond RK4's stability limit
  EXPECT_EQ(o.configure(hstmon::ThesisReducedModel<double>{}, c), hstmon::Status::kInvalidConfig);
  c.lambda_h_max = 0.8;
  c.gain(0, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(o.configure(hstmon::ThesisReducedModel<double>{}, c), hstmon::Status::kInvalidConfig);
}

TEST(Observer, SubstepCapIsReported) {
  Obs<double> o;
  Obs<double>::Config c;
  c.tick = 10e-3;
  c.max_substeps = 4;
  ASSERT_EQ(o.configure(hstmon::ThesisReducedModel<double>{}, c), hstmon::Status::kOk);
  hstmon::ThesisInputs<double> u;
  o.reset_rest(u);
  EXPECT_TRUE(o.step(u, {}) & hstmon::kHealthSubstepsClipped);
}

TEST(Observer, PaperModelRunsFromRest) {
  hstmon::Observer<hstmon::PaperModel<double>> o;
  hstmon::Observer<hstmon::PaperModel<double>>::Config c;
  c.tick = 1e-3;
  ASSERT_EQ(o.configure(hstmon::PaperModel<double>{}, c), hstmon::Status::kOk);
  hstmon::PaperInputs<double> u;
  for (int i = 0; i < 20000; ++i) o.step(u, {});
  const auto& x = o.state();
  EXPECT_TRUE(x.allFinite());
  EXPECT_GT(x[hstmon::PaperModel<double>::kWm], 10.0);
  EXPECT_LT(x[hstmon::PaperModel<double>::kPs], 90e5 * 1.01);  // compensator holds pressure
  EXPECT_EQ(o.health(), 0u);
}

}  // namespace
