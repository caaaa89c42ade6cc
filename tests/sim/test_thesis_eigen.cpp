// Stiffness of the full thesis model: eigenvalues of thesis_jacobian at the steady states
// (documented in docs/numerics.md).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <vector>

#include "hstmon/thesis_model.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim {
namespace {

std::vector<std::complex<double>> eigenvalues_at(const ThesisInputs<double>& u) {
  const ThesisParams<double> p;
  const ThesisState<double> x = thesis_steady_state(u, p);
  double j[4][4];
  thesis_jacobian(p, u, x, j);
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = j[r][c];
  }
  const Eigen::EigenSolver<Eigen::Matrix4d> es(m);
  EXPECT_EQ(es.info(), Eigen::Success);
  std::vector<std::complex<double>> ev(es.eigenvalues().data(), es.eigenvalues().data() + 4);
  // Most negative real part first, then by imaginary part.
  std::sort(ev.begin(), ev.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  return ev;
}

TEST(ThesisEigen, NominalPoint) {
  const auto ev = eigenvalues_at(ThesisInputs<double>{});
  // Two fast real DCV-side modes near −3.72e5 1/s (the stiffness) …
  EXPECT_NEAR(ev[0].real(), -3.7209e5, 0.0005e5);
  EXPECT_NEAR(ev[1].real(), -3.7206e5, 0.0005e5);
  EXPECT_EQ(ev[0].imag(), 0.0);
  EXPECT_EQ(ev[1].imag(), 0.0);
  // … and the slow shaft / loading-pump pair −316 ± 217i 1/s.
  EXPECT_NEAR(ev[2].real(), -316.32, 0.05);
  EXPECT_NEAR(ev[3].real(), -316.32, 0.05);
  EXPECT_NEAR(ev[2].imag(), -217.21, 0.05);
  EXPECT_NEAR(ev[3].imag(), 217.21, 0.05);
  // Stiffness ratio ≈ 980; RK4's real-axis limit 2.785/|λ| = 7.49 µs.
  EXPECT_NEAR(2.785 / -ev[0].real(), 7.49e-6, 0.01e-6);
}

TEST(ThesisEigen, HalvedKp) {
  ThesisInputs<double> u;
  u.kp *= 0.5;
  const auto ev = eigenvalues_at(u);
  EXPECT_NEAR(ev[0].real(), -6.4146e5, 0.0005e5);
  EXPECT_NEAR(ev[1].real(), -6.4144e5, 0.0005e5);
  EXPECT_NEAR(ev[2].real(), -152.86, 0.05);
  EXPECT_NEAR(ev[3].imag(), 307.34, 0.05);
}

}  // namespace
}  // namespace hstmon::sim
