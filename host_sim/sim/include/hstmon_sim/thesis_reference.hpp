#pragma once
/// @file thesis_reference.hpp
/// Reference ("truth") integration of the full 4-state thesis model, equations 2.5–2.8
/// (hstmon::thesis_derivative with its analytic Jacobian hstmon::thesis_jacobian), in
/// double with the stiff integrator of stiff_integrator.hpp. Inputs are piecewise
/// constant: each change of inputs restarts the integrator at the change time, so the
/// discontinuity falls on a step boundary. ∂f/∂t = 0 within a segment.

#include "hstmon/thesis_params.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/segmented_reference.hpp"

namespace hstmon::sim {

/// Full thesis model integrated with Rosenbrock-4: inputs Psupl, Ps, Pbp [Pa],
/// kp [m³/(s·√Pa)]; state Pmi, Pmo, Ppp [Pa], ωm [rad/s]. Not copyable; movable.
class ThesisReference : public SegmentedReference<ThesisReference, ThesisState<double>, ThesisInputs<double>> {
 public:
  using Params = ThesisParams<double>;  ///< Table 2.2 by default

  /// @param p    model parameters (must satisfy ThesisCircuitModel::params_valid)
  /// @param x0   state at t0
  /// @param t0   initial time [s]
  /// @param tol  integration tolerances (pressures in Pa, speed in rad/s)
  /// @throws std::invalid_argument on invalid parameters or a non-finite x0
  explicit ThesisReference(const Params& p = Params{}, const State& x0 = State{}, double t0 = 0.0,
                           const ReferenceTolerances& tol = ReferenceTolerances{});

  /// Parameters in use.
  const Params& params() const noexcept { return p_; }

 private:
  friend SegmentedReference;
  static constexpr const char* kName = "ThesisReference";
  static void to_array(const State& x, double* out) noexcept;
  static State from_array(const double* v) noexcept;
  /// Invalid inputs: non-finite, or kp < 0.
  void begin_segment(const Inputs& u);

  Params p_;
  Inputs u_{};  // the inputs of the open segment
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
