#pragma once
/// @file units.hpp
/// Unit strings of log columns and parameter files, and their conversion to SI
/// (Pa, rad/s, s, m³/(s·√Pa), m²). Every conversion is si = value·factor + offset.

#include <string>
#include <string_view>

namespace hstmon::host {

/// Physical quantity of a column or parameter; decides which unit strings are valid.
enum class Quantity {
  kPressure,  ///< SI unit Pa (gauge in this project)
  kSpeed,     ///< SI unit rad/s
  kTime,      ///< SI unit s
  kKp,        ///< orifice coefficient, SI unit m³/(s·√Pa); only SI is accepted
  kArea,      ///< SI unit m²
  kNone,      ///< dimensionless or unknown: only an empty unit (or "-") is accepted
};

/// Name of a quantity for messages ("pressure", "speed", ...).
const char* quantity_name(Quantity q) noexcept;

/// SI unit written for a quantity ("Pa", "rad/s", "s", "m3/(s*Pa^0.5)", "m2", "").
const char* si_unit(Quantity q) noexcept;

/// Affine map from a unit to SI: si = value·factor + offset. Offset is 0 for every
/// unit accepted today (no °C); it is kept so callers need not change if one comes.
struct UnitConversion {
  double factor = 1.0;  ///< SI per unit, e.g. 1e5 for bar [SI/unit]
  double offset = 0.0;  ///< SI value of unit zero [SI]

  /// Value in the unit → SI.
  double to_si(double value) const noexcept { return value * factor + offset; }
  /// SI value → the unit (exact inverse up to rounding).
  double from_si(double si) const noexcept { return (si - offset) / factor; }
};

/// Result of parse_unit: a conversion, or a message in `error`.
struct UnitResult {
  UnitConversion conversion;  ///< valid when ok()
  std::string error;          ///< empty on success, else why the unit was refused
  bool ok() const noexcept { return error.empty(); }
};

/// Parses a unit string for quantity q. Surrounding blanks are ignored; an empty unit
/// means SI. Accepted (case-insensitive unless marked exact):
///  - pressure: Pa, hPa, kPa, bar, psi (6894.757293168 Pa), N/m2, N/m^2, N/m²;
///    exact only: MPa, mbar (mpa, MPA, mPa, Mbar ... are refused as ambiguous)
///  - speed: rad/s; rpm, 1/min, U/min, r/min, rev/min, min-1, min^-1 (all rev/min)
///  - time: s, sec, min, h; exact only: ms
///  - kp: m3/(s*Pa^0.5) and the spellings m^3/(s*Pa^0.5), m³/(s·√Pa), m3/(s*sqrt(Pa))
///  - area (exact): m2, m^2, m², mm2, mm^2, mm²
///  - none: "" or "-"
/// Unknown units give an error naming the unit and the quantity.
UnitResult parse_unit(Quantity q, std::string_view unit);

/// Result of parse_value_with_unit: an SI value, or a message in `error`.
struct ValueResult {
  double value = 0.0;  ///< value in SI, valid when ok()
  std::string error;   ///< empty on success
  bool ok() const noexcept { return error.empty(); }
};

/// Parses "<number> [unit]" (e.g. "35 bar", "3.5e6", "120rpm") to SI for quantity q.
/// The number uses a decimal point; a missing unit means SI. Non-finite results
/// (nan, inf, overflow after conversion) are refused.
ValueResult parse_value_with_unit(Quantity q, std::string_view text);

}  // namespace hstmon::host
