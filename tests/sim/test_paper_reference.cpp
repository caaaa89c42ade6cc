// Reference integration of the paper model: analytic Jacobian, start from rest to a
// steady state that an independent Newton solve confirms, and mode locations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "hstmon_sim/paper_jacobian.hpp"
#include "hstmon_sim/paper_reference.hpp"
#include "hstmon_sim/simulate.hpp"

namespace hstmon::sim {
namespace {

using Model = PaperModel<double>;
using State = Model::State;

Eigen::Matrix4d jacobian(const Model& m, const State& x) {
  double j[4][4];
  paper_jacobian(m, x, j);
  Eigen::Matrix4d J;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) J(r, c) = j[r][c];
  }
  return J;
}

Model start_model() {
  Model m;
  m.set_inputs(paper_start().schedule.front().u);
  return m;
}

TEST(PaperJacobian, MatchesCentralDifferences) {
  const Model m = start_model();
  // States in every pump-curve region and in the laminar zone of both orifices.
  const State pts[] = {State(40e5, 30e5, 20e5, 150.0), State(80e5, 66e5, 18.7e5, 235.0),
                       State(88e5, 80e5, 50e5, 100.0), State(1.5e5, 1.0e5, 500.0, 2.0),
                       State(500.0, 0.0, -300.0, 0.0)};
  const double scale[4] = {1e5, 1e5, 1e5, 1.0};
  for (const State& x : pts) {
    const Eigen::Matrix4d J = jacobian(m, x);
    for (int c = 0; c < 4; ++c) {
      const double h = 1e-5 * scale[c];  // 1 Pa / 1e-5 rad/s: FD error ≪ 1e-5 relative
      State xp = x, xm = x;
      xp[c] += h;
      xm[c] -= h;
      const State fd = (m.derivative(xp) - m.derivative(xm)) / (2.0 * h);
      for (int r = 0; r < 4; ++r) {
        const double tol = 1e-5 * (std::fabs(J(r, c)) + 1e-3 * J.row(r).cwiseAbs().maxCoeff());
        EXPECT_NEAR(fd[r], J(r, c), tol) << "row " << r << " col " << c << " at " << x.transpose();
      }
    }
  }
}

TEST(PaperReference, StartReachesTheNewtonSteadyState) {
  const PaperScenario sc = paper_start(30.0);
  const PaperTrajectory tr = simulate(sc, {0.0, 30.0});
  ASSERT_EQ(tr.size(), 2u);
  EXPECT_TRUE(tr[0].x.isZero());
  const State x_end = tr[1].x;

  // Independent steady state: Newton on f(x) = 0 with the analytic Jacobian.
  const Model m = start_model();
  State x = x_end * 1.02;  // start a few % off
  for (int it = 0; it < 50; ++it) {
    const State f = m.derivative(x);
    const State dx = jacobian(m, x).fullPivLu().solve(-f);
    x += dx;
    if (dx.cwiseAbs().maxCoeff() < 1e-12 * x.cwiseAbs().maxCoeff()) break;
  }
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x_end[i], x[i], 1e-6 * std::fabs(x[i])) << "state " << i;
  // ≈ 79.4 bar at pump B (on its compensator region), 65.9 bar at the motor, 2249 rpm.
  EXPECT_NEAR(x[Model::kPs], 79.397e5, 0.01e5);
  EXPECT_NEAR(x[Model::kWm] * 30.0 / 3.14159265358979323846, 2249.39, 0.05);

  // The paper model is not stiff: modes at the steady state are slow and damped.
  const Eigen::EigenSolver<Eigen::Matrix4d> es(jacobian(m, x));
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(es.eigenvalues()[i].real(), 0.0);
    EXPECT_LT(std::abs(es.eigenvalues()[i]), 2e3);
  }
}

}  // namespace
}  // namespace hstmon::sim
