// ROS34PW2 (rosenbrock.hpp): third-order convergence with the exact Jacobian and with one
// 30 % off, L-stability on a mode far faster than the step, the error-controlled tick, and
// a state padded to a larger capacity giving the same bits (built with -ffp-contract=off,
// as the ports are: bit equality is a property of IEEE operations without fused ones). (The error-controlled tick's
// `clipped` is not asserted: at tolerances this tight the filtered estimate of a component
// just brought onto its fast manifold still exceeds it at the finest step, though the
// result is as accurate as asked; the observer's tolerance is 1e-3.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "hstmon/rosenbrock.hpp"

namespace {

// x0' = −x0², x1' = −x1·x0 (both 1/(1+t) from 1), plus a fast mode x2' = −λ(x2 − x0)
// that follows x0; N ≥ 3 pads the state with zeros.
template <int N>
struct StiffModel {
  using Scalar = double;
  using State = Eigen::Matrix<double, N, 1>;
  using StateMatrix = Eigen::Matrix<double, N, N>;
  double lambda = 1e6;
  State derivative(const State& x) const {
    State d = State::Zero();
    d[0] = -x[0] * x[0];
    d[1] = -x[1] * x[0];
    d[2] = -lambda * (x[2] - x[0]);
    return d;
  }
  void jacobian(const State& x, StateMatrix& J, double off = 1.0) const {
    J.setZero();
    J(0, 0) = -2 * x[0] * off;
    J(1, 0) = -x[1];
    J(1, 1) = -x[0];
    J(2, 0) = lambda;
    J(2, 2) = -lambda;
  }
};

double error_at_1s(int steps, double jacobian_off) {
  StiffModel<3> m;
  hstmon::CompensatedState<StiffModel<3>::State> s;
  s.reset({1.0, 1.0, 1.0});
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) {
    StiffModel<3>::StateMatrix J;
    m.jacobian(s.x, J, jacobian_off);
    StiffModel<3>::State step, err;
    EXPECT_TRUE(hstmon::rosenbrock_increment(m, s.x, h, m.derivative(s.x), J, 3, step, err));
    s.add(step);
  }
  return std::fabs(s.x[0] - 0.5) + std::fabs(s.x[1] - 0.5);
}

TEST(Rosenbrock, ThirdOrderWithTheExactJacobianAndWithAnApproximateOne) {
  for (double off : {1.0, 1.3}) {
    double prev = error_at_1s(8, off);
    for (int n = 16; n <= 64; n *= 2) {
      const double e = error_at_1s(n, off);
      EXPECT_GT(prev / e, 6.5) << "n=" << n << " Jacobian factor " << off;  // 2³ = 8
      prev = e;
    }
  }
}

TEST(Rosenbrock, DampsAModeFarFasterThanTheStepInOneStep) {
  // λh = 1e4: the fast component starts 1 off its manifold and lands on it.
  StiffModel<3> m;
  StiffModel<3>::State x(1.0, 1.0, 2.0);
  StiffModel<3>::StateMatrix J;
  m.jacobian(x, J);
  StiffModel<3>::State step, err;
  ASSERT_TRUE(hstmon::rosenbrock_increment(m, x, 1e-2, m.derivative(x), J, 3, step, err));
  const StiffModel<3>::State x1 = x + step;
  EXPECT_NEAR(x1[2], x1[0], 1e-3);  // R(∞) = 0: no ringing across the manifold
}

TEST(Rosenbrock, ErrorControlledTickEndsOnTheTickWithinTolerance) {
  StiffModel<3> m;
  hstmon::CompensatedState<StiffModel<3>::State> s;
  s.reset({1.0, 1.0, 3.0});  // far off the fast manifold: the first steps must be short
  int level = 0;
  const hstmon::RosenbrockTick r =
      hstmon::rosenbrock_tick(m, s, 0.1, m.derivative(s.x), StiffModel<3>::State::Ones(), 1e-5, 12, level);
  ASSERT_TRUE(r.ok);
  EXPECT_GT(r.steps, 1);
  EXPECT_NEAR(s.x[0], 1.0 / 1.1, 1e-5);
  EXPECT_NEAR(s.x[2], s.x[0], 1e-4);
}

