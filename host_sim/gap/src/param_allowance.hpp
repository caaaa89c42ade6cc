#pragma once
/// @file param_allowance.hpp
/// How much of a steady gap the model's stated parameter uncertainty can account for
/// (docs/gap.md, "Parameter uncertainty"). The parameters are taken as uncertain by their
/// stated relative uncertainty ε_k (one standard deviation), the steady residuals r (one
/// per operating point and channel, in units of the channel's noise) as r + J·δ under a
/// relative parameter move ε·δ, J the steady outputs' change per ε. The most likely move,
///   δ* = argmin |r + J·δ|² + |δ|²,
/// charges every parameter move against its uncertainty, and what remains,
///   z = √((|r + J·δ*|² + |δ*|²) / m),
/// is a gap in the same noise units as before: with no uncertainty z is the plain RMS of
/// r. A systematic gap of another shape than the parameters can make — a leak that grows
/// with pressure, a constant offset where the machine is at the charge pressure, Coulomb
/// friction's constant torque — stays above z's threshold; a shift the parameters make
/// within their uncertainty does not.
#include <cstddef>
#include <vector>

namespace hstmon::gap::detail {

struct Allowance {
  std::vector<double> delta;       ///< δ*, per parameter [units of ε]
  std::vector<double> after;       ///< r + J·δ* (linearised) [noise units]
  double z = 0;                    ///< √((|after|² + |δ*|²)/m)
  double rms_before = 0;           ///< √(|r|²/m)
};

/// @param r  residuals (m) [noise units]
/// @param J  columns per parameter (K × m, J[k][i]): change of r_i under +ε_k [noise units]
Allowance parameter_allowance(const std::vector<double>& r, const std::vector<std::vector<double>>& J);

}  // namespace hstmon::gap::detail
