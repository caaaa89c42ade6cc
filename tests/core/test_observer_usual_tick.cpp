// The fused usual tick (ThesisReducedModel::usual_tick, taken by Observer::step at the
// operating point) against the general tick (tick_derivative + rk4_step): the same model
// and RK4 to rounding, taken where it applies and nowhere else, and the observer's
// residuals, masks and health flags unchanged by it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "hstmon/hstmon.hpp"

namespace {

template <typename T>
using Model = hstmon::ThesisReducedModel<T>;
template <typename T, bool Usual = true>
using Obs = hstmon::Observer<Model<T>, Usual>;

static_assert(Model<double>::kHasUsualTick, "host builds have the usual tick");

template <typename T, bool Usual>
Obs<T, Usual> make_observer(T tick) {
  Obs<T, Usual> o;
  typename Obs<T, Usual>::Config c;
  c.tick = tick;
  EXPECT_EQ(o.configure(Model<T>{}, c), hstmon::Status::kOk);
  return o;
}

static_assert(std::is_same_v<Obs<double>, hstmon::Observer<Model<double>>>, "on by default");

double rel(double a, double b) { return std::fabs(a - b) / std::fmax(std::fabs(b), 1e-300); }

// One step from x by both routes: outputs and increment agree to rounding.
TEST(UsualTick, MatchesTickDerivativeAndRk4OnTheModel) {
  Model<double> m;
  typename Model<double>::State x0;
  ASSERT_TRUE(m.steady_state(x0));
  const double h = 1e-3;
  const double rho_max = 0.8 / h;
  const auto c = m.usual_tick_coeffs(h, rho_max);
  // Around the operating point, including well off it (a kp step's transient).
  const double scales[][2] = {{1.0, 1.0}, {0.9, 1.0}, {1.1, 0.8}, {1.3, 1.2}, {0.8, 0.9}};
  for (const auto& sc : scales) {
    const typename Model<double>::State x(m.inputs().Pbp + sc[0] * (x0[0] - m.inputs().Pbp), sc[1] * x0[1]);
    typename Model<double>::Output y_usual, y_general;
    typename Model<double>::State dx;
    ASSERT_TRUE(m.usual_tick(c, x, y_usual, dx)) << sc[0] << " " << sc[1];
    double rho;
    bool alg_ok;
    const auto k1 = m.tick_derivative(x, rho_max, y_general, rho, alg_ok);
    EXPECT_EQ(rho, 0.0);
    EXPECT_TRUE(alg_ok);
    hstmon::CompensatedState<typename Model<double>::State> s;
    s.reset(x);
    hstmon::rk4_step(m, s, h, k1);
    for (int i = 0; i < 4; ++i) EXPECT_LT(rel(y_usual[i], y_general[i]), 1e-14) << "output " << i;
    const auto dx_general = (s.x - x).eval();
    // Increments to rounding of the state they are added to (near steady state they are
    // themselves rounding-sized).
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(dx[i], dx_general[i], 1e-14 * std::fabs(x[i]) + 1e-12 * std::fabs(dx_general[i])) << "increment " << i;
    }
  }
}

// Outside the usual region usual_tick declines and the general path decides.
TEST(UsualTick, DeclinesOutsideTheUsualRegion) {
  Model<double> m;
  const double h = 1e-3;
  const auto c = m.usual_tick_coeffs(h, 0.8 / h);
  typename Model<double>::Output y;
  typename Model<double>::State dx;
  EXPECT_FALSE(m.usual_tick(c, m.rest_state(), y, dx));                            // at rest
  EXPECT_FALSE(m.usual_tick(c, {m.inputs().Pbp + 1e7, -150.0}, y, dx));            // reversing
  EXPECT_FALSE(m.usual_tick(c, {m.inputs().Pbp + 1e3, 150.0}, y, dx));             // PRV laminar
  EXPECT_FALSE(m.usual_tick(c, {m.inputs().Pbp + 1e7, 400.0}, y, dx));             // beyond one refinement
  EXPECT_FALSE(m.usual_tick(c, {std::numeric_limits<double>::quiet_NaN(), 150.0}, y, dx));
  // A 10 ms tick never meets ρ·h ≤ 0.8 on this rig (K·Dp²/J alone is 1e5 1/s²): empty region.
  const auto c10 = m.usual_tick_coeffs(10e-3, 0.8 / 10e-3);
  EXPECT_GT(c10.w_lo, c10.w_hi);
  // A wide-open PRV is stiff (J11 = −K·kp/(2√ΔPpp) large): outside the region at 1 ms.
  hstmon::ThesisInputs<double> u;
  u.kp *= 40.0;
  m.set_inputs(u);
  typename Model<double>::State xs;
  ASSERT_TRUE(m.steady_state(xs));
  const auto cs = m.usual_tick_coeffs(h, 0.8 / h);
  EXPECT_FALSE(m.usual_tick(cs, xs, y, dx));
  EXPECT_GT(m.spectral_radius(xs), 0.8 / h);
}

