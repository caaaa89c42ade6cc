#pragma once
// A compiled model's fused usual tick (CompiledModel::usual_tick, behind its certified
// stiffness box) against its general tick (Observer<Model, false>): the same arithmetic,
// so bit for bit the same states, estimates, residuals and health — from a steady start
// with an input change, from rest (stiff: substeps), and at ten times the tick.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "hstmon/circuit/compiled_model.hpp"
#include "hstmon/observer.hpp"

namespace usual_tick_equality {

/// Ticks of each run, and how many the usual tick took.
struct Taken {
  long ticks = 0;
  long usual = 0;
};

/// Both observers at tick h from a steady start (or rest) under u, u2 from half-way, for
/// `seconds`, measuring the general observer's first estimate with alternating offsets.
template <typename T, class Kernel, class Model = hstmon::circuit::CompiledModel<T, Kernel>>
Taken run(const typename Model::Params& p, const typename Model::Inputs& u, const typename Model::Inputs& u2, T h,
          double seconds, bool from_rest) {
  using Fused = hstmon::Observer<Model, true>;
  using General = hstmon::Observer<Model, false>;
  Fused of;
  General og;
  typename Fused::Config cf;
  typename General::Config cg;
  cf.tick = cg.tick = h;
  Taken taken;
  EXPECT_EQ(of.configure(Kernel::description(), p, cf), hstmon::Status::kOk);
  EXPECT_EQ(og.configure(Kernel::description(), p, cg), hstmon::Status::kOk);
  if (from_rest) {
    EXPECT_EQ(of.reset_rest(u), hstmon::Status::kOk);
    EXPECT_EQ(og.reset_rest(u), hstmon::Status::kOk);
  } else {
    if (of.reset_steady(u) != hstmon::Status::kOk) return taken;  // no steady state: nothing to compare
    EXPECT_EQ(og.reset_steady(u), hstmon::Status::kOk);
  }
  const auto y0 = og.estimate();
  const long n = std::lround(seconds / static_cast<double>(h));
  for (long k = 0; k < n; ++k) {
    const auto& uk = 2 * k < n ? u : u2;
    typename General::Measurement m;
    for (int ch = 0; ch < Model::kOutputs; ++ch) m.y[ch] = y0[ch] * (T(1) + ((k & 1) ? T(1e-3) : T(-1e-3)));
    m.valid = static_cast<std::uint8_t>((1u << Kernel::description().n_channels) - 1u);
    const std::uint32_t hf = of.step(uk, m);
    const std::uint32_t hg = og.step(uk, m);
    EXPECT_EQ(hf, hg) << "health at tick " << k;
    EXPECT_EQ(of.substeps(), og.substeps()) << "substeps at tick " << k;
    for (int s = 0; s < Model::kStates; ++s) EXPECT_EQ(of.state()[s], og.state()[s]) << "state " << s << " tick " << k;
    for (int ch = 0; ch < Model::kOutputs; ++ch) {
      EXPECT_EQ(of.estimate()[ch], og.estimate()[ch]) << "estimate " << ch << " tick " << k;
      EXPECT_EQ(of.residual()[ch], og.residual()[ch]) << "residual " << ch << " tick " << k;
    }
    if (::testing::Test::HasFailure()) break;  // one tick's report is enough
  }
  taken.ticks = n;
  taken.usual = static_cast<long>(of.usual_ticks());
  return taken;
}

/// The three runs; returns the steady run's counts (where the usual tick should serve).
template <typename T, class Kernel, class Model = hstmon::circuit::CompiledModel<T, Kernel>>
Taken expect_same(const typename Model::Params& p, const typename Model::Inputs& u, const typename Model::Inputs& u2,
                  T h) {
  {
    SCOPED_TRACE("from rest");
    (void)run<T, Kernel>(p, u, u2, h, 0.5, true);
  }
  {
    SCOPED_TRACE("ten times the tick");
    (void)run<T, Kernel>(p, u, u2, T(10) * h, 2.0, false);
  }
  SCOPED_TRACE("steady start, input change");
  return run<T, Kernel>(p, u, u2, h, 2.0, false);
}

}  // namespace usual_tick_equality
