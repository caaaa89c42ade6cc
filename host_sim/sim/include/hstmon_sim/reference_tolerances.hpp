#pragma once
/// @file reference_tolerances.hpp
/// Error tolerances of the host reference integrators (thesis and paper models).

namespace hstmon::sim {

/// Tolerances of the stiff reference integration. The step controller accepts a step when
/// the RMS over the states of err_i / (abs_i + rel·|x_i|) is at most 1, with abs_i the
/// per-state absolute tolerance below. The defaults make the reference the "truth" for
/// 1 % and 1e-6 relative tests.
struct ReferenceTolerances {
  double rel = 1e-9;           ///< relative tolerance [-]
  double abs_pressure = 1e-3;  ///< absolute tolerance of pressure states [Pa]
  double abs_speed = 1e-9;     ///< absolute tolerance of speed states [rad/s]
  double initial_step = 1e-7;  ///< first trial step after each (re)start [s]
  double max_step = 0.0;       ///< upper bound on the step [s]; 0 means none
};

}  // namespace hstmon::sim
