#pragma once
/// @file thesis_reference.hpp
/// Reference ("truth") integration of the full 4-state thesis model, equations 2.5–2.8
/// (hstmon::thesis_derivative with its analytic Jacobian hstmon::thesis_jacobian), in
/// double with the stiff integrator of stiff_integrator.hpp. Inputs are piecewise
/// constant: each change of inputs restarts the integrator at the change time, so the
/// discontinuity falls on a step boundary. ∂f/∂t = 0 within a segment.

#include <functional>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace hstmon::sim {

/// Full thesis model integrated with Rosenbrock-4. Not copyable; movable.
class ThesisReference {
 public:
  using Params = ThesisParams<double>;  ///< Table 2.2 by default
  using Inputs = ThesisInputs<double>;  ///< Psupl, Ps, Pbp [Pa], kp [m³/(s·√Pa)]
  using State = ThesisState<double>;    ///< Pmi, Pmo, Ppp [Pa], ωm [rad/s]
  /// Receives one sample: time [s] and state.
  using Sampler = std::function<void(double t, const State& x)>;

  /// @param p    model parameters (must satisfy ThesisCircuitModel::params_valid)
  /// @param x0   state at t0
  /// @param t0   initial time [s]
  /// @param tol  integration tolerances (pressures in Pa, speed in rad/s)
  /// @throws std::invalid_argument on invalid parameters or a non-finite x0
  explicit ThesisReference(const Params& p = Params{}, const State& x0 = State{}, double t0 = 0.0,
                           const ReferenceTolerances& tol = ReferenceTolerances{});

  /// Integrates from time() to t_end [s] with inputs u held constant. If u differs from the
  /// inputs of the previous call (or on the first call) the integrator restarts at time().
  /// @throws std::invalid_argument on non-finite inputs, kp < 0 or t_end < time();
  ///         std::runtime_error if the integration fails
  void advance_to(double t_end, const Inputs& u);

  /// As advance_to(t_end, u), also calling on_sample for every time ts in sample_times
  /// (ascending) with time() < ts ≤ t_end, with the dense-output state at ts.
  void advance_to(double t_end, const Inputs& u, const std::vector<double>& sample_times,
                  const Sampler& on_sample);

  /// Replaces the state at time t [s]; the next advance_to() restarts the integrator.
  void reset(const State& x, double t);

  /// Current state.
  State state() const;
  /// Current time [s].
  double time() const noexcept;
  /// Parameters in use.
  const Params& params() const noexcept { return p_; }
  /// Step statistics of the integrator.
  const IntegratorStats& stats() const noexcept { return integ_.stats(); }

 private:
  void begin_segment(const Inputs& u);

  Params p_;
  Inputs u_{};
  bool segment_open_ = false;  // true once the integrator runs with inputs u_
  State x_pending_{};          // state to restart from when !segment_open_
  double t_pending_ = 0.0;
  StiffIntegrator integ_;
};

/// Copies a thesis state to an array in channel order (Pmi, Pmo, Ppp [Pa], ωm [rad/s]).
inline void to_array(const ThesisState<double>& x, double* out) noexcept {
  out[0] = x.Pmi;
  out[1] = x.Pmo;
  out[2] = x.Ppp;
  out[3] = x.w_m;
}

/// Builds a thesis state from an array in channel order (Pmi, Pmo, Ppp [Pa], ωm [rad/s]).
inline ThesisState<double> thesis_state_from(const double* v) noexcept {
  ThesisState<double> x;
  x.Pmi = v[0];
  x.Pmo = v[1];
  x.Ppp = v[2];
  x.w_m = v[3];
  return x;
}

}  // namespace hstmon::sim
