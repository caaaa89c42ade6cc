#pragma once
/// @file port_area.hpp
/// Valve port areas from flow and pressure-drop data (seed 001 §4.2–4.3, eqs. 12–13):
///   Q = Cd·A·√(2|ΔP|/ρ)·sign(ΔP)
/// is a line through the origin in x = sign(ΔP)·√(2|ΔP|/ρ) [m/s]; its slope b = Cd·A [m²]
/// is fitted by least squares, b = Σxq/Σx², with standard error s/√Σx²,
/// s² = Σ(q − b·x)²/(n − 1), and the port area A = b/Cd with a Student-t interval. The
/// discharge coefficient is not identifiable from these data (only Cd·A is); Cd is an input.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hstmon::ident {

/// One (ΔP, Q) sample across a valve.
struct PortSample {
  double dp = 0.0;  ///< pressure drop across the valve [Pa] (signed; sign gives the flow direction)
  double q = 0.0;   ///< volume flow through the valve [m³/s]
};

/// Result of fit_port_area.
struct PortAreaFit {
  std::optional<std::string> error;  ///< set on bad data (no numbers are then valid)
  std::string label;                 ///< opening label, e.g. "dcv A1"
  std::size_t n = 0;                 ///< samples used
  double cd_area = 0.0;              ///< slope Cd·A [m²]
  double area = 0.0;                 ///< port area A [m²]
  double area_se = 0.0;              ///< standard error of A [m²]
  double ci_lo = 0.0;                ///< lower end of the confidence interval of A [m²]
  double ci_hi = 0.0;                ///< upper end [m²]
  double rms = 0.0;                  ///< RMS of the flow residuals [m³/s]
  double r2 = 0.0;                   ///< uncentred R² of the line through the origin [-]
  /// True on success.
  bool ok() const noexcept { return !error.has_value(); }
};

/// Fits Q = Cd·A·√(2|ΔP|/ρ) through the origin.
/// @param label       name used in messages
/// @param samples     ≥ 2 finite samples with some ΔP ≠ 0
/// @param cd          discharge coefficient [-] (> 0; the paper's rig: 0.61 assumed)
/// @param rho         oil density [kg/m³] (> 0; Table I: 870)
/// @param confidence  interval level (default 0.95)
PortAreaFit fit_port_area(const std::string& label, const std::vector<PortSample>& samples, double cd = 0.61,
                          double rho = 870.0, double confidence = 0.95);

}  // namespace hstmon::ident
