// The observer (reduced model, RK4 with stiffness-driven substeps) against the stiff
// reference (full equations 2.5–2.8, Rosenbrock) at the controller tick (1 ms) and the
// PLC scan (10 ms), in double and float: start from rest, then a kp step (PRV 50 %
// blockage). Every channel within 1 % from 10 ms after the start, and the final state on
// the true fixed point (a false fixed point is 1.5–13 % off).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "hstmon/hstmon.hpp"
#include "hstmon_sim/thesis_reference.hpp"

namespace {

constexpr double kStepTime = 1.0;  // kp halves here [s]
constexpr double kEnd = 2.0;       // [s]

struct Sample {
  double t;
  double y[4];
};

// Reference outputs at every multiple of `tick` in [0, kEnd].
std::vector<Sample> reference(double tick) {
  hstmon::ThesisInputs<double> u;
  hstmon::ThesisState<double> x0{u.Ps, u.Ps, u.Pbp, 0.0};  // rest, supply applied at t = 0
  hstmon::sim::ThesisReference ref({}, x0, 0.0);
  std::vector<double> times;
  const int n = static_cast<int>(std::lround(kEnd / tick));
  for (int i = 0; i <= n; ++i) times.push_back(i * tick);
  std::vector<Sample> out;
  auto on = [&](double t, const hstmon::ThesisState<double>& x) { out.push_back({t, {x.Pmi, x.Pmo, x.Ppp, x.w_m}}); };
  // The reference samples times in (time(), t_end]: t = 0 is the initial state, and the
  // sample at the step time ends the first segment (the state is continuous there).
  on(0.0, x0);
  std::vector<double> first, second;
  for (double t : times) {
    if (t <= 0.0) continue;
    (t <= kStepTime + 1e-12 ? first : second).push_back(t);
  }
  ref.advance_to(kStepTime, u, first, on);
  u.kp *= 0.5;
  ref.advance_to(kEnd, u, second, on);
  return out;
}

// Largest error relative to the channel's scale over samples with t ≥ 10 ms.
template <typename T>
void check(double tick, const std::vector<Sample>& ref) {
  using Model = hstmon::ThesisReducedModel<T>;
  hstmon::Observer<Model> o;
  typename hstmon::Observer<Model>::Config c;
  c.tick = static_cast<T>(tick);
  ASSERT_EQ(o.configure(Model{}, c), hstmon::Status::kOk);
  hstmon::ThesisInputs<T> u;
  o.reset_rest(u);
  // Scale per channel: the channel's magnitude, floored at 1 % of its largest value so a
  // pressure crossing zero is judged against its range, not against zero.
  double scale_floor[4] = {0, 0, 0, 0};
  for (const auto& s : ref)
    for (int i = 0; i < 4; ++i) scale_floor[i] = std::fmax(scale_floor[i], 0.01 * std::fabs(s.y[i]));
  double worst[4] = {0, 0, 0, 0};
  double worst_t[4] = {0, 0, 0, 0};
  const typename hstmon::Observer<Model>::Measurement none;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const double t = ref[k].t;
    if (t >= kStepTime - 1e-12) u.kp = static_cast<T>(4.41e-8 * 0.5);
    o.step(u, none);  // estimate() is ŷ at t_k, before the step
    if (t < 10e-3 - 1e-12) continue;
    for (int i = 0; i < 4; ++i) {
      const double e = std::fabs(static_cast<double>(o.estimate()[i]) - ref[k].y[i]) /
                       std::fmax(std::fabs(ref[k].y[i]), scale_floor[i]);
      if (e > worst[i]) {
        worst[i] = e;
        worst_t[i] = t;
      }
    }
  }
  const char* names[] = {"Pmi", "Pmo", "Ppp", "w_m"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_LT(worst[i], 0.01) << names[i] << " tick " << tick << " worst at t = " << worst_t[i];
    std::printf("%s tick %.0f ms %s: worst rel error %.3g at t = %.3f s\n", sizeof(T) == 4 ? "float " : "double", tick * 1e3, names[i], worst[i], worst_t[i]);
    ::testing::Test::RecordProperty(std::string("worst_rel_") + names[i] + "_tick_" + std::to_string(tick), std::to_string(worst[i]));
  }
  // The end state is the true fixed point, not a false one.
  const auto& last = ref.back();
  const auto y = o.model().outputs(o.state());
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(static_cast<double>(y[i]) / last.y[i], 1.0, sizeof(T) == 4 ? 1e-5 : 1e-7) << names[i];
  }
  EXPECT_EQ(o.health(), 0u);
}

