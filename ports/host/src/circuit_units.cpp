#include "hstmon_host/circuit_units.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "text_util.hpp"

namespace hstmon::host {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A quantity's name in circuit files, its SI unit, and the unit it is shown in.
struct Named {
  CircuitQuantity q;
  const char* name;
  const char* si;
  const char* engineering;
};

const Named kQuantities[] = {
    {CircuitQuantity::kPressure, "pressure", "Pa", "bar"},
    {CircuitQuantity::kSpeed, "speed", "rad/s", "rpm"},
    {CircuitQuantity::kFlow, "flow", "m3/s", "L/min"},
    {CircuitQuantity::kDisplacement, "displacement", "m3/rad", "cc/rev"},
    {CircuitQuantity::kResistance, "resistance", "Pa*s/m3", "bar/(L/min)"},
    {CircuitQuantity::kOrifice, "orifice", "m3/(s*Pa^0.5)", "m3/(s*Pa^0.5)"},
    {CircuitQuantity::kArea, "area", "m2", "mm2"},
    {CircuitQuantity::kStiffness, "stiffness", "Pa/m3", "bar/L"},
    {CircuitQuantity::kVolume, "volume", "m3", "L"},
    {CircuitQuantity::kInertia, "inertia", "kg*m2", "kg*m2"},
    {CircuitQuantity::kDamping, "damping", "N*m*s/rad", "N*m*s/rad"},
    {CircuitQuantity::kTorque, "torque", "N*m", "N*m"},
    {CircuitQuantity::kDensity, "density", "kg/m3", "kg/m3"},
    {CircuitQuantity::kFraction, "fraction", "-", "%"},
    {CircuitQuantity::kConductance, "conductance", "m3/(s*Pa)", "(L/min)/bar"},
};

/// The row of q, or nullptr for a value outside the enumeration.
const Named* named(CircuitQuantity q) noexcept {
  for (const auto& n : kQuantities) {
    if (n.q == q) return &n;
  }
  return nullptr;
}

/// Units of the quantities units.hpp does not know: name (compared ignoring ASCII case)
/// and SI per unit.
struct UnitRow {
  CircuitQuantity q;
  const char* unit;
  double factor;
};

const UnitRow kUnits[] = {
    {CircuitQuantity::kFlow, "m3/s", 1.0},
    {CircuitQuantity::kFlow, "m^3/s", 1.0},
    {CircuitQuantity::kFlow, "L/min", 1e-3 / 60.0},
    {CircuitQuantity::kFlow, "lpm", 1e-3 / 60.0},
    {CircuitQuantity::kFlow, "L/s", 1e-3},
    {CircuitQuantity::kFlow, "cm3/s", 1e-6},
    {CircuitQuantity::kDisplacement, "m3/rad", 1.0},
    {CircuitQuantity::kDisplacement, "m^3/rad", 1.0},
    {CircuitQuantity::kDisplacement, "cc/rev", 1e-6 / (2.0 * kPi)},
    {CircuitQuantity::kDisplacement, "cm3/rev", 1e-6 / (2.0 * kPi)},
    {CircuitQuantity::kDisplacement, "m3/rev", 1.0 / (2.0 * kPi)},
    {CircuitQuantity::kResistance, "Pa*s/m3", 1.0},
    {CircuitQuantity::kResistance, "Pa.s/m3", 1.0},
    {CircuitQuantity::kResistance, "N*s/m5", 1.0},
    {CircuitQuantity::kResistance, "bar/(L/min)", 1e5 / (1e-3 / 60.0)},
    {CircuitQuantity::kStiffness, "Pa/m3", 1.0},
    {CircuitQuantity::kStiffness, "bar/L", 1e5 / 1e-3},
    {CircuitQuantity::kVolume, "m3", 1.0},
    {CircuitQuantity::kVolume, "L", 1e-3},
    {CircuitQuantity::kVolume, "cm3", 1e-6},
    {CircuitQuantity::kVolume, "cc", 1e-6},
    {CircuitQuantity::kInertia, "kg*m2", 1.0},
    {CircuitQuantity::kInertia, "kg*m^2", 1.0},
    {CircuitQuantity::kDamping, "N*m*s/rad", 1.0},
    {CircuitQuantity::kDamping, "Nm*s/rad", 1.0},
    {CircuitQuantity::kDamping, "Nm/rpm", 60.0 / (2.0 * kPi)},
    {CircuitQuantity::kTorque, "N*m", 1.0},
    {CircuitQuantity::kTorque, "Nm", 1.0},
    {CircuitQuantity::kTorque, "kN*m", 1e3},
    {CircuitQuantity::kDensity, "kg/m3", 1.0},
    {CircuitQuantity::kDensity, "kg/m^3", 1.0},
    {CircuitQuantity::kFraction, "-", 1.0},
    {CircuitQuantity::kFraction, "%", 0.01},
    {CircuitQuantity::kConductance, "m3/(s*Pa)", 1.0},
    {CircuitQuantity::kConductance, "(L/min)/bar", (1e-3 / 60.0) / 1e5},
    {CircuitQuantity::kConductance, "L/min/bar", (1e-3 / 60.0) / 1e5},
};

}  // namespace

