#pragma once
/// @file fault_tree.hpp
/// Fault trees (thesis §2.4, Figs. 2.8–2.11): from an observed deviation of a node, the
/// antecedents of Table 2.4 (the in-edges of the causal graph) expanded down to
/// parameters and sources, each with the sign of change that explains the deviation.

#include <string>
#include <vector>

#include "hstmon/fault_signature.hpp"
#include "hstmon_fdi/causal_graph.hpp"

namespace hstmon::fdi {

/// How a fault-tree entry ends.
enum class TreeLeaf {
  kNone,         ///< an expanded variable
  kParameter,    ///< a parameter (cause event)
  kSource,       ///< an effort source (an input: Psupl, Ps, Pbp)
  kLoop,         ///< the variable is already on the path to the root (feedback loop)
  kSeeAbove,     ///< the variable was expanded earlier in the tree
};

/// One entry of a fault tree.
struct FaultTreeNode {
  std::string name;    ///< node or parameter name
  QualSign sign;       ///< direction of change that explains the root event
  TreeLeaf leaf;
  int depth;           ///< distance from the root (root = 0)
  std::vector<FaultTreeNode> children;
};

/// Fault tree of node `root` deviating with `sign` (±1), written depth-first in edge order.
/// Each variable is expanded once, at one of its shallowest places; its other
/// occurrences are kSeeAbove leaves (kLoop when on their own path to the root).
/// @throws std::invalid_argument if root is not a node of g
FaultTreeNode fault_tree(const CausalGraph& g, const std::string& root, int sign);

/// The tree as indented text, two spaces per level, e.g. "  f31+ [Kpp+ on dt edge]".
std::string render_fault_tree(const FaultTreeNode& tree);

/// A parameter or source reached in a tree, at its shallowest depth.
struct TreeCause {
  std::string name;  ///< parameter or source
  QualSign sign;     ///< sign at the shallowest occurrence
  int depth;         ///< that depth
  bool ambiguous;    ///< also reached with the opposite sign at the same depth
};

/// Causes (parameters and sources) of a tree, each at its shallowest occurrence, in
/// order of depth then first appearance.
std::vector<TreeCause> tree_causes(const FaultTreeNode& tree);

}  // namespace hstmon::fdi