TEST(ObserverAccuracy, Tick1msDoubleAndFloat) {
  const auto ref = reference(1e-3);
  check<double>(1e-3, ref);
  check<float>(1e-3, ref);
}

TEST(ObserverAccuracy, Tick10msDoubleAndFloat) {
  const auto ref = reference(10e-3);
  check<double>(10e-3, ref);
  check<float>(10e-3, ref);
}

}  // namespace

namespace {

// The end-state check above is what catches a false fixed point. Shown here on the
// integrator that has one: explicit RK4 on the full stiff model at h = 7 µs (just inside
// the nominal stability limit of 7.5 µs, but not for the start-up transient) settles
// with ωm 3 % low and Pmo 150 % high, and no NaN.
TEST(FalseFixedPoint, EndStateCheckRejectsExplicitRk4OnTheFullModel) {
  const hstmon::ThesisParams<double> p;
  const hstmon::ThesisInputs<double> u;
  using S = hstmon::ThesisState<double>;
  auto axpy = [](const S& x, const S& k, double h) {
    return S{x.Pmi + h * k.Pmi, x.Pmo + h * k.Pmo, x.Ppp + h * k.Ppp, x.w_m + h * k.w_m};
  };
  S x{u.Ps, u.Ps, u.Pbp, 0.0};
  const double h = 7e-6;
  for (int i = 0; i < 150000; ++i) {  // ≈ 1 s
    const S k1 = hstmon::thesis_derivative(p, u, x);
    const S k2 = hstmon::thesis_derivative(p, u, axpy(x, k1, h / 2));
    const S k3 = hstmon::thesis_derivative(p, u, axpy(x, k2, h / 2));
    const S k4 = hstmon::thesis_derivative(p, u, axpy(x, k3, h));
    x.Pmi += h / 6 * (k1.Pmi + 2 * k2.Pmi + 2 * k3.Pmi + k4.Pmi);
    x.Pmo += h / 6 * (k1.Pmo + 2 * k2.Pmo + 2 * k3.Pmo + k4.Pmo);
    x.Ppp += h / 6 * (k1.Ppp + 2 * k2.Ppp + 2 * k3.Ppp + k4.Ppp);
    x.w_m += h / 6 * (k1.w_m + 2 * k2.w_m + 2 * k3.w_m + k4.w_m);
  }
  ASSERT_TRUE(std::isfinite(x.w_m) && std::isfinite(x.Pmo));  // nothing warns…
  hstmon::ThesisReducedModel<double> m;
  auto xs = hstmon::ThesisReducedModel<double>::State::Zero().eval();
  ASSERT_TRUE(m.steady_state(xs));
  const auto truth = m.outputs(xs);
  // …and it is still far from the truth: the check the observer passes fails here.
  EXPECT_GT(std::fabs(x.w_m / truth[hstmon::kChWm] - 1.0), 0.01);
  EXPECT_GT(std::fabs(x.Pmo / truth[hstmon::kChPmo] - 1.0), 0.5);
  // The derivative there is not zero: it is a fixed point of the step map, not of the ODE.
  EXPECT_GT(std::fabs(hstmon::thesis_derivative(p, u, x).Pmi), 1e9);
}

}  // namespace
