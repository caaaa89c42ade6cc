// thesis.json through the engine against the hand-written ThesisReducedModel: the stiff
// nodes it picks, outputs and derivatives at several states, steady states at Table 2.2
// and with kp halved, and an observer on each over a start from rest and a kp step.
#include <gtest/gtest.h>

#include <cmath>

#include "circuit_fixture.hpp"
#include "hstmon/observer.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace {

using circuit_test::Loaded;
using circuit_test::Model;
using Hand = hstmon::ThesisReducedModel<double>;

/// Hand-written inputs matching the engine's (by name).
Hand::Inputs hand_inputs(const Loaded& l, const Model::Inputs& u) {
  Hand::Inputs h;
  h.Psupl = u.v[l.file.input_index("Psupl")];
  h.Ps = u.v[l.file.input_index("Ps")];
  h.Pbp = u.v[l.file.input_index("Pbp")];
  h.kp = u.v[l.file.input_index("kp")];
  return h;
}

double rel(double a, double b, double scale) { return std::fabs(a - b) / scale; }

TEST(ThesisCircuit, PicksTheDcvPressuresAsStiff) {
  for (double tick : {1e-3, 1e-2}) {
    const Loaded l = circuit_test::load("thesis", tick);
    ASSERT_TRUE(l.ok);
    const int pmi = l.file.node_index("Pmi"), pmo = l.file.node_index("Pmo");
    EXPECT_EQ(l.file.circuit.stiff_mask, (1u << pmi) | (1u << pmo)) << "tick " << tick;
    const Model m = circuit_test::model_of(l);
    ASSERT_TRUE(m.valid());
    EXPECT_EQ(m.n_states(), 2);  // (Ppp, ωm), the hand-written model's states
    EXPECT_EQ(m.state_z(0), l.file.node_index("Ppp"));
    // A-priori contraction of the DCV solve over the whole envelope: the cross-port
    // leakage against the DCV orifice at 400 bar.
    EXPECT_LT(m.contraction_bound(), 1e-8);
  }
}

TEST(ThesisCircuit, OutputsAndDerivativesEqualTheHandWrittenModel) {
  const Loaded l = circuit_test::load("thesis", 1e-3);
  ASSERT_TRUE(l.ok);
  Model m = circuit_test::model_of(l);
  Hand h;  // Table 2.2
  h.set_inputs(hand_inputs(l, l.values.inputs));
  const double states[][2] = {{1.0e6, 0.0},   {1.710822e7, 175.6867}, {1.2e7, 120.0}, {2.0e7, 60.0},
                              {1.05e6, 5.0},  {1.0e6, 300.0},         {3.0e7, 200.0}, {1.1e6, 0.5}};
  double worst_y = 0, worst_d = 0;
  for (const auto& s : states) {
    Model::State x = Model::State::Zero();
    x[0] = s[0];
    x[1] = s[1];
    const Hand::State xh(s[0], s[1]);
    Model::Output y;
    Hand::Output yh;
    const Model::State d = m.derivative(x, &y);
    const Hand::State dh = h.derivative(xh, &yh);
    for (int c = 0; c < 4; ++c) {
      const double scale = c < 3 ? 3.5e6 : 1.0;  // pressures against the supply, speed in rad/s
      worst_y = std::fmax(worst_y, rel(y[c], yh[c], std::fmax(std::fabs(yh[c]), scale)));
    }
    // Rates against the size of their largest term (they cancel at a steady state).
    worst_d = std::fmax(worst_d, rel(d[0], dh[0], 1e14 * 1.00745e-6 * (std::fabs(s[1]) + 1.0)));
    worst_d = std::fmax(worst_d, rel(d[1], dh[1], 7.96e-6 / 1e-3 * 3.5e6));
  }
  EXPECT_LT(worst_y, 1e-12);
  EXPECT_LT(worst_d, 1e-12);
  std::printf("thesis engine vs hand-written: outputs %.2e, derivatives %.2e (relative)\n", worst_y, worst_d);
}

