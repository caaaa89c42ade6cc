// The committed compiled model of thesis.json (lib/circuit/include/hstmon/generated/
// thesis_circuit_compiled.hpp) equals the interpreting CircuitModel on the committed
// description: at Table 2.2, with kp halved, from rest, and observer runs at 1 ms and
// 10 ms (compiled_equality.hpp). The other shipped circuits: test_compiled_shipped.
#include <gtest/gtest.h>

#include "compiled_equality.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"

namespace {

namespace gen = hstmon::generated::thesis_circuit;
using Model = gen::CompiledModel<double>;

Model::Params params() {
  Model::Params p;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = gen::kParams[i];
  return p;
}

Model::Inputs inputs(double kp_scale = 1.0) {
  Model::Inputs u;
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = gen::kInputs[i];
  u.v[3] *= kp_scale;  // kp, the PRV's flow coefficient
  return u;
}

static_assert(hstmon::is_observer_model_v<Model>, "the compiled model is an observer model");

TEST(CompiledThesis, EqualsTheInterpreterAtTable22) {
  compiled_equality::expect_same_model<gen::Kernel>(params(), inputs(), inputs(0.5), 1e-3);
}

TEST(CompiledThesis, EqualsTheInterpreterWithKpHalved) {
  compiled_equality::expect_same_model<gen::Kernel>(params(), inputs(0.5), inputs(), 1e-3);
}

TEST(CompiledThesis, EqualsTheInterpreterAtATenMsTick) {
  compiled_equality::expect_same_model<gen::Kernel>(params(), inputs(), inputs(0.5), 1e-2);
}

TEST(CompiledThesis, FloatAgreesBitForBit) {
  // The firmware's scalar: the same float operations in the same order.
  using F = gen::CompiledModel<float>;
  using E = F::Engine;
  F::Params p;
  F::Inputs u;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = static_cast<float>(gen::kParams[i]);
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = static_cast<float>(gen::kInputs[i]);
  const E e(gen::kCircuit, p, u);
  const F c(p, u);
  E::State x;
  ASSERT_TRUE(e.steady_state(x));
  F::State xc;
  ASSERT_TRUE(c.steady_state(xc));
  for (int s = 0; s < 2; ++s) EXPECT_EQ(xc[s], x[s]);
  x[0] += 1e5f;
  const E::State de = e.derivative(x), dc = c.derivative(x);
  for (int s = 0; s < 2; ++s) EXPECT_EQ(dc[s], de[s]);
}

TEST(CompiledThesis, ConfiguresFromParametersAlone) {
  // Observer::configure(p, cfg): the model binds its own circuit on set_params.
  hstmon::Observer<Model> a, b;
  hstmon::Observer<Model>::Config cfg;
  ASSERT_EQ(a.configure(params(), cfg), hstmon::Status::kOk);
  ASSERT_EQ(b.configure(gen::kCircuit, params(), cfg), hstmon::Status::kOk);
  EXPECT_TRUE(a.model().valid());
  ASSERT_EQ(a.reset_steady(inputs()), hstmon::Status::kOk);
  ASSERT_EQ(b.reset_steady(inputs()), hstmon::Status::kOk);
  EXPECT_EQ(a.state()[0], b.state()[0]);
  EXPECT_EQ(a.state()[1], b.state()[1]);
}

TEST(CompiledThesis, RefusesAnotherDescription) {
  const auto other = gen::kCircuit;  // a copy: not the circuit the code was generated for
  Model m;
  EXPECT_EQ(m.bind(other), hstmon::circuit::CircuitError::kUnbound);
  EXPECT_EQ(m.bind(gen::kCircuit), hstmon::circuit::CircuitError::kOk);
}

}  // namespace
