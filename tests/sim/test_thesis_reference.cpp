// Reference integration of the full thesis model: steady states, blockage signature,
// tolerance convergence and an independent explicit-RK4 cross-check.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hstmon/thesis_model.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/simulate.hpp"
#include "hstmon_sim/thesis_reference.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim {
namespace {

using State = ThesisState<double>;
using Inputs = ThesisInputs<double>;

double rel(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

// Independent Newton solve in seeds/READING.md (7 significant digits).
const State kNominal{3.312079e6, 1.879209e5, 1.710822e7, 175.6867};
const State kHalvedKp{3.436769e6, 6.32307e4, 2.268005e7, 101.9096};

void expect_state_near(const State& x, const State& ref, double tol) {
  EXPECT_LT(rel(x.Pmi, ref.Pmi), tol) << "Pmi " << x.Pmi;
  EXPECT_LT(rel(x.Pmo, ref.Pmo), tol) << "Pmo " << x.Pmo;
  EXPECT_LT(rel(x.Ppp, ref.Ppp), tol) << "Ppp " << x.Ppp;
  EXPECT_LT(rel(x.w_m, ref.w_m), tol) << "w_m " << x.w_m;
}

TEST(ThesisReference, SteadyStateFromRestMatchesTable22) {
  const ThesisScenario sc = thesis_start_from_rest(5.0);
  const ThesisTrajectory tr = simulate(sc, {0.0, 1.0, 5.0});
  ASSERT_EQ(tr.size(), 3u);
  const State x0 = tr[0].x;
  EXPECT_EQ(x0.Pmi, 0.0);
  EXPECT_EQ(x0.Pmo, 0.0);
  EXPECT_EQ(x0.Ppp, 1.0e6);
  EXPECT_EQ(x0.w_m, 0.0);
  expect_state_near(tr[2].x, kNominal, 1e-6);
  // ≈ 1678 rpm
  EXPECT_NEAR(tr[2].x.w_m / kRadPerSecPerRpm, 1677.7, 0.1);
  // Steady to rounding already at 1 s; equal to the reduced model's steady state.
  const State ss = thesis_steady_state(Inputs{});
  expect_state_near(tr[1].x, ss, 1e-9);
  expect_state_near(tr[2].x, ss, 1e-9);
}

TEST(ThesisReference, HalvedKpSteadyStateAndFaultSigns) {
  const ThesisScenario sc = thesis_prv_blockage();
  const ThesisTrajectory tr = simulate(sc, {0.0, 79.0, 80.0, 80.01, 120.0});
  ASSERT_EQ(tr.size(), 5u);
  const State before = tr[1].x;
  const State after = tr[4].x;
  expect_state_near(before, kNominal, 1e-6);
  expect_state_near(after, kHalvedKp, 1e-6);
  // Fault-tree signature of kp− (thesis §2.4): Pmi+, Pmo−, Ppp+, ωm−.
  EXPECT_GT(after.Pmi, before.Pmi);
  EXPECT_LT(after.Pmo, before.Pmo);
  EXPECT_GT(after.Ppp, before.Ppp);
  EXPECT_LT(after.w_m, before.w_m);
  // Inputs are right-continuous; the state is continuous across the change.
  EXPECT_EQ(tr[1].u.kp, 4.41e-8);
  EXPECT_EQ(tr[2].u.kp, 0.5 * 4.41e-8);
  expect_state_near(tr[2].x, kNominal, 1e-6);
  // 10 ms after the change Ppp has started to rise (first-order effect, thesis Fig. 2.18).
  EXPECT_GT(tr[3].x.Ppp, before.Ppp * 1.05);
}

TEST(ThesisReference, StaircaseSettlesAtEachSetting) {
  const ThesisScenario sc = thesis_prv_staircase(0.5);
  std::vector<double> ends;
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) ends.push_back(segment_end(sc, k) - 1e-3);
  const ThesisTrajectory tr = simulate(sc, ends);
  ASSERT_EQ(tr.size(), sc.schedule.size());
  double w_prev = 1e9;
  for (std::size_t k = 0; k < tr.size(); ++k) {
    const State ss = thesis_steady_state(sc.schedule[k].u);
    expect_state_near(tr[k].x, ss, 1e-8);
    EXPECT_LT(tr[k].x.w_m, w_prev);  // smaller kp, slower motor
    w_prev = tr[k].x.w_m;
  }
}

TEST(ThesisReference, TighterTolerancesAgreeOnTheStartTransient) {
  const ThesisScenario sc = thesis_start_from_rest(0.05);
  std::vector<double> ts;
  for (int k = 0; k <= 50; ++k) ts.push_back(1e-3 * k);
  ReferenceTolerances tight;
  tight.rel = 1e-11;
  tight.abs_pressure = 1e-5;
  tight.abs_speed = 1e-11;
  const ThesisTrajectory a = simulate(sc, ts);
  const ThesisTrajectory b = simulate(sc, ts, ThesisParams<double>{}, tight);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    worst = std::fmax(worst, rel(a[i].x.w_m, b[i].x.w_m));
    worst = std::fmax(worst, std::fabs(a[i].x.Pmi - b[i].x.Pmi) / 3.5e6);
    worst = std::fmax(worst, std::fabs(a[i].x.Pmo - b[i].x.Pmo) / 3.5e6);
    worst = std::fmax(worst, rel(a[i].x.Ppp, b[i].x.Ppp));
  }
  EXPECT_LT(worst, 1e-7);
}