TEST(ThesisCircuit, SteadyStatesEqualTheHandWrittenModel) {
  const Loaded l = circuit_test::load("thesis", 1e-3);
  ASSERT_TRUE(l.ok);
  Model m = circuit_test::model_of(l);
  for (double kp_scale : {1.0, 0.5}) {
    Model::Inputs u = l.values.inputs;
    u.v[l.file.input_index("kp")] *= kp_scale;
    m.set_inputs(u);
    Hand h;
    h.set_inputs(hand_inputs(l, u));
    Model::State x;
    Hand::State xh;
    ASSERT_TRUE(m.steady_state(x));
    ASSERT_TRUE(h.steady_state(xh));
    const Model::Output y = m.outputs(x);
    const Hand::Output yh = h.outputs(xh);
    for (int c = 0; c < 4; ++c) {
      EXPECT_LT(std::fabs(y[c] - yh[c]) / std::fabs(yh[c]), 1e-6) << "kp x" << kp_scale << " channel " << c;
    }
    std::printf("kp x%.1f: Pmi %.7e Pmo %.7e Ppp %.7e wm %.7f (hand %.7e %.7e %.7e %.7f)\n", kp_scale, y[0], y[1], y[2],
                y[3], yh[0], yh[1], yh[2], yh[3]);
  }
  // docs/equations.md's independent Newton solve of 2.5–2.8.
  m.set_inputs(l.values.inputs);
  Model::State x;
  ASSERT_TRUE(m.steady_state(x));
  const Model::Output y = m.outputs(x);
  EXPECT_NEAR(y[0] / 3.312079e6, 1.0, 1e-6);
  EXPECT_NEAR(y[1] / 1.879209e5, 1.0, 1e-6);
  EXPECT_NEAR(y[2] / 1.710822e7, 1.0, 1e-6);
  EXPECT_NEAR(y[3] / 175.6867, 1.0, 1e-6);
}

/// Max relative difference of the two observers' estimates over a start from rest and a
/// kp step (kp halved at t_step), per channel scale; substep counts compared too.
void compare_observers(double tick, double& worst, int& substep_mismatch, int& max_sub) {
  const Loaded l = circuit_test::load("thesis", tick);
  ASSERT_TRUE(l.ok);
  using EObs = hstmon::Observer<Model, false>;
  using HObs = hstmon::Observer<Hand, false>;
  EObs eo;
  HObs ho;
  EObs::Config ec;
  HObs::Config hc;
  ec.tick = hc.tick = tick;
  // The hand-written model has no Jacobian, so its observer takes RK4 substeps on stiff
  // ticks too: the engine's does the same here, since this compares the models.
  ec.implicit_above = 0;
  ASSERT_EQ(eo.configure(circuit_test::model_of(l), ec), hstmon::Status::kOk);
  ASSERT_EQ(ho.configure(Hand{}, hc), hstmon::Status::kOk);
  Model::Inputs u = l.values.inputs;
  ASSERT_EQ(eo.reset_rest(u), hstmon::Status::kOk);
  ASSERT_EQ(ho.reset_rest(hand_inputs(l, u)), hstmon::Status::kOk);
  const int n = static_cast<int>(std::lround(3.0 / tick));
  const double scale[4] = {3.5e6, 3.5e6, 2.3e7, 180.0};
  worst = 0;
  substep_mismatch = 0;
  max_sub = 0;
  EObs::Measurement em;
  HObs::Measurement hm;
  for (int i = 0; i < n; ++i) {
    if (i == n / 2) u.v[l.file.input_index("kp")] *= 0.5;
    eo.step(u, em);
    ho.step(hand_inputs(l, u), hm);
    for (int c = 0; c < 4; ++c) worst = std::fmax(worst, std::fabs(eo.estimate()[c] - ho.estimate()[c]) / scale[c]);
    substep_mismatch += eo.substeps() != ho.substeps();
    max_sub = std::max<int>(max_sub, eo.substeps());
  }
  EXPECT_EQ(eo.health() & ~static_cast<std::uint32_t>(hstmon::kHealthStateOutOfBounds), 0u);
}

// The observers on the engine and on the hand-written model at a `tick` [s] agree.
void expect_observers_match(double tick) {
  double worst;
  int mismatch, max_sub;
  compare_observers(tick, worst, mismatch, max_sub);
  std::printf("%g ms: worst estimate difference %.2e of scale, substep mismatches %d, max substeps %d\n", tick * 1e3,
              worst, mismatch, max_sub);
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(mismatch, 0);
}

TEST(ThesisCircuit, ObserverMatchesTheHandWrittenOneAt1ms) { expect_observers_match(1e-3); }

TEST(ThesisCircuit, ObserverMatchesTheHandWrittenOneAt10ms) { expect_observers_match(1e-2); }

}  // namespace