// Whole runs, usual tick on and off: start from rest (general path), settle (usual),
// PRV blockage and its release (usual through the transient where the region holds).
template <typename T>
void compare_runs(T tick, double tol) {
  auto on = make_observer<T, true>(tick);
  auto off = make_observer<T, false>(tick);
  hstmon::ThesisInputs<T> u;
  ASSERT_EQ(on.reset_rest(u), hstmon::Status::kOk);
  ASSERT_EQ(off.reset_rest(u), hstmon::Status::kOk);
  const T kp0 = u.kp;
  const long n = std::lround(6.0 / static_cast<double>(tick));
  double worst[4] = {0, 0, 0, 0};
  for (long k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * static_cast<double>(tick);
    u.kp = (t >= 2.0 && t < 4.0) ? kp0 * T(0.5) : kp0;
    typename Obs<T>::Measurement m;  // the same type for both observers
    m.y = off.estimate();
    m.y[0] += T(3e3);
    m.y[3] += T(0.1);
    m.valid = 0x0F;
    const auto f_on = on.step(u, m);
    const auto f_off = off.step(u, m);
    ASSERT_EQ(f_on, f_off) << "t = " << t;
    ASSERT_EQ(on.substeps(), off.substeps()) << "t = " << t;
    for (int i = 0; i < 4; ++i) {
      const double e = rel(static_cast<double>(on.estimate()[i]), static_cast<double>(off.estimate()[i]));
      worst[i] = std::fmax(worst[i], e);
    }
  }
  for (int i = 0; i < 4; ++i) EXPECT_LT(worst[i], tol) << "channel " << i;
  std::printf("%s: worst rel difference usual vs general %.2g %.2g %.2g %.2g; usual ticks %llu of %ld\n",
              sizeof(T) == 4 ? "float " : "double", worst[0], worst[1], worst[2], worst[3],
              static_cast<unsigned long long>(on.usual_ticks()), n);
  EXPECT_EQ(off.usual_ticks(), 0u);
  // Every tick but the start-up and the first after each kp change: at either tick the
  // whole blockage transient stays in the usual region.
  EXPECT_GT(on.usual_ticks(), static_cast<std::uint64_t>(0.97 * static_cast<double>(n)));
  EXPECT_LT(on.usual_ticks(), static_cast<std::uint64_t>(n));
  EXPECT_EQ(on.health(), 0u);
}

TEST(UsualTick, ObserverRunsAgreeWithTheGeneralPathDouble) { compare_runs<double>(1e-3, 1e-13); }
TEST(UsualTick, ObserverRunsAgreeWithTheGeneralPathFloat) { compare_runs<float>(1e-3f, 5e-6); }
// A PLC scan: every tick needs ≥ 4 substeps, so the usual tick runs in n substeps.
TEST(UsualTick, ObserverRunsAgreeWithTheGeneralPathDouble10ms) { compare_runs<double>(10e-3, 1e-13); }
TEST(UsualTick, ObserverRunsAgreeWithTheGeneralPathFloat10ms) { compare_runs<float>(10e-3f, 5e-6); }

// The usual tick keeps the general path's residual bookkeeping: masked and non-finite
// channels, and their flags.
TEST(UsualTick, MasksAndNonFiniteChannelsAsTheGeneralPath) {
  auto on = make_observer<double, true>(1e-3);
  auto off = make_observer<double, false>(1e-3);
  const hstmon::ThesisInputs<double> u;
  ASSERT_EQ(on.reset_steady(u), hstmon::Status::kOk);
  ASSERT_EQ(off.reset_steady(u), hstmon::Status::kOk);
  Obs<double>::Measurement m;
  m.y = on.estimate();
  m.y[1] = std::numeric_limits<double>::quiet_NaN();
  m.y[2] += 5e4;
  m.valid = 0x07;  // no speed sample, Pmo not finite
  const auto f_on = on.step(u, m);
  const auto f_off = off.step(u, m);
  EXPECT_EQ(on.usual_ticks(), 1u);
  EXPECT_EQ(f_on, hstmon::kHealthMeasNonFinite);
  EXPECT_EQ(f_on, f_off);
  EXPECT_EQ(on.residual_valid(), 0x05);
  EXPECT_EQ(on.residual_valid(), off.residual_valid());
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(on.residual()[i], off.residual()[i], 1e-6) << i;
  EXPECT_EQ(on.residual()[1], 0.0);
  EXPECT_EQ(on.residual()[3], 0.0);
}

// Output injection moves the state before the RK4 step: always the general path.
TEST(UsualTick, NotTakenWithAnInjectionGain) {
  Obs<double> o;
  Obs<double>::Config c;
  c.gain(1, 3) = 0.5;
  ASSERT_EQ(o.configure(Model<double>{}, c), hstmon::Status::kOk);
  const hstmon::ThesisInputs<double> u;
  ASSERT_EQ(o.reset_steady(u), hstmon::Status::kOk);
  Obs<double>::Measurement m;
  m.y = o.estimate();
  m.valid = 0x0F;
  for (int i = 0; i < 10; ++i) o.step(u, m);
  EXPECT_EQ(o.usual_ticks(), 0u);
  EXPECT_EQ(o.ticks(), 10u);
}

}  // namespace
