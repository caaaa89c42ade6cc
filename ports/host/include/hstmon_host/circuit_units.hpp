#pragma once
/// @file circuit_units.hpp
/// The quantities of circuit files and their units: pressure, speed and area through
/// units.hpp, and the others a circuit needs (flow, displacement, resistance, ...).

#include <string>
#include <string_view>

#include "hstmon_host/units.hpp"

namespace hstmon::host {

/// What a circuit number measures; decides the units it may be written in.
enum class CircuitQuantity {
  kPressure,      ///< Pa (bar, MPa, psi, ...)
  kSpeed,         ///< rad/s (rpm, ...)
  kFlow,          ///< m³/s (L/min, ...)
  kDisplacement,  ///< m³/rad (cc/rev, ...)
  kResistance,    ///< laminar resistance, Pa·s/m³
  kOrifice,       ///< orifice coefficient, m³/(s·√Pa)
  kArea,          ///< m² (mm², ...)
  kStiffness,     ///< bulk stiffness K of a volume, Pa/m³
  kVolume,        ///< m³ (L, cm³, ...)
  kInertia,       ///< kg·m²
  kDamping,       ///< viscous friction, N·m·s/rad
  kTorque,        ///< N·m
  kDensity,       ///< kg/m³
  kFraction,      ///< dimensionless (-, %)
  kConductance,   ///< laminar leak conductance, m³/(s·Pa) ((L/min)/bar, ...)
};

/// Name used in files ("pressure", "flow", ...).
const char* circuit_quantity_name(CircuitQuantity q) noexcept;
/// SI unit for messages ("Pa", "m3/s", ...).
const char* circuit_si_unit(CircuitQuantity q) noexcept;
/// Parses a quantity name; false if unknown.
bool parse_circuit_quantity(std::string_view name, CircuitQuantity& q) noexcept;
/// Every quantity name, comma separated (for messages).
std::string circuit_quantity_list();

/// The unit an engineer reads quantity q in, for tables and plots: bar, rpm, L/min,
/// cc/rev, bar/(L/min), mm2, bar/L, L, N*m, % (SI where no other is usual: orifice
/// coefficients, inertias, damping, densities). parse_circuit_unit knows each.
const char* engineering_unit(CircuitQuantity q) noexcept;

/// A value of quantity q [SI] in engineering_unit(q), e.g. "2.29e+11 Pa*s/m3" →
/// "0.382 bar/(L/min)"; `digits` significant digits.
std::string engineering_text(CircuitQuantity q, double si, int digits = 3);

/// How one quantity is shown in tables, notes and plots: the unit a circuit file states
/// for the sensor or input (an engineer's choice), else engineering_unit(q).
struct DisplayUnit {
  std::string unit;     ///< "bar", "rpm", "L/min", ...
  double per_si = 1.0;  ///< display units per SI unit [unit/SI]
  /// si in the display unit.
  double of(double si) const noexcept { return si * per_si; }
  /// "<value> <unit>" with `digits` significant digits; "+" before positive values if `sign`.
  std::string text(double si, int digits = 3, bool sign = false) const;
};

/// The display unit of quantity q when its file states `stated` ("" or a unit q does not
/// know: engineering_unit(q)).
DisplayUnit display_unit(CircuitQuantity q, std::string_view stated = {});

/// Conversion of a unit of quantity q to SI (error in the result if unknown).
UnitResult parse_circuit_unit(CircuitQuantity q, std::string_view unit);

/// "<number> [unit]" to SI for quantity q (e.g. "55 cc/rev", "35 bar", "0.5").
ValueResult parse_circuit_value(CircuitQuantity q, std::string_view text);

}  // namespace hstmon::host
