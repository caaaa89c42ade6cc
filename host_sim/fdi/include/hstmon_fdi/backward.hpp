#pragma once
/// @file backward.hpp
/// Hypothesis generation (thesis §2.5.1): backward propagation on the temporal causal
/// graph from an observed deviation to the fault candidates. Edges are followed against
/// their direction, instantaneous ones first (a priority queue on the number of dt edges
/// crossed); a branch ends at a parameter, at an effort source, or at a node that already
/// holds the opposite sign (a conflicting node).

#include <string>
#include <vector>

#include "hstmon/fault_signature.hpp"
#include "hstmon_fdi/causal_graph.hpp"

namespace hstmon::fdi {

/// One fault candidate.
struct Candidate {
  std::string name;               ///< parameter or source name ("Rpl", "Psupl")
  QualSign sign;                  ///< direction of the deviation that explains the observation
  int order;                      ///< dt edges between it and the observed node
  bool input;                     ///< true for an effort source (an input, not a component)
  std::vector<std::string> path;  ///< nodes from the observation to the edge it sits on
};

/// A branch stopped because its node, or a parameter, had already been given the opposite sign.
struct Conflict {
  std::string name;   ///< node or parameter
  QualSign held;      ///< the sign it holds (reached first)
  QualSign wanted;    ///< the sign this branch asked for
};

/// Result of backward propagation.
struct BackwardResult {
  std::vector<Candidate> candidates;  ///< in the order found (lowest delay order first)
  std::vector<Conflict> conflicts;    ///< conflicting nodes and parameters met
};

/// Backward propagation from node `start` observed with sign `sign` (±1).
/// @throws std::invalid_argument if start is not a node of g
BackwardResult backward_propagate(const CausalGraph& g, const std::string& start, int sign);

/// Parses an observation "e31+", "p_pp-", "w_m+" into node name and sign.
/// @throws std::invalid_argument without a trailing '+' or '-'
void parse_observation(const std::string& text, std::string& node, int& sign);

}  // namespace hstmon::fdi