const char* circuit_quantity_name(CircuitQuantity q) noexcept {
  const Named* n = named(q);
  return n != nullptr ? n->name : "?";
}

const char* circuit_si_unit(CircuitQuantity q) noexcept {
  const Named* n = named(q);
  return n != nullptr ? n->si : "?";
}

const char* engineering_unit(CircuitQuantity q) noexcept {
  const Named* n = named(q);
  return n != nullptr ? n->engineering : "?";
}

std::string engineering_text(CircuitQuantity q, double si, int digits) { return display_unit(q).text(si, digits); }

DisplayUnit display_unit(CircuitQuantity q, std::string_view stated) {
  DisplayUnit d;
  if (!detail::trim(stated).empty()) {
    if (const UnitResult u = parse_circuit_unit(q, stated); u.ok() && u.conversion.offset == 0.0) {
      d.unit = std::string(detail::trim(stated));
      d.per_si = 1.0 / u.conversion.factor;
      return d;
    }
  }
  const UnitResult u = parse_circuit_unit(q, engineering_unit(q));
  d.unit = u.ok() ? engineering_unit(q) : circuit_si_unit(q);
  d.per_si = u.ok() ? 1.0 / u.conversion.factor : 1.0;
  return d;
}

std::string DisplayUnit::text(double si, int digits, bool sign) const {
  char b[96];
  std::snprintf(b, sizeof b, sign ? "%+.*g %s" : "%.*g %s", digits, of(si), unit.c_str());
  return b;
}

bool parse_circuit_quantity(std::string_view name, CircuitQuantity& q) noexcept {
  for (const auto& n : kQuantities) {
    if (name == n.name) {
      q = n.q;
      return true;
    }
  }
  return false;
}

std::string circuit_quantity_list() {
  std::string s;
  for (const auto& n : kQuantities) {
    if (!s.empty()) s += ", ";
    s += n.name;
  }
  return s;
}

UnitResult parse_circuit_unit(CircuitQuantity q, std::string_view unit) {
  switch (q) {
    case CircuitQuantity::kPressure:
      return parse_unit(Quantity::kPressure, unit);
    case CircuitQuantity::kSpeed:
      return parse_unit(Quantity::kSpeed, unit);
    case CircuitQuantity::kArea:
      return parse_unit(Quantity::kArea, unit);
    case CircuitQuantity::kOrifice:
      return parse_unit(Quantity::kKp, unit);
    default:
      break;
  }
  const std::string_view u = detail::trim(unit);
  UnitResult r;
  if (u.empty()) return r;  // SI
  for (const auto& row : kUnits) {
    if (row.q == q && detail::iequals(u, row.unit)) {
      r.conversion.factor = row.factor;
      return r;
    }
  }
  std::string known;
  for (const auto& row : kUnits) {
    if (row.q != q) continue;
    if (!known.empty()) known += ", ";
    known += row.unit;
  }
  r.error = "unknown " + std::string(circuit_quantity_name(q)) + " unit '" + detail::printable(u) + "' (known: " + known + ")";
  return r;
}

ValueResult parse_circuit_value(CircuitQuantity q, std::string_view text) {
  ValueResult r;
  const std::string s(detail::trim(text));
  const char* begin = s.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin) {
    r.error = "expected a number with an optional " + std::string(circuit_quantity_name(q)) + " unit, got '" +
              detail::printable(s) + "'";
    return r;
  }
  const UnitResult u = parse_circuit_unit(q, std::string_view(end));
  if (!u.ok()) {
    r.error = u.error;
    return r;
  }
  r.value = u.conversion.to_si(v);
  if (!std::isfinite(r.value)) r.error = "value '" + detail::printable(s) + "' is not finite";
  return r;
}

}  // namespace hstmon::host
