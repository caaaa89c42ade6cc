// Steady states of the reduced model (what the observer converges to) against an
// independent Newton solve of the full equations 2.5–2.8.
#include <gtest/gtest.h>

#include "hstmon/hstmon.hpp"
#include "newton_reference.hpp"

namespace {

using hstmon::ThesisInputs;
using hstmon::ThesisReducedModel;
using hstmon::test::Vec4;

template <typename T>
Vec4 reduced_steady(T kp_scale) {
  ThesisReducedModel<T> m;
  ThesisInputs<T> u;
  u.kp *= kp_scale;
  m.set_inputs(u);
  typename ThesisReducedModel<T>::State x = ThesisReducedModel<T>::State::Zero();
  EXPECT_TRUE(m.steady_state(x));
  const auto y = m.outputs(x);
  return {y[0], y[1], y[2], y[3]};
}

Vec4 newton(long double kp_scale) {
  hstmon::test::NewtonInputs u;
  u.kp *= kp_scale;
  return hstmon::test::newton_steady_state({}, u, {3.3e6L, 1.9e5L, 1.7e7L, 175.0L});
}

void expect_rel(const Vec4& got, const Vec4& want, double tol) {
  const char* names[] = {"Pmi", "Pmo", "Ppp", "w_m"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(static_cast<double>(got[i] / want[i]), 1.0, tol) << names[i];
  }
}

TEST(SteadyState, NewtonReferenceMatchesPublishedReading) {
  // Cross-check of the test's own solver against seeds/READING.md.
  expect_rel(newton(1), {3.312079e6L, 1.879209e5L, 1.710822e7L, 175.6867L}, 1e-6);
  expect_rel(newton(0.5L), {3.436769e6L, 6.32307e4L, 2.268005e7L, 101.9096L}, 1e-6);
}

TEST(SteadyState, Table22NominalMatchesNewtonTo1e6) {
  const Vec4 x = reduced_steady<double>(1.0);
  expect_rel(x, newton(1), 1e-6);
  EXPECT_NEAR(static_cast<double>(x[3]) * 60 / (2 * M_PI), 1677.7, 0.5);  // ≈ 1678 rpm
}

TEST(SteadyState, PrvHalvedMatchesNewtonAndThesisSigns) {
  const Vec4 nominal = reduced_steady<double>(1.0);
  const Vec4 blocked = reduced_steady<double>(0.5);
  expect_rel(blocked, newton(0.5L), 1e-6);
  // Thesis Figs 2.12–2.13 / fault tree: kp− ⇒ Pmi+, Pmo−, Ppp+, ωm−.
  EXPECT_GT(blocked[0], nominal[0]);
  EXPECT_LT(blocked[1], nominal[1]);
  EXPECT_GT(blocked[2], nominal[2]);
  EXPECT_LT(blocked[3], nominal[3]);
}

TEST(SteadyState, FloatSolveWithinFloatPrecision) {
  expect_rel(reduced_steady<float>(1.0f), newton(1), 2e-6);
  expect_rel(reduced_steady<float>(0.5f), newton(0.5L), 2e-6);
}

TEST(SteadyState, FullModelDerivativeVanishesAtReducedSteadyState) {
  // The reduced model's fixed point is a fixed point of equations 2.5–2.8 too.
  hstmon::ThesisReducedModel<double> m;
  hstmon::ThesisReducedModel<double>::State x = hstmon::ThesisReducedModel<double>::State::Zero();
  ASSERT_TRUE(m.steady_state(x));
  const auto y = m.outputs(x);
  const hstmon::ThesisState<double> s{y[0], y[1], y[2], y[3]};
  const auto d = hstmon::thesis_derivative(m.params(), m.inputs(), s);
  // Flows balance to 1e-12 of the motor flow (K = 1e14 scales them to Pa/s).
  const double q_scale = 1e14 * 7.96e-6 * 175.0;
  EXPECT_LT(std::fabs(d.Pmi) / q_scale, 1e-12);
  EXPECT_LT(std::fabs(d.Pmo) / q_scale, 1e-12);
  EXPECT_LT(std::fabs(d.Ppp) / q_scale, 1e-12);
  EXPECT_LT(std::fabs(d.w_m), 1e-6);
}

TEST(SteadyState, NoSteadyStateWithPrvShut) {
  hstmon::ThesisReducedModel<double> m;
  hstmon::ThesisInputs<double> u;
  u.kp = 0;
  m.set_inputs(u);
  hstmon::ThesisReducedModel<double>::State x(1, 2);
  EXPECT_FALSE(m.steady_state(x));
  EXPECT_EQ(x[0], 1);  // untouched
}

TEST(SteadyState, ReversedSupplyRunsBackwards) {
  hstmon::ThesisReducedModel<double> m;
  hstmon::ThesisInputs<double> u;
  u.Psupl = 0;
  u.Ps = 3.5e6;
  m.set_inputs(u);
  hstmon::ThesisReducedModel<double>::State x = hstmon::ThesisReducedModel<double>::State::Zero();
  ASSERT_TRUE(m.steady_state(x));
  EXPECT_LT(x[1], 0);
  EXPECT_NEAR(m.steady_torque(x[1]), 0, 1e-6);
}

}  // namespace
