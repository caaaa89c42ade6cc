#pragma once
// The compiled model of a generated circuit (hstmon-circuit-header --compiled) against the
// interpreting CircuitModel on the same description and values: derivative, outputs,
// tick_derivative (rho, alg_ok), Jacobian and steady state at a few states, and a 2-s
// observer run with an input change, to 1e-12 relative (in practice they agree bit for bit,
// but for the sign of a zero sum: the same laws, the same solve, sums in the same order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hstmon/circuit/compiled_model.hpp"
#include "hstmon/observer.hpp"

namespace compiled_equality {

namespace circuit = hstmon::circuit;

inline ::testing::AssertionResult close(double a, double b) {
  if (a == b || std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b))) return ::testing::AssertionSuccess();
  if (std::isnan(a) && std::isnan(b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (rel " << std::fabs(a - b) / std::fabs(b) << ")";
}

template <class V>
void expect_close(const V& a, const V& b, const char* what) {
  for (int i = 0; i < a.size(); ++i) EXPECT_TRUE(close(a[i], b[i])) << what << "[" << i << "]";
}

/// Every evaluation at state x, with both models warm-started alike.
template <class Eng, class Cmp>
void expect_same_at(const Eng& e, const Cmp& c, const typename Eng::State& x, const char* where) {
  SCOPED_TRACE(where);
  typename Eng::Output ye, yc;
  expect_close(c.derivative(x, &yc), e.derivative(x, &ye), "derivative");
  expect_close(yc, ye, "derivative's outputs");
  expect_close(c.outputs(x), e.outputs(x), "outputs");
  for (const double rho_max : {0.0, 800.0, 1e9}) {
    double re = -1.0, rc = -1.0;
    bool oke = false, okc = true;
    expect_close(c.tick_derivative(x, rho_max, yc, rc, okc), e.tick_derivative(x, rho_max, ye, re, oke),
                 "tick_derivative");
    expect_close(yc, ye, "tick_derivative's outputs");
    EXPECT_TRUE(close(rc, re)) << "rho at rho_max " << rho_max;
    EXPECT_EQ(okc, oke) << "alg_ok at rho_max " << rho_max;
  }
  typename Eng::StateMatrix je, jc;
  e.jacobian(x, je);
  c.jacobian(x, jc);
  for (int r = 0; r < je.rows(); ++r) {
    for (int k = 0; k < je.cols(); ++k) EXPECT_TRUE(close(jc(r, k), je(r, k))) << "jacobian " << r << "," << k;
  }
  EXPECT_TRUE(close(c.spectral_radius(x), e.spectral_radius(x))) << "spectral radius";
}

/// The models on description d with values p and inputs u: rest, steady state, states
/// around it, then the observer at `tick` for 2 s with u2 from 1 s.
template <class Kernel>
void expect_same_model(const typename circuit::CompiledModel<double, Kernel>::Params& p,
                       const typename circuit::CompiledModel<double, Kernel>::Inputs& u,
                       const typename circuit::CompiledModel<double, Kernel>::Inputs& u2, double tick) {
  using Cmp = circuit::CompiledModel<double, Kernel>;
  using Eng = typename Cmp::Engine;
  Eng e(Kernel::description(), p, u);
  Cmp c(p, u);
  ASSERT_TRUE(e.valid());
  ASSERT_TRUE(c.valid());
  ASSERT_EQ(c.n_states(), Kernel::kN);
  expect_close(c.rest_state(), e.rest_state(), "rest state");
  expect_same_at(e, c, e.rest_state(), "from rest");
  typename Eng::State xe, xc;
  ASSERT_EQ(c.steady_state(xc), e.steady_state(xe));
  expect_close(xc, xe, "steady state");
  expect_same_at(e, c, xe, "steady state");
  for (int s = 0; s < Kernel::kN; ++s) {
    typename Eng::State x = xe;
    x[s] = x[s] * 1.05 + (Kernel::kStateZ[s] < Kernel::Cap::kNodes ? 2e5 : 3.0);
    expect_same_at(e, c, x, "steady state moved");
  }

  // The observer on each, from the steady state, measuring the interpreter's own outputs
  // with alternating offsets; u2 from 1 s.
  using Oe = hstmon::Observer<Eng>;
  using Oc = hstmon::Observer<Cmp>;
  Oe oe;
  Oc oc;
  typename Oe::Config ce;
  ce.tick = tick;
  typename Oc::Config cc;
  cc.tick = tick;
  ASSERT_EQ(oe.configure(Kernel::description(), p, ce), hstmon::Status::kOk);
  ASSERT_EQ(oc.configure(Kernel::description(), p, cc), hstmon::Status::kOk);
  ASSERT_EQ(oe.reset_steady(u), hstmon::Status::kOk);
  ASSERT_EQ(oc.reset_steady(u), hstmon::Status::kOk);
  const int n = static_cast<int>(std::lround(2.0 / tick));
  const typename Eng::Output y0 = oe.estimate();
  for (int k = 0; k < n; ++k) {
    const auto& uk = k * tick < 1.0 ? u : u2;
    typename Oe::Measurement m;
    for (int ch = 0; ch < Eng::kOutputs; ++ch) m.y[ch] = y0[ch] * (1.0 + ((k & 1) ? 1e-3 : -1e-3));
    m.valid = static_cast<std::uint8_t>((1u << c.n_outputs()) - 1u);
    const std::uint32_t he = oe.step(uk, m);
    const std::uint32_t hc = oc.step(uk, m);
    ASSERT_EQ(hc, he) << "health at tick " << k;
    for (int s = 0; s < Kernel::kN; ++s) ASSERT_TRUE(close(oc.state()[s], oe.state()[s])) << "state " << s << " tick " << k;
    for (int ch = 0; ch < Eng::kOutputs; ++ch) {
      ASSERT_TRUE(close(oc.residual()[ch], oe.residual()[ch])) << "residual " << ch << " tick " << k;
    }
  }
}

}  // namespace compiled_equality
