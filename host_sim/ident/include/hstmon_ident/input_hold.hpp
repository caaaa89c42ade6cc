#pragma once
/// @file input_hold.hpp
/// When a logged input holds: within 0.5 % of its value or within 8 of its own
/// sample-to-sample noise σ (a measured input scatters on every row). The operating points
/// of `identify --circuit` (circuit_points.cpp) and the setting windows of the circuit's
/// balance equations (gap circuit_equations.cpp) use the same rule.
#include <vector>

namespace hstmon::ident {

inline constexpr double kInputRelative = 0.005;  ///< an input within 0.5 % of its value holds…
inline constexpr double kInputNoise = 8.0;       ///< … or within 8 of its own noise σ

/// σ of a column's sample-to-sample noise: the median successive difference, robust to
/// its steps and ramps (1.4826 · median|Δ| / √2) [the column's unit]; 0 for a column held
/// exactly or shorter than 3 rows.
double column_noise(const std::vector<double>& v);

}  // namespace hstmon::ident
