// The generator works for every shipped circuit: the compiled models of paper.json (5 ms),
// closed_loop_hst.json and test_stand.json (1 ms), generated at build time into the build
// tree (tests/circuit/CMakeLists.txt), equal the interpreting CircuitModel on the same
// description (compiled_equality.hpp): nominal inputs, the first input at 90 % from 1 s; and
// their fused usual tick equals their general tick bit for bit (usual_tick_equality.hpp).
// And test_stand.json with sensors on the drive speed and the tank, which the compiled
// outputs read from the engine rather than from the integrated vector.
#include <gtest/gtest.h>

#include <cstdio>

#include "compiled_equality.hpp"
#include "hstmon/generated/test_closed_loop_hst_compiled.hpp"
#include "hstmon/generated/test_paper_compiled.hpp"
#include "hstmon/generated/test_stand_fixed_sensors_compiled.hpp"
#include "hstmon/generated/test_test_stand_compiled.hpp"
#include "usual_tick_equality.hpp"

namespace {

/// The generated header's values as the compiled model's parameters and inputs.
template <class Model, std::size_t P, std::size_t I>
void values(const double (&params)[P], const double (&inputs)[I], typename Model::Params& p,
            typename Model::Inputs& u) {
  for (std::size_t i = 0; i < P; ++i) p.v[i] = params[i];
  for (std::size_t i = 0; i < I; ++i) u.v[i] = inputs[i];
}

template <class Kernel, std::size_t P, std::size_t I>
void check(const double (&params)[P], const double (&inputs)[I], double tick) {
  using Model = hstmon::circuit::CompiledModel<double, Kernel>;
  static_assert(hstmon::is_observer_model_v<Model>, "an observer model");
  typename Model::Params p;
  typename Model::Inputs u;
  values<Model>(params, inputs, p, u);
  typename Model::Inputs u2 = u;
  u2.v[0] = u.v[0] * 0.9;
  compiled_equality::expect_same_model<Kernel>(p, u, u2, tick);
  // The fused usual tick (hosts) against the general tick (firmware): bit for bit.
  const auto taken = usual_tick_equality::expect_same<double, Kernel>(p, u, u2, tick);
  std::printf("usual tick: %ld of %ld steady-run ticks\n", taken.usual, taken.ticks);
}

TEST(CompiledShipped, Paper) {
  namespace g = hstmon::generated::test_paper;
  check<g::Kernel>(g::kParams, g::kInputs, g::kTick);
}

TEST(CompiledShipped, ClosedLoopHst) {
  namespace g = hstmon::generated::test_closed_loop_hst;
  check<g::Kernel>(g::kParams, g::kInputs, g::kTick);
}

TEST(CompiledShipped, TestStand) {
  namespace g = hstmon::generated::test_test_stand;
  check<g::Kernel>(g::kParams, g::kInputs, g::kTick);
}

TEST(CompiledShipped, SensorsOnFixedEntries) {
  namespace g = hstmon::generated::test_stand_fixed_sensors;
  static_assert(g::Cap::kChannels == 4, "p_line, q, n_drive, p_tank");
  check<g::Kernel>(g::kParams, g::kInputs, g::kTick);
  // The drive-speed channel reads the input n_drive [rad/s], the tank channel the boundary.
  using Model = hstmon::circuit::CompiledModel<double, g::Kernel>;
  typename Model::Params p;
  typename Model::Inputs u;
  values<Model>(g::kParams, g::kInputs, p, u);
  ASSERT_STREQ(g::kInputNames[0], "n_drive");
  const Model m(p, u);
  const auto y = m.outputs(m.rest_state());
  EXPECT_GT(u.v[0], 0.0);
  EXPECT_EQ(y[2], u.v[0]);
  EXPECT_EQ(y[3], 0.0);
}

}  // namespace
