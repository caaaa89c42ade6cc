#pragma once
/// @file circuit_discover.hpp
/// Beyond the candidates, for any circuit (discover.hpp is the thesis rig's): the located
/// balance equation's imbalance (circuit_equations.hpp) regressed on physics-structured
/// candidate terms built from the circuit, by sequentially thresholded least squares
/// (stlsq.hpp), fitted on the fit log and the sparsest model that does (nearly) as well as
/// the best chosen on the check log. Forms use the circuit's node and shaft names.
///  - flow:<node>: `1`; the node pressure (leak to tank); the speed of each shaft driving a
///    machine at the node (displacement error); per element touching the node the pressure
///    difference across it `a-b` (ports in the element's direction) and, for an orifice or
///    poppet, `sqrt(a-b)` (signed root); per such shaft `<node>*<shaft>`; `d<node>/dt`
///    (compliance); `t` (drift, time since the log's start).
///  - torque:<shaft>: `tanh(<shaft>/0.5)` (Coulomb, before the constant: on a shaft that
///    turns one way they coincide, and the physical reading is friction), `1`, `<shaft>`
///    (viscous), per machine on it the pressure difference across it, `<shaft>*|<shaft>|`
///    (windage), per machine `(a-b)*<shaft>`, `d<shaft>/dt` (inertia), `t`.
/// Rows are weighted by 1/(propagated noise). The sign is the equation's: a positive
/// coefficient on a positive term is a loss the model lacks.
#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_gap/circuit_equations.hpp"
#include "hstmon_gap/discover.hpp"

namespace hstmon::gap {

/// A proposed missing term in one balance equation of a circuit.
struct CircuitDiscovery {
  std::string equation;               ///< "flow:Ppp"
  std::vector<DiscoveredTerm> terms;  ///< largest contribution first; coefficient in its SI unit
  double shrink_fit = 0;              ///< share of the equation imbalance above noise removed, fit log (shrink.hpp)
  double shrink_check = 0;            ///< same on the check log (the judge)
  double rms_w_before_check = 0, rms_w_after_check = 0;  ///< the check log's imbalance RMS/noise
  std::string reading;                                   ///< the leading term in words, with the circuit's names
};

/// Proposes the missing term of equation `eq` (index in fit.equations) from both logs'
/// evaluations; nullopt when the equation is unavailable on either log, either has fewer
/// than 20 rows, or nothing shrinks the check log.
std::optional<CircuitDiscovery> discover_circuit(const circuit_tools::LoadedCircuit& c, const CircuitArrData& fit,
                                                 const CircuitArrData& check, int eq);

}  // namespace hstmon::gap