// Explicit RK4 at h = 1e-7 s is stable here (|λ|·h ≤ 1.3 < 2.78 even at rest, where the
// regularised DCV slope gives λ ≈ −1.3e7 1/s) and accurate to ~1e-12: an independent truth.
TEST(ThesisReference, MatchesFineExplicitRk4FromRest) {
  const ThesisParams<double> p;
  const Inputs u;
  const double h = 1e-7;
  State x = thesis_rest_state(u);
  auto axpy = [](const State& a, const State& d, double s) {
    return State{a.Pmi + s * d.Pmi, a.Pmo + s * d.Pmo, a.Ppp + s * d.Ppp, a.w_m + s * d.w_m};
  };
  std::vector<State> rk;
  const int per_ms = 10000;
  for (int k = 1; k <= 20 * per_ms; ++k) {
    const State k1 = thesis_derivative(p, u, x);
    const State k2 = thesis_derivative(p, u, axpy(x, k1, 0.5 * h));
    const State k3 = thesis_derivative(p, u, axpy(x, k2, 0.5 * h));
    const State k4 = thesis_derivative(p, u, axpy(x, k3, h));
    x = State{x.Pmi + h / 6 * (k1.Pmi + 2 * k2.Pmi + 2 * k3.Pmi + k4.Pmi),
              x.Pmo + h / 6 * (k1.Pmo + 2 * k2.Pmo + 2 * k3.Pmo + k4.Pmo),
              x.Ppp + h / 6 * (k1.Ppp + 2 * k2.Ppp + 2 * k3.Ppp + k4.Ppp),
              x.w_m + h / 6 * (k1.w_m + 2 * k2.w_m + 2 * k3.w_m + k4.w_m)};
    if (k % (2 * per_ms) == 0) rk.push_back(x);  // every 2 ms
  }
  std::vector<double> ts;
  for (int k = 1; k <= 10; ++k) ts.push_back(2e-3 * k);
  const ThesisTrajectory tr = simulate(thesis_start_from_rest(0.02), ts);
  ASSERT_EQ(tr.size(), rk.size());
  for (std::size_t i = 0; i < rk.size(); ++i) {
    EXPECT_LT(rel(tr[i].x.w_m, rk[i].w_m), 1e-7) << "t = " << tr[i].t;
    EXPECT_LT(std::fabs(tr[i].x.Pmi - rk[i].Pmi), 1.0) << "t = " << tr[i].t;  // Pa
    EXPECT_LT(std::fabs(tr[i].x.Pmo - rk[i].Pmo), 1.0) << "t = " << tr[i].t;
    EXPECT_LT(rel(tr[i].x.Ppp, rk[i].Ppp), 1e-7) << "t = " << tr[i].t;
  }
}

// Samples come from the dense-output polynomial; on this model at default tolerances they
// agree with samples taken as hard stops (true step ends) to ~1e-9 relative.
TEST(ThesisReference, DenseSamplesAgreeWithHardStops) {
  ThesisScenario sc = thesis_prv_blockage();
  sc.schedule[1].t_start = 0.1;
  sc.duration = 0.5;
  const std::vector<double> ts = uniform_times(sc.duration, 1e-3);
  const ThesisTrajectory dense = simulate(sc, ts);
  ThesisReference ref(ThesisParams<double>{}, thesis_initial_state(sc));
  ASSERT_EQ(dense.size(), ts.size());
  for (std::size_t i = 1; i < ts.size(); ++i) {
    ref.advance_to(ts[i], ts[i] <= 0.1 ? sc.schedule[0].u : sc.schedule[1].u);
    const State x = ref.state();
    EXPECT_NEAR(dense[i].x.Pmi, x.Pmi, 0.02) << ts[i];   // Pa
    EXPECT_NEAR(dense[i].x.Pmo, x.Pmo, 0.02) << ts[i];   // Pa
    EXPECT_NEAR(dense[i].x.Ppp, x.Ppp, 0.2) << ts[i];    // Pa
    EXPECT_NEAR(dense[i].x.w_m, x.w_m, 1e-6) << ts[i];   // rad/s
  }
}

TEST(ThesisReference, RestartsOnlyWhenInputsChange) {
  ThesisReference ref(ThesisParams<double>{}, thesis_steady_state(Inputs{}));
  ref.advance_to(1.0, Inputs{});
  ref.advance_to(2.0, Inputs{});
  EXPECT_EQ(ref.stats().restarts, 1u);
  Inputs blocked;
  blocked.kp *= 0.5;
  ref.advance_to(3.0, blocked);
  EXPECT_EQ(ref.stats().restarts, 2u);
  EXPECT_EQ(ref.time(), 3.0);
  expect_state_near(ref.state(), kHalvedKp, 1e-6);
  EXPECT_THROW(ref.advance_to(2.5, blocked), std::invalid_argument);
  Inputs bad;
  bad.kp = -1.0;
  EXPECT_THROW(ref.advance_to(4.0, bad), std::invalid_argument);
}

}  // namespace
}  // namespace hstmon::sim
