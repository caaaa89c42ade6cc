// The model bound in place (ModelBound::compute_in_place: the firmware monitor's, no model
// copy on the stack) gives the copy's bound bit for bit and leaves the model as the copy's
// bound leaves it: values, warm start and every later evaluation, on every shipped circuit
// and on the compiled thesis model.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "circuit_fixture.hpp"
#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/compiled_bound.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"

namespace {

using circuit_test::Model;
using Bound = hstmon::ModelBound<Model>;

template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Every uncertain parameter of l at ±2 % (capacitances and inertias too: more solves).
Bound::Uncertainty two_percent(const circuit_test::Loaded& l) {
  Bound::Uncertainty eps;
  for (int k = 0; k < l.file.circuit.n_params; ++k) eps.rel[k] = 0.02;
  return eps;
}

// The outputs and rates of m at its steady state and at rest, as raw values.
struct Evaluations {
  Model::Output y_steady{}, y_rest{};
  Model::State d_steady{}, d_rest{};
  bool steady = false;
};
Evaluations evaluate(const Model& m) {
  Evaluations e;
  Model::State xs;
  e.steady = m.steady_state(xs);
  if (e.steady) e.d_steady = m.derivative(xs, &e.y_steady);
  e.d_rest = m.derivative(m.rest_state(), &e.y_rest);
  return e;
}

class BoundInPlace : public ::testing::TestWithParam<std::string> {};

TEST_P(BoundInPlace, SameBoundAndTheModelAsTheCopyLeavesIt) {
  const auto l = circuit_test::load(GetParam(), 1e-3);
  ASSERT_TRUE(l.ok);
  const Bound::Uncertainty eps = two_percent(l);
  Model by_copy = circuit_test::model_of(l);
  Model in_place = circuit_test::model_of(l);
  double m_copy[Bound::kN] = {}, m_place[Bound::kN] = {};
  double tau_copy = -1.0, tau_place = -1.0;
  hstmon::circuit::BoundLead<double, Bound::kN> lead_copy, lead_place;
  const auto s_copy = Bound::compute(by_copy, eps, m_copy, &tau_copy, &lead_copy);
  const auto s_place = Bound::compute_in_place(in_place, eps, m_place, &tau_place, &lead_place);
  ASSERT_EQ(s_copy, s_place);
  for (int i = 0; i < Bound::kN; ++i) {
    EXPECT_TRUE(same_bits(m_copy[i], m_place[i])) << "channel " << i << ": " << m_copy[i] << " vs " << m_place[i];
    EXPECT_EQ(lead_copy.param[i], lead_place.param[i]);
  }
  EXPECT_TRUE(same_bits(tau_copy, tau_place)) << tau_copy << " vs " << tau_place;
  EXPECT_TRUE(same_bits(by_copy.params(), in_place.params()));
  for (int j = 0; j < in_place.n_stiff(); ++j) EXPECT_TRUE(same_bits(by_copy.warm_start(j), in_place.warm_start(j)));
  const Evaluations a = evaluate(by_copy), b = evaluate(in_place);
  EXPECT_EQ(a.steady, b.steady);
  EXPECT_TRUE(same_bits(a.y_steady, b.y_steady));
  EXPECT_TRUE(same_bits(a.d_steady, b.d_steady));
  EXPECT_TRUE(same_bits(a.y_rest, b.y_rest));
  EXPECT_TRUE(same_bits(a.d_rest, b.d_rest));
}

INSTANTIATE_TEST_SUITE_P(Shipped, BoundInPlace, ::testing::Values("thesis", "paper", "closed_loop_hst", "test_stand"));

TEST(BoundInPlace, CompiledModelIsTheInterpretersBound) {
  using Compiled = hstmon::generated::thesis_circuit::CompiledModel<double>;
  using CB = hstmon::ModelBound<Compiled>;
  Compiled::Params p;
  for (int k = 0; k < Compiled::Cap::kParams; ++k) p.v[k] = hstmon::generated::thesis_circuit::kParams[k];
  Compiled::Inputs u;
  for (int i = 0; i < Compiled::Cap::kInputs; ++i) u.v[i] = hstmon::generated::thesis_circuit::kInputs[i];
  Compiled in_place(p, u);
  Compiled by_copy(p, u);
  CB::Uncertainty eps;
  for (int k = 0; k < Compiled::Cap::kParams; ++k) eps.rel[k] = hstmon::generated::thesis_circuit::kUncertainty[k];
  double m_copy[CB::kN] = {}, m_place[CB::kN] = {};
  ASSERT_EQ(CB::compute(by_copy, eps, m_copy), hstmon::Status::kOk);
  ASSERT_EQ(CB::compute_in_place(in_place, eps, m_place), hstmon::Status::kOk);
  double sum = 0.0;
  for (int i = 0; i < CB::kN; ++i) {
    EXPECT_TRUE(same_bits(m_copy[i], m_place[i])) << "channel " << i;
    sum += m_place[i];
  }
  EXPECT_GT(sum, 0.0);
  // Both compiled models evaluate alike afterwards.
  Compiled::State xa, xb;
  ASSERT_TRUE(by_copy.steady_state(xa));
  ASSERT_TRUE(in_place.steady_state(xb));
  EXPECT_TRUE(same_bits(xa, xb));
  Compiled::Output ya, yb;
  const auto da = by_copy.derivative(xa, &ya);
  const auto db = in_place.derivative(xb, &yb);
  EXPECT_TRUE(same_bits(da, db));
  EXPECT_TRUE(same_bits(ya, yb));
}

}  // namespace
