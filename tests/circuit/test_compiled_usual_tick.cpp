// The compiled thesis model's fused usual tick (CompiledModel::usual_tick, what hosts run):
// bit for bit the general tick (Observer<Model, false>, what firmware runs) in double and
// float — steady with a kp step, from rest, at 10 ms — and taken at the operating point;
// its box certified where the general tick's own ρ and contraction say so, and not from rest.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hstmon/generated/thesis_circuit_compiled.hpp"
#include "usual_tick_equality.hpp"

namespace {

namespace gen = hstmon::generated::thesis_circuit;

template <typename T>
typename gen::CompiledModel<T>::Params params() {
  typename gen::CompiledModel<T>::Params p;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = static_cast<T>(gen::kParams[i]);
  return p;
}

template <typename T>
typename gen::CompiledModel<T>::Inputs inputs(double kp_scale = 1.0) {
  typename gen::CompiledModel<T>::Inputs u;
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = static_cast<T>(gen::kInputs[i]);
  u.v[3] = static_cast<T>(gen::kInputs[3] * kp_scale);  // kp, the PRV's flow coefficient
  return u;
}

static_assert(gen::CompiledModel<double>::kHasUsualTick, "hosts have the compiled usual tick");
static_assert(hstmon::Observer<gen::CompiledModel<double>>::kUsualTick, "and observers take it by default");

template <typename T>
void expect_usual_equals_general() {
  // kp halved half-way: a PRV restriction's transient, which leaves the first box.
  const auto taken = usual_tick_equality::expect_same<T, gen::Kernel>(params<T>(), inputs<T>(), inputs<T>(0.5), T(1e-3));
  EXPECT_EQ(taken.ticks, 2000);
  EXPECT_GT(taken.usual, 1800) << "the usual tick serves the operating point";
}

TEST(CompiledUsualTick, DoubleEqualsTheGeneralTickBitForBit) { expect_usual_equals_general<double>(); }

TEST(CompiledUsualTick, FloatEqualsTheGeneralTickBitForBit) { expect_usual_equals_general<float>(); }

TEST(CompiledUsualTick, KpHalvedToo) {
  const auto taken =
      usual_tick_equality::expect_same<double, gen::Kernel>(params<double>(), inputs<double>(0.5), inputs<double>(), 1e-3);
  EXPECT_GT(taken.usual, 1800);
}

using Model = gen::CompiledModel<double>;

// Everywhere in a certified box — sampled, the stiff pressures solved — the general tick
// finds ρ ≤ λh_max/h and the solve contracting: what lets the usual tick skip them.
TEST(CompiledUsualTick, CertifiedBoxHoldsWhatItCertifies) {
  const Model m(params<double>(), inputs<double>());
  Model::State x0;
  ASSERT_TRUE(m.steady_state(x0));
  const double h = 1e-3, rho_max = 0.8 / h;
  const auto c = m.usual_tick_coeffs(h, rho_max, x0);
  ASSERT_TRUE(c.certified);
  for (int s = 0; s < 2; ++s) {
    EXPECT_LE(c.x_lo[s], x0[s]);
    EXPECT_GE(c.x_hi[s], x0[s]);
    EXPECT_LT(c.x_lo[s], c.x_hi[s]);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inside = 0;
  for (int k = 0; k < 400; ++k) {
    Model::State x;
    for (int s = 0; s < 2; ++s) x[s] = c.x_lo[s] + unit(rng) * (c.x_hi[s] - c.x_lo[s]);
    Model::Output y;
    double rho = -1.0;
    bool alg_ok = false;
    (void)m.tick_derivative(x, rho_max, y, rho, alg_ok);
    // Only where the solved stiff pressures lie in the box too (usual_tick's other test):
    // outputs 0 and 1 are the DCV-side pressures, the stiff nodes.
    if (!(y[0] >= c.a_lo[0] && y[0] <= c.a_hi[0] && y[1] >= c.a_lo[1] && y[1] <= c.a_hi[1])) continue;
    ++inside;
    EXPECT_EQ(rho, 0.0) << "ρ above λh_max/h inside the box at " << x.transpose();
    EXPECT_TRUE(alg_ok) << x.transpose();
    EXPECT_LE(m.spectral_radius(x), rho_max);
  }
  EXPECT_GT(inside, 100);
}

// From rest the model is stiff (start-up: ρ far above 800/s): no box, and the observer
// takes its substeps on the general path's count.
TEST(CompiledUsualTick, NoCertificateAtAStiffPoint) {
  const Model m(params<double>(), inputs<double>());
  const Model::State x = m.rest_state();
  const double h = 1e-3, rho_max = 0.8 / h;
  ASSERT_GT(m.spectral_radius(x), rho_max);
  EXPECT_FALSE(m.usual_tick_coeffs(h, rho_max, x).certified);
  Model::Output y;
  Model::State dx;
  EXPECT_FALSE(m.usual_tick(m.usual_tick_coeffs(h, rho_max, x), x, y, dx));
}

// Outside its box the usual tick declines and writes nothing.
TEST(CompiledUsualTick, DeclinesOutsideItsBox) {
  const Model m(params<double>(), inputs<double>());
  Model::State x0;
  ASSERT_TRUE(m.steady_state(x0));
  const auto c = m.usual_tick_coeffs(1e-3, 800.0, x0);
  ASSERT_TRUE(c.certified);
  Model::Output y = Model::Output::Constant(-7.0);
  Model::State dx = Model::State::Constant(-7.0);
  Model::State x = x0;
  x[1] = c.x_hi[1] + 1.0;
  EXPECT_FALSE(m.usual_tick(c, x, y, dx));
  x = x0;
  x[0] = std::nan("");
  EXPECT_FALSE(m.usual_tick(c, x, y, dx));
  EXPECT_EQ(y, Model::Output::Constant(-7.0));
  EXPECT_EQ(dx, Model::State::Constant(-7.0));
  EXPECT_TRUE(m.usual_tick(c, x0, y, dx));
}

}  // namespace
