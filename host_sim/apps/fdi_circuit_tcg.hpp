#pragma once
// hstmon-fdi graph|backward|forward|tree|crosscheck --circuit FILE: the bond graph, temporal
// causal graph, propagation, fault trees and nonlinear cross-check of any circuit file
// (host_sim/fdi circuit_bond_graph, circuit_tcg, circuit_crosscheck), as text or JSON.
#include <string>
#include <utility>
#include <vector>

namespace hstmon::fdi {

/// Where the circuit and its values come from.
struct CircuitSource {
  std::string circuit;  ///< circuit file
  std::string params;   ///< its parameter file ("" = <stem>.params.json beside it, if any)
};

/// Prints the bond graph (elements, bonds with causality) and the TCG's edges; @return 0, 2 for a bad file
int run_circuit_graph(const CircuitSource& s, bool json);

/// Prints the fault candidates of an observation "p_pp+" (a sensor or any node); @return 0, 2 for a bad file
int run_circuit_backward(const CircuitSource& s, const std::string& observation, bool json);

/// Prints the predicted signature of a fault "kp-" (a circuit parameter or input, or a graph
/// parameter such as "prv.k-"); @return 0, 2 for a bad file
int run_circuit_forward(const CircuitSource& s, const std::string& fault, int order, bool json);

/// Prints the fault tree of a sensor (or node) going up, or down with minus; @return 0, 2 for a bad file
int run_circuit_tree(const CircuitSource& s, const std::string& channel, bool minus);

/// Prints the cross-check tables and agreement counts.
/// @param cases  extra operating points "NAME=FACTOR" (input or parameter scaled); none = the defaults
/// @param steps  per-fault steps "NAME=STEP"
/// @return 0, 1 for a bad case or step, 2 for a bad file
int run_circuit_crosscheck(const CircuitSource& s, const std::vector<std::string>& cases,
                           const std::vector<std::string>& steps, double step, bool json);

}  // namespace hstmon::fdi
