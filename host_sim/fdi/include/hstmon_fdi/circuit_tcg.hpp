#pragma once
/// @file circuit_tcg.hpp
/// The temporal causal graph of any circuit file, derived from its bond graph
/// (circuit_bond_graph.hpp) at a steady operating point of the engine: efforts and flows
/// of every bond as nodes; junction relations with the signs of the bonds' half-arrows;
/// element relations in their assigned causality carrying the element's parameter with
/// the sign of its influence there; dt edges at C and I; gains ∂to/∂from and parameter
/// injections ∂to/∂ln θ from the engine's laws at the operating point. backward_propagate,
/// forward_qualitative_at / forward_weighted_at, linear_steady_change_at and fault_tree
/// run on it unchanged. docs/fdi.md ("Any circuit") gives the derivation.

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_fdi/causal_graph.hpp"
#include "hstmon_fdi/circuit_bond_graph.hpp"
#include "hstmon_fdi/forward.hpp"

namespace hstmon::fdi {

/// A steady operating point of a circuit: the engine at (params, inputs) and its steady
/// full vector. The model refers to the loaded circuit's description, which must outlive it.
struct CircuitOperatingPoint {
  host::HostCircuitModel model;  ///< bound, at the point's parameters and inputs
  std::vector<double> z;         ///< steady pressures of every node [Pa], then shaft speeds [rad/s]
};

/// Steady operating point of c under (p, u) (every volume a state: the stiff mask is 0).
/// @return nothing, or why there is none (invalid values, no steady state)
std::optional<std::string> circuit_operating_point(const circuit_tools::LoadedCircuit& c,
                                                   const host::HostCircuitModel::Params& p,
                                                   const host::HostCircuitModel::Inputs& u, CircuitOperatingPoint& out);

/// A parameter of the graph (on an edge) or a source node, and the circuit's parameter or
/// input it stands for.
struct GraphParameter {
  std::string name;          ///< edge parameter ("prv.k", "Pmi.K") or source node ("Psupl")
  std::string circuit_name;  ///< circuit parameter or input ("kp", "K", "Psupl"); "" for a literal
  circuit::Ref ref{};        ///< that parameter or input
  bool source = false;       ///< true: a source node (an Se or Sf value), not an edge parameter
};

/// A circuit's temporal causal graph.
struct CircuitTcg {
  CircuitBondGraph bond_graph;             ///< what it was derived from
  CausalGraph graph;                       ///< the TCG; measurement nodes are named after the sensors
  std::vector<std::string> measured;       ///< sensor channel names, in channel order
  std::vector<GraphParameter> parameters;  ///< every edge parameter and source, in first-appearance order
};

/// Derives the TCG of c at op.
/// @throws std::invalid_argument if the bond graph's causality fails (message names the element)
CircuitTcg circuit_tcg(const circuit_tools::LoadedCircuit& c, const CircuitOperatingPoint& op);

/// The graph steps of fault (name, sign): a circuit parameter or input steps every edge
/// parameter and source standing for it; a graph parameter ("prv.k") or source steps itself.
/// @throws std::invalid_argument if name is neither
std::vector<ParamStep> circuit_fault_steps(const CircuitTcg& t, const std::string& name, int sign);

/// Circuit parameters and inputs on the graph (each once, in first-appearance order).
std::vector<std::string> circuit_graph_faults(const CircuitTcg& t);

}  // namespace hstmon::fdi
