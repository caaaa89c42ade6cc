#pragma once
/// @file bench_common.hpp
/// Shared workload for bench_observer.cpp and count_ticks.cpp: the nominal operating point,
/// a fixed table of measurements, and the Boost.Odeint baselines the observer is compared
/// with. Both programs include this header so the timing benchmark and the instruction
/// count measure exactly the same work.
///
/// Baselines (an observer built on odeint, per tick, no health checks):
///   OdeintReduced<T>, n_sub = 1 ("naive"): ŷ = outputs(x); r = y − ŷ (4 channels); one
///                     runge_kutta4 step of ThesisReducedModel<T>::derivative over the tick.
///                     No stiffness control: unstable at start from rest (docs/numerics.md).
///   OdeintReduced<T>, n_sub = safe_substeps(tick) ("safe fixed"): the same with the one
///                     fixed substep count that is stable over the whole envelope, start
///                     from rest included: ⌈ρ_rest·h/0.8⌉ = 22 at 1 ms.
///   OdeintFull:       the full stiff 4-state thesis_derivative, runge_kutta4 at the
///                     3.5 µs step its DCV modes (≈ −3.7e5 1/s) need: 286 steps per 1 ms tick.

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "hstmon/hstmon.hpp"
#include "perturbed_measurements.hpp"

namespace hstmon_bench {

template <typename T>
using Reduced = hstmon::ThesisReducedModel<T>;
template <typename T>
using Obs = hstmon::Observer<Reduced<T>>;

/// Measurements fed to every variant (perturbed_measurements.hpp).
template <typename T>
using MeasurementTable = PerturbedMeasurements<Obs<T>>;

/// Compiler barrier: the pointee is assumed read and written (same as
/// benchmark::DoNotOptimize + ClobberMemory, usable without Google Benchmark).
inline void escape(const void* p) noexcept { asm volatile("" : : "g"(p) : "memory"); }

/// Our observer at the nominal operating point (default ThesisInputs), started steady.
template <typename T>
Obs<T> make_observer(T tick) noexcept {
  Obs<T> o;
  typename Obs<T>::Config cfg;
  cfg.tick = tick;
  (void)o.configure(Reduced<T>{}, cfg);
  (void)o.reset_steady(hstmon::ThesisInputs<T>{});
  return o;
}

/// Substeps our observer picks per tick at the nominal point for this tick length.
template <typename T>
int nominal_substeps(T tick) noexcept {
  Obs<T> o = make_observer<T>(tick);
  typename Obs<T>::Measurement m;
  m.y = o.estimate();
  m.valid = 0x0F;
  (void)o.step(hstmon::ThesisInputs<T>{}, m);
  return o.substeps();
}

/// Fixed RK4 substeps per tick that a non-adaptive observer needs to stay stable over the
/// whole operating envelope: ρ is largest at rest (ωm = 0, Ppp = Pbp: both orifices in
/// their laminar branch, ρ = 1.74e4 1/s), so n = ⌈ρ_rest·h / (λh)_max⌉, the observer's rule.
template <typename T>
int safe_substeps(T tick) noexcept {
  const Reduced<T> m{};
  const typename Obs<T>::Config cfg{};
  const double want = static_cast<double>(m.spectral_radius(m.rest_state())) * static_cast<double>(tick) /
                      static_cast<double>(cfg.lambda_h_max);
  return static_cast<int>(std::ceil(want));
}

/// The odeint observer on the same reduced model, with a fixed substep count.
template <typename T>
class OdeintReduced {
 public:
  using state_type = std::array<T, 2>;
  using Output = typename Reduced<T>::Output;
  using State = typename Reduced<T>::State;

  /// @param tick   observer tick [s]
  /// @param n_sub  RK4 steps per tick: 1 (naive at 1 ms), the observer's nominal count, or
  ///               safe_substeps(tick)
  explicit OdeintReduced(T tick, int n_sub = 1) noexcept : n_(n_sub), dt_(tick / static_cast<T>(n_sub)) {
    const Obs<T> o = make_observer<T>(tick);  // same steady start as ours
    model_ = o.model();
    x_ = {o.state()[0], o.state()[1]};
  }

  void step(const hstmon::ThesisInputs<T>& u, const typename Obs<T>::Measurement& m) noexcept {
    // As ours: the model's input-dependent coefficients are only recomputed on a change.
    if (std::memcmp(&u, &model_.inputs(), sizeof u) != 0) model_.set_inputs(u);
    yhat_ = model_.outputs(State(x_[0], x_[1]));
    r_ = m.y - yhat_;
    const Reduced<T>& model = model_;
    auto sys = [&model](const state_type& x, state_type& dxdt, T /*t*/) {
      const State d = model.derivative(State(x[0], x[1]));
      dxdt[0] = d[0];
      dxdt[1] = d[1];
    };
    for (int i = 0; i < n_; ++i) {
      stepper_.do_step(sys, x_, t_, dt_);
      t_ += dt_;
    }
  }

  const Output& residual() const noexcept { return r_; }
  const state_type& state() const noexcept { return x_; }
  int steps_per_tick() const noexcept { return n_; }

 private:
  Reduced<T> model_{};
  boost::numeric::odeint::runge_kutta4<state_type, T, state_type, T> stepper_{};
  state_type x_{};
  Output yhat_ = Output::Zero();
  Output r_ = Output::Zero();
  T t_ = T(0);
  int n_;
  T dt_;
};

/// The naive odeint observer on the full stiff 4-state model (double only).
class OdeintFull {
 public:
  using state_type = std::array<double, 4>;
  static constexpr int kStepsPerMs = 286;  ///< 1 ms / 286 ≈ 3.5 µs: |λ|·h ≈ 1.3 at λ ≈ −3.7e5 1/s

  explicit OdeintFull(double tick) noexcept
      : n_(static_cast<int>(tick / 1e-3 * kStepsPerMs + 0.5)), dt_(tick / n_) {
    const Obs<double> o = make_observer<double>(tick);
    const auto y = o.estimate();  // quasi-steady Pmi, Pmo at the steady state
    x_ = {y[0], y[1], y[2], y[3]};
  }

  void step(const hstmon::ThesisInputs<double>& u, const Obs<double>::Measurement& m) noexcept {
    u_ = u;
    for (int i = 0; i < 4; ++i) r_[i] = m.y[i] - x_[static_cast<std::size_t>(i)];  // outputs = state
    const hstmon::ThesisParams<double>& p = p_;
    const hstmon::ThesisInputs<double>& uu = u_;
    auto sys = [&p, &uu](const state_type& x, state_type& dxdt, double /*t*/) {
      const hstmon::ThesisState<double> d =
          hstmon::thesis_derivative(p, uu, hstmon::ThesisState<double>{x[0], x[1], x[2], x[3]});
      dxdt = {d.Pmi, d.Pmo, d.Ppp, d.w_m};
    };
    for (int i = 0; i < n_; ++i) {
      stepper_.do_step(sys, x_, t_, dt_);
      t_ += dt_;
    }
  }

  int steps_per_tick() const noexcept { return n_; }
  const Obs<double>::Output& residual() const noexcept { return r_; }
  const state_type& state() const noexcept { return x_; }

 private:
  hstmon::ThesisParams<double> p_{};
  hstmon::ThesisInputs<double> u_{};
  boost::numeric::odeint::runge_kutta4<state_type> stepper_{};
  state_type x_{};
  Obs<double>::Output r_ = Obs<double>::Output::Zero();
  double t_ = 0.0;
  int n_;
  double dt_;
};

}  // namespace hstmon_bench