TEST(Rosenbrock, PaddedStateGivesTheSameBits) {
  StiffModel<3> a;
  StiffModel<8> b;
  hstmon::CompensatedState<StiffModel<3>::State> sa;
  hstmon::CompensatedState<StiffModel<8>::State> sb;
  sa.reset({1.0, 1.0, 1.5});
  StiffModel<8>::State xb = StiffModel<8>::State::Zero();
  xb.head<3>() = sa.x;
  sb.reset(xb);
  int la = 0, lb = 0;
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(hstmon::rosenbrock_tick(a, sa, 0.05, a.derivative(sa.x), StiffModel<3>::State::Ones(), 1e-4, 6, la).ok);
    ASSERT_TRUE(
        hstmon::rosenbrock_tick(b, sb, 0.05, b.derivative(sb.x), StiffModel<8>::State::Ones(), 1e-4, 6, lb, 3).ok);
  }
  for (int i = 0; i < 3; ++i) EXPECT_EQ(sa.x[i], sb.x[i]) << i;
  for (int i = 3; i < 8; ++i) EXPECT_EQ(sb.x[i], 0.0) << i;
}

TEST(Rosenbrock, NonFiniteMatrixIsRefused) {
  StiffModel<3> m;
  StiffModel<3>::State x(1.0, 1.0, 1.0);
  StiffModel<3>::StateMatrix J;
  m.jacobian(x, J);
  J(1, 1) = std::numeric_limits<double>::quiet_NaN();
  StiffModel<3>::State step, err;
  EXPECT_FALSE(hstmon::rosenbrock_increment(m, x, 0.1, m.derivative(x), J, 3, step, err));
}

// The coefficients rounded at compile time (Ros34pw2As) are those a run-time conversion
// gives, bit for bit, in float and double; fmax_inline is std::fmax on what the tick's
// error norm sees (≥ +0, ∞, NaN).
template <typename T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
template <typename T>
void expect_coefficients_as_at_run_time() {
  using M = hstmon::Ros34pw2;
  constexpr hstmon::rosenbrock_detail::Ros34pw2As<T> c{};
  for (int i = 0; i < M::kStages; ++i) {
    for (int j = 0; j < M::kStages; ++j) {
      volatile double a = M::kAlpha[i][j];
      volatile double g = M::kGammaIJ[i][j];
      EXPECT_TRUE(same_bits(c.alpha[i][j], static_cast<T>(a))) << i << "," << j;
      EXPECT_TRUE(same_bits(c.gamma_ij[i][j], static_cast<T>(g))) << i << "," << j;
      EXPECT_EQ(c.alpha[i][j] != T(0), M::kAlpha[i][j] != 0.0);
    }
    volatile double b = M::kB[i];
    volatile double bh = M::kBHat[i];
    EXPECT_TRUE(same_bits(c.b[i], static_cast<T>(b))) << i;
    EXPECT_TRUE(same_bits(c.b_err[i], static_cast<T>(b - bh))) << i;
  }
}

TEST(Rosenbrock, CoefficientsRoundedAtCompileTimeAreTheRunTimeOnes) {
  expect_coefficients_as_at_run_time<float>();
  expect_coefficients_as_at_run_time<double>();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float v[] = {0.0f, 1e-30f, 0.5f, 1.0f, 3e7f, inf, nan};
  for (float a : v) {
    for (float b : v) {
      const float f = hstmon::rosenbrock_detail::fmax_inline(a, b);
      const float g = std::fmax(a, b);
      if (std::isnan(g)) {
        EXPECT_TRUE(std::isnan(f)) << a << " " << b;
      } else {
        EXPECT_TRUE(same_bits(f, g)) << a << " " << b;
      }
    }
  }
}

}  // namespace
