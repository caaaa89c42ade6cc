#pragma once
/// @file circuit_bond_graph.hpp
/// The bond graph of any circuit file (docs/circuits.md), derived element by element, and
/// its causality (docs/fdi.md, "Any circuit"). One 0-junction per volume node (with its C,
/// the bulk stiffness) and per boundary held by a named input or parameter (with its Se);
/// one 1-junction per shaft (with its I, the inertia, or the Sf of a driven speed); one
/// 1-junction per two-port element between two junctions (the pressure difference), with
/// an R for orifices, valves, leakages, relief and check valves and compensated pumps, a TF
/// (the displacement) for pumps and motors, an Sf for flow sources; R on the shaft for
/// friction, Se for a load torque; an effort detector per pressure sensor. A boundary at a
/// fixed pressure (tank or drain at a literal value) is no junction: its elements hang
/// from the other node's 0-junction as one-ports. An orifice or valve shut at the operating
/// point (a directional valve's closed paths, a relief or check valve below its cracking
/// pressure) is left out: the graph is that of the operating point. Causality: sources first, then every C
/// and I in integral causality, propagated through the junctions (SCAP); an R left free
/// takes whatever the junctions give it.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_fdi/bond_graph.hpp"

namespace hstmon::fdi {

/// What a bond-graph element of a circuit stands for in the circuit description.
struct CircuitElementSource {
  int element = -1;  ///< circuit element index (R, TF, Sf flow source, Se load torque), or −1
  int node = -1;     ///< circuit node index (0-junction, C, boundary Se, detector), or −1
  int shaft = -1;    ///< circuit shaft index (shaft 1-junction, I, driven Sf), or −1
  int channel = -1;  ///< sensor channel index (detector), or −1
  circuit::Ref ref{};  ///< the number the element's parameter is (K or β, J, k or A, R, D, c, τ, Q, p, ω)
  /// The element's other named numbers, each a parameter of the same relations: a valve's
  /// opening, Cd and ρ, a poppet's cracking and full-open pressures, a compensated pump's
  /// leakage R, Pc, Pk and Pmax, a machine's displacement fraction, a volume's V. Laminar
  /// transitions (dp_t) are not: they shape the law near zero flow only.
  std::vector<std::pair<std::string, circuit::Ref>> extra;
};

/// A circuit's bond graph with its causality.
struct CircuitBondGraph {
  BondGraph graph;                            ///< elements and bonds (numbered 1…), half-arrows as power
  std::vector<CircuitElementSource> sources;  ///< parallel to graph.elements
  /// Per bond (parallel to graph.bonds): the element that imposes the effort on it (the
  /// causal stroke's far end); the other end imposes the flow.
  std::vector<std::string> effort_by;

  /// Index of element `name` in graph.elements, or −1.
  int element_index(std::string_view name) const;
};

/// Derives the bond graph of a loaded circuit and assigns its causality.
/// @param at   the engine bound to c's description at the operating point's values
/// @param z    the operating point's full vector (node pressures [Pa], shaft speeds [rad/s]):
///             an orifice or poppet with no conductance there (shut) is left out
/// @param out  the graph
/// @return nothing, or a message naming the element where the causality fails
std::optional<std::string> circuit_bond_graph(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel& at,
                                              const std::vector<double>& z, CircuitBondGraph& out);

/// Name of a graph parameter: "<circuit element, node or shaft>.<field>" ("prv.k",
/// "Pmi.K", "motor.J", "motor.D"); the circuit parameter or input behind it is
/// CircuitElementSource::ref.
std::string graph_parameter_name(const std::string& owner, const char* field);

/// Name of the circuit parameter or input behind r, or "" (none, or a literal number).
std::string named_ref(const host::CircuitFile& f, circuit::Ref r);

}  // namespace hstmon::fdi
