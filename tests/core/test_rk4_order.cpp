// RK4 convergence order (halve h → error / 16) and the compensated float update.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon/hstmon.hpp"

namespace {

// A smooth nonlinear test problem with a known solution: x' = −x² (x(t) = x0/(1 + x0·t))
// coupled with a rotation, as a 2-state model in the library's Model shape.
template <typename T>
struct SmoothModel {
  using Scalar = T;
  using State = Eigen::Matrix<T, 2, 1>;
  State derivative(const State& x) const { return State(-x[0] * x[0], -x[1] * x[0]); }
};

double error_at_1s(int steps) {
  SmoothModel<double> m;
  hstmon::CompensatedState<SmoothModel<double>::State> s;
  s.reset({1.0, 1.0});
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) hstmon::rk4_step(m, s, h);
  // Exact: x0(t) = 1/(1+t); x1' = −x1·x0 ⇒ x1 = 1/(1+t).
  return std::fabs(s.x[0] - 0.5) + std::fabs(s.x[1] - 0.5);
}

TEST(Rk4, FourthOrderConvergence) {
  double prev = error_at_1s(8);
  for (int n = 16; n <= 128; n *= 2) {
    const double e = error_at_1s(n);
    const double ratio = prev / e;
    EXPECT_GT(ratio, 14.0) << "n=" << n;
    EXPECT_LT(ratio, 18.5) << "n=" << n;
    prev = e;
  }
}

TEST(Rk4, ReducedThesisModelConvergesAtFourthOrder) {
  // A kp step from the nominal steady state: the smooth part of the observer's problem.
  auto run = [](int n_per_ms) {
    hstmon::ThesisReducedModel<double> m;
    hstmon::ThesisReducedModel<double>::State x0 = hstmon::ThesisReducedModel<double>::State::Zero();
    EXPECT_TRUE(m.steady_state(x0));
    hstmon::ThesisInputs<double> u;
    u.kp *= 0.5;
    m.set_inputs(u);
    hstmon::CompensatedState<hstmon::ThesisReducedModel<double>::State> s;
    s.reset(x0);
    const double h = 1e-3 / n_per_ms;
    for (int i = 0; i < 10 * n_per_ms; ++i) hstmon::rk4_step(m, s, h);
    return s.x;
  };
  const auto ref = run(64);
  const double e1 = (run(1) - ref).cwiseQuotient(ref).cwiseAbs().maxCoeff();
  const double e2 = (run(2) - ref).cwiseQuotient(ref).cwiseAbs().maxCoeff();
  const double e4 = (run(4) - ref).cwiseQuotient(ref).cwiseAbs().maxCoeff();
  EXPECT_GT(e1 / e2, 12.0);
  EXPECT_GT(e2 / e4, 13.0);
  EXPECT_LT(e2 / e4, 19.0);
}

TEST(Rk4, CompensatedFloatKeepsDoubleAccuracy) {
  // 1e5 tiny increments onto a large state: plain float loses them, Kahan keeps them.
  using V = Eigen::Matrix<float, 1, 1>;
  hstmon::CompensatedState<V> s;
  s.reset(V(1.7e7f));
  float plain = 1.7e7f;
  const V dx(0.37f);
  for (int i = 0; i < 100000; ++i) {
    s.add(dx);
    plain += dx[0];
  }
  const double exact = 1.7e7 + 0.37 * 100000;  // float(0.37) differs by 1e-8 relative
  EXPECT_NEAR(s.x[0] / exact, 1.0, 1e-7);
  EXPECT_GT(std::fabs(plain / exact - 1.0), 1e-4);  // the failure the compensation prevents
}

}  // namespace
