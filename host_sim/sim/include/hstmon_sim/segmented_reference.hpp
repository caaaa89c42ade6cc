#pragma once
/// @file segmented_reference.hpp
/// What the reference integrations (ThesisReference, PaperReference) share: a 4-state model
/// integrated in double with the stiff integrator of stiff_integrator.hpp under piecewise
/// constant inputs. Each change of inputs restarts the integrator at the change time, so
/// the discontinuity falls on a step boundary; ∂f/∂t = 0 within a segment.

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace hstmon::sim {

/// Base of a 4-state reference integration (CRTP). Derived, a friend, provides:
///  - static constexpr const char* kName: its name, for the messages;
///  - static void to_array(const State&, double*) and static State from_array(const double*):
///    the state in channel order (three pressures [Pa], a speed [rad/s]);
///  - void begin_segment(const Inputs& u): throws std::invalid_argument on invalid inputs;
///    else, unless segment_open() with inputs u already, takes u and calls restart() with
///    the model's equations at u.
/// Not copyable; movable.
template <class Derived, class StateT, class InputsT>
class SegmentedReference {
 public:
  using State = StateT;    ///< three pressures [Pa] and a speed [rad/s]
  using Inputs = InputsT;  ///< the model's inputs, held constant within a segment
  /// Receives one sample: time [s] and state.
  using Sampler = std::function<void(double t, const State& x)>;

  /// Integrates from time() to t_end [s] with inputs u held constant. If u differs from the
  /// inputs of the previous call (or on the first call) the integrator restarts at time().
  /// @throws std::invalid_argument on invalid inputs or t_end < time();
  ///         std::runtime_error if the integration fails
  void advance_to(double t_end, const Inputs& u) { advance_to(t_end, u, {}, {}); }

  /// As advance_to(t_end, u), also calling on_sample for every time ts in sample_times
  /// (ascending) with time() < ts ≤ t_end, with the dense-output state at ts.
  void advance_to(double t_end, const Inputs& u, const std::vector<double>& sample_times, const Sampler& on_sample) {
    if (!(t_end >= time())) {
      throw std::invalid_argument(std::string(Derived::kName) + "::advance_to: t_end before current time");
    }
    static_cast<Derived&>(*this).begin_segment(u);
    if (on_sample) {
      integ_.advance_to(t_end, sample_times,
                        [&on_sample](double t, const double* x) { on_sample(t, Derived::from_array(x)); });
    } else {
      integ_.advance_to(t_end);
    }
  }

  /// Replaces the state at time t [s]; the next advance_to() restarts the integrator.
  /// @throws std::invalid_argument on a non-finite x or t
  void reset(const State& x, double t) {
    double v[4];
    Derived::to_array(x, v);
    bool finite = std::isfinite(t);
    for (double e : v) finite = finite && std::isfinite(e);
    if (!finite) throw std::invalid_argument(std::string(Derived::kName) + ": non-finite state or time");
    x_pending_ = x;
    t_pending_ = t;
    segment_open_ = false;
  }

  /// Current state.
  State state() const { return segment_open_ ? Derived::from_array(integ_.state().data()) : x_pending_; }
  /// Current time [s].
  double time() const noexcept { return segment_open_ ? integ_.time() : t_pending_; }
  /// Step statistics of the integrator.
  const IntegratorStats& stats() const noexcept { return integ_.stats(); }

 protected:
  /// @param tol  integration tolerances (pressures in Pa, speed in rad/s)
  /// @throws std::invalid_argument on a non-positive tolerance or step
  explicit SegmentedReference(const ReferenceTolerances& tol)
      : integ_({tol.abs_pressure, tol.abs_pressure, tol.abs_pressure, tol.abs_speed}, tol.rel, tol.initial_step,
               tol.max_step) {}

  /// True once the integrator runs with the inputs last passed to begin_segment().
  bool segment_open() const noexcept { return segment_open_; }

  /// Opens a segment: restarts the integrator at time() and state() with the right-hand
  /// side rhs(x, dxdt) [state units/s] and its Jacobian jacobian(x, j), j[r][c] = ∂f_r/∂x_c
  /// [1/s in the state units], both on states in channel order.
  template <class Rhs, class Jacobian>
  void restart(Rhs rhs, Jacobian jacobian) {
    double x0[4];
    Derived::to_array(state(), x0);
    integ_.restart(time(), x0, std::move(rhs), [jacobian](const double* x, double* jac) {
      double j[4][4];
      jacobian(x, j);
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) jac[r * 4 + c] = j[r][c];
      }
    });
    segment_open_ = true;
  }

 private:
  bool segment_open_ = false;  // true once the integrator runs with the current inputs
  State x_pending_{};          // state to restart from when !segment_open_
  double t_pending_ = 0.0;
  StiffIntegrator integ_;
};

}  // namespace hstmon::sim
