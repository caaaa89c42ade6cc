#pragma once
/// @file paper_circuit.hpp
/// The circuit file's values that the paper rig's table analysis (pump_curve_fit.hpp,
/// port_area.hpp) estimates, for `hstmon identify --circuit FILE --paper TABLE.csv`:
///  - a pressure-compensated pump (ElementKind::kCompPump): its curve's Q0, R, Pc, Pk, Pmax;
///  - an orifice named like a table kind ("dcv", "prv", or a valve path "dcv.PA"): its
///    area (or its coefficient k = Cd·A·√(2/ρ) when the file gives k), Cd and ρ.
/// A number the circuit takes from an input is that input's nominal value (the parameter
/// file's, else the circuit file's).

#include <array>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::ident {

/// One number of a circuit element, as the comparison shows it.
struct CircuitNumber {
  std::string name;    ///< the parameter or input it comes from ("Rpump", "A_prv"); "" = not given
  bool input = false;  ///< true: an input's nominal value, not a parameter
  double value = 0.0;  ///< [SI]; NaN when not given
  bool given() const noexcept { return !name.empty(); }
};

/// A compensated pump of the circuit: the pump-curve parameters by
/// pump_curve_param_names() order (Q0 [m³/s], R [Pa·s/m³], Pc, Pk, Pmax [Pa]).
struct CircuitPumpCurve {
  std::string element;  ///< its component name
  std::array<CircuitNumber, 5> params;
};

/// An orifice of the circuit that a table kind names.
struct CircuitOrificeValues {
  std::string element;  ///< its element name ("prv", "dcv.PA")
  CircuitNumber area;   ///< port area [m²] (times a fixed opening other than 1); not given when k is
  CircuitNumber k;      ///< coefficient Cd·A·√(2/ρ) [m³/(s·√Pa)] when the file gives it instead
  CircuitNumber cd;     ///< discharge coefficient [-]
  CircuitNumber rho;    ///< density [kg/m³]
};

/// Every compensated pump of c, in element order.
std::vector<CircuitPumpCurve> circuit_pump_curves(const circuit_tools::LoadedCircuit& c);

/// The orifices of c named `kind` or `kind.<path>` (case-insensitive), in element order.
std::vector<CircuitOrificeValues> circuit_orifices_named(const circuit_tools::LoadedCircuit& c,
                                                         const std::string& kind);

/// 100·(fitted − circuit)/circuit [%]; NaN when circuit is 0 or not finite.
double percent_difference(double fitted, double circuit);

}  // namespace hstmon::ident
