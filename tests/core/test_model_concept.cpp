// The model concept as code (model_concept.hpp): the shipped models satisfy it, a model
// without a piece does not, and the tiny example model runs in the Observer to the exact
// solution of its linear ODE.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon/model_concept.hpp"
#include "hstmon/observer.hpp"
#include "hstmon/paper_model.hpp"
#include "hstmon/thesis_reduced.hpp"
#include "tiny_model.hpp"

namespace {

using Tiny = hstmon_test::TinyNodeModel<double>;

struct NoTickDerivative {  // a model that forgot tick_derivative
  using Scalar = double;
  static constexpr int kStates = 1, kOutputs = 1;
  using State = Eigen::Matrix<double, 1, 1>;
  using Output = State;
  struct Inputs {};
  static bool inputs_valid(const Inputs&) { return true; }
  void set_inputs(const Inputs&) {}
  Inputs inputs() const { return {}; }
  Output outputs(const State& x) const { return x; }
  State rest_state() const { return State::Zero(); }
  bool steady_state(State&) const { return false; }
  bool state_plausible(const State&) const { return true; }
  int state_channel(int) const { return 0; }
  State derivative(const State& x) const { return -x; }
};

static_assert(hstmon::is_observer_model_v<hstmon::ThesisReducedModel<float>>);
static_assert(hstmon::is_observer_model_v<hstmon::ThesisReducedModel<double>>);
static_assert(hstmon::is_observer_model_v<hstmon::PaperModel<double>>);
static_assert(hstmon::is_observer_model_v<Tiny>);
static_assert(hstmon::is_observer_model_v<hstmon_test::TinyNodeModel<float>>);
static_assert(!hstmon::is_observer_model_v<NoTickDerivative>);
static_assert(hstmon::ObserverModelParts<NoTickDerivative>::kStates);
static_assert(!hstmon::ObserverModelParts<NoTickDerivative>::kDerivatives);
static_assert(!hstmon::is_observer_model_v<int>);

// From rest, a 1 s time constant, 10 ms ticks: the observer follows Q·R·(1 − e^(−t/τ)) to
// RK4's accuracy (h/τ = 0.01: local error ~1e-12 of the step), and the residual against
// exact measurements stays at that level.
TEST(ModelConcept, TinyModelRunsInTheObserverToTheExactSolution) {
  hstmon::Observer<Tiny, false> obs;
  hstmon::Observer<Tiny, false>::Config cfg;
  cfg.tick = 0.01;
  ASSERT_EQ(obs.configure(Tiny{}, cfg), hstmon::Status::kOk);
  Tiny::Inputs u;
  ASSERT_EQ(obs.reset_rest(u), hstmon::Status::kOk);
  const double p_inf = u.Q * Tiny{}.R;  // 1e7 Pa
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    const double t = k * cfg.tick;
    hstmon::Observer<Tiny, false>::Measurement m;
    m.y[0] = p_inf * (1.0 - std::exp(-t));
    m.valid = 1;
    EXPECT_EQ(obs.step(u, m), 0u);
    worst = std::max(worst, std::fabs(obs.residual()[0]) / p_inf);
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(obs.state()[0], p_inf * (1.0 - std::exp(-5.0)), 1e-9 * p_inf);
  EXPECT_EQ(obs.substeps(), 1);
}

// The start rule of initial_state.hpp on the tiny model: the measured state when there is one.
TEST(ModelConcept, TinyModelStartsFromTheMeasurement) {
  hstmon::Observer<Tiny, false> obs;
  ASSERT_EQ(obs.configure(Tiny{}, {}), hstmon::Status::kOk);
  hstmon::Observer<Tiny, false>::Measurement m;
  m.y[0] = 3e6;
  m.valid = 1;
  hstmon::InitialState how = hstmon::InitialState::kRest;
  ASSERT_EQ(obs.reset_measured(Tiny::Inputs{}, m, &how), hstmon::Status::kOk);
  EXPECT_EQ(how, hstmon::InitialState::kMeasured);
  EXPECT_EQ(obs.state()[0], 3e6);
  m.valid = 0;
  ASSERT_EQ(obs.reset_measured(Tiny::Inputs{}, m, &how), hstmon::Status::kOk);
  EXPECT_EQ(how, hstmon::InitialState::kRest) << "nothing measured: rest";
}

}  // namespace
