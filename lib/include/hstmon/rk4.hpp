#pragma once
/// @file rk4.hpp
/// Classical fixed-step Runge–Kutta 4 with a compensated (Kahan) state update in float.
///
/// In float, adding a small increment h·f to a large state (Ppp ≈ 1.7e7 Pa) loses the
/// increment's low bits every step; over 1e4 steps plain float RK4 drifts by ~1e-4
/// relative. Carrying the rounding error of each update in `comp` and feeding it back
/// into the next keeps the state at double-like accuracy for two extra adds per element.
/// Requires IEEE evaluation order: never build with -ffast-math.

#include <Eigen/Core>

namespace hstmon {

/// A state vector and the running compensation of its rounding error. Compensated only
/// in float: a double state loses ~1e-16 per update, ~1e-12 over a day at 1 kHz.
template <typename Vec>
struct CompensatedState {
  /// True when the updates are compensated (float and narrower scalars).
  static constexpr bool kCompensated = sizeof(typename Vec::Scalar) < sizeof(double);
  Vec x = Vec::Zero();     ///< the state, in the model's units
  Vec comp = Vec::Zero();  ///< rounding error of the last updates, same units (subtracted next time)

  /// Sets the state and clears the compensation.
  void reset(const Vec& x0) noexcept {
    x = x0;
    comp.setZero();
  }

  /// x += dx, with Kahan compensation where kCompensated. Never allocates.
  void add(const Vec& dx) noexcept {
    if constexpr (kCompensated) {
      const Vec y = dx - comp;
      const Vec t = x + y;
      comp = (t - x) - y;
      x = t;
    } else {
      x += dx;
    }
  }
};

/// The step-size factors of one RK4 step, computed once per step size.
template <typename T>
struct Rk4Step {
  T h = T(0);      ///< step [s]
  T half = T(0);   ///< h/2 [s]
  T sixth = T(0);  ///< h/6 [s]

  Rk4Step() noexcept = default;
  /// @param step  h [s]
  explicit Rk4Step(T step) noexcept : h(step), half(T(0.5) * step), sixth(step / T(6)) {}
};

/// One RK4 step from s.x, given k1 = f(s.x) already evaluated (the observer
/// gets k1 together with the outputs it compares with the measurement).
/// @param model  provides `State derivative(const State&) const`, inputs already set
/// @param s      state and compensation, advanced in place
/// @param h      step factors (h [s], h/2, h/6)
/// @param k1     f(s.x) [state units / s]
template <typename Model>
inline void rk4_step(const Model& model, CompensatedState<typename Model::State>& s,
              const Rk4Step<typename Model::Scalar>& h, const typename Model::State& k1) noexcept {
  using State = typename Model::State;
  const State k2 = model.derivative(s.x + h.half * k1);
  const State k3 = model.derivative(s.x + h.half * k2);
  const State k4 = model.derivative(s.x + h.h * k3);
  s.add(h.sixth * (k1 + typename Model::Scalar(2) * (k2 + k3) + k4));
}

/// rk4_step with the step h [s] given directly.
template <typename Model>
inline void rk4_step(const Model& model, CompensatedState<typename Model::State>& s,
              typename Model::Scalar h, const typename Model::State& k1) noexcept {
  rk4_step(model, s, Rk4Step<typename Model::Scalar>(h), k1);
}

/// One RK4 step of size h, evaluating k1 itself.
template <typename Model>
inline void rk4_step(const Model& model, CompensatedState<typename Model::State>& s,
              typename Model::Scalar h) noexcept {
  rk4_step(model, s, h, model.derivative(s.x));
}

}  // namespace hstmon
