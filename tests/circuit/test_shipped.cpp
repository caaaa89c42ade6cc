// The shipped circuits (examples/circuits): each reads with its parameter file, yields a
// steady state, and a quasi-steady solve that contracts — a-priori over the envelope
// (contraction_bound) and at the states a start-up passes through (contraction_factor).
// paper.json through the engine equals the hand-written PaperModel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "circuit_fixture.hpp"
#include "hstmon/observer.hpp"
#include "hstmon/paper_model.hpp"

namespace {

using circuit_test::Loaded;
using circuit_test::Model;

const char* const kShipped[] = {"thesis", "paper", "closed_loop_hst", "test_stand"};

TEST(ShippedCircuits, SteadyStatesAndContraction) {
  for (const char* name : kShipped) {
    for (double tick : {1e-3, 1e-2}) {
      const Loaded l = circuit_test::load(name, tick);
      ASSERT_TRUE(l.ok) << name;
      const Model m = circuit_test::model_of(l);
      ASSERT_TRUE(m.valid()) << name;
      EXPECT_LT(m.contraction_bound(), 0.5) << name;
      Model::State x;
      ASSERT_TRUE(m.steady_state(x)) << name;
      const Model::Output y = m.outputs(x);
      std::printf("%-16s %2.0f ms: %d states, %d stiff, bound %.1e, rho(steady) %.3g 1/s, steady:", name, tick * 1e3,
                  m.n_states(), m.n_stiff(), m.contraction_bound(), m.spectral_radius(x));
      for (int c = 0; c < m.n_outputs(); ++c) std::printf(" %s %.6g", l.file.sensors[static_cast<std::size_t>(c)].name.c_str(), y[c]);
      std::printf("\n");
      // The steady state is one: the state equations vanish there.
      const Model::State d = m.derivative(x);
      for (int s = 0; s < m.n_states(); ++s) {
        const double scale = m.state_z(s) < Model::kNodes ? m.pressure_envelope() : m.speed_envelope();
        EXPECT_LT(std::fabs(d[s]) / scale, 1e-6) << name << " state " << s;
      }
    }
  }
}

TEST(ShippedCircuits, LocalContractionAlongStartUps) {
  // Every circuit at the tick that gives it stiff nodes: the local factor (Jacobi's
  // ∞-norm factor of the stiff block) at every state of a start from rest, and the solve
  // converged there.
  for (const char* name : kShipped) {
    for (double tick : {1e-3, 1e-2}) {
      const Loaded l = circuit_test::load(name, tick);
      ASSERT_TRUE(l.ok);
      Model m = circuit_test::model_of(l);
      if (m.n_stiff() == 0) continue;
      hstmon::Observer<Model, false> o;
      hstmon::Observer<Model, false>::Config cfg;
      cfg.tick = tick;
      ASSERT_EQ(o.configure(m, cfg), hstmon::Status::kOk);
      ASSERT_EQ(o.reset_rest(l.values.inputs), hstmon::Status::kOk);
      double worst = 0;
      bool all_converged = true;
      hstmon::Observer<Model, false>::Measurement none;
      for (int k = 0; k < static_cast<int>(2.0 / tick); ++k) {
        o.step(l.values.inputs, none);
        worst = std::fmax(worst, o.model().contraction_factor(o.state()));
        double z[Model::kZ];
        all_converged = o.model().full_vector(o.state(), z) && all_converged;
      }
      std::printf("%-16s %2.0f ms: %d stiff nodes, local contraction factor <= %.2e over 2 s from rest (bound %.2e)\n", name,
                  tick * 1e3, m.n_stiff(), worst, m.contraction_bound());
      EXPECT_LT(worst, 0.5) << name;
      EXPECT_TRUE(all_converged) << name;
      EXPECT_EQ(o.health() & hstmon::kHealthAlgebraicDiverged, 0u) << name;
    }
  }
}

TEST(ShippedCircuits, PaperEqualsPaperModel) {
  Loaded l = circuit_test::load("paper", 1e-3);
  ASSERT_TRUE(l.ok);
  l.file.circuit.stiff_mask = 0;  // every pressure a state, as PaperModel has them
  const Model m = circuit_test::model_of(l);
  ASSERT_EQ(m.n_states(), 4);
  hstmon::PaperModel<double> p;  // Table I
  const double states[][4] = {{0, 0, 0, 0}, {8.0e6, 6.0e6, 3.0e6, 80.0}, {8.9e6, 8.8e6, 7.0e6, 10.0}, {5e6, 2e6, 1e6, 150.0}};
  double worst = 0;
  for (const auto& s : states) {
    Model::State x = Model::State::Zero();
    for (int i = 0; i < 4; ++i) x[i] = s[i];
    // Engine state order: Ps, Pmi, Ppp, ωm — PaperModel's.
    const Model::State d = m.derivative(x);
    const hstmon::PaperModel<double>::State dp = p.derivative(hstmon::PaperModel<double>::State(s[0], s[1], s[2], s[3]));
    for (int i = 0; i < 4; ++i) {
      const double scale = i < 3 ? 1e11 * 2e-4 : 6.74e-7 * 9e6 / 0.015;  // K·Q0, Dm·Pmax/J
      worst = std::fmax(worst, std::fabs(d[i] - dp[i]) / scale);
    }
  }
  std::printf("paper engine vs PaperModel: derivatives %.2e (relative)\n", worst);
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
