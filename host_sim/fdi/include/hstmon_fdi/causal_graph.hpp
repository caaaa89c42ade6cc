#pragma once
/// @file causal_graph.hpp
/// A temporal causal graph (Mosterman & Biswas 1999): nodes are bond efforts and flows,
/// effort sources and measurements; each directed edge carries a gain sign, optionally a
/// parameter with the sign of its influence, and a temporal type (instantaneous, dt =
/// integrating, 1/dt = derivative). Edges also carry their numeric gain at an operating
/// point so that forward propagation can resolve paths of opposite sign.

#include <string>
#include <string_view>
#include <vector>

namespace hstmon::fdi {

/// What a node stands for.
enum class NodeKind {
  kEffort,       ///< effort e<bond> [Pa or N·m]
  kFlow,         ///< flow f<bond> [m³/s or rad/s]
  kSource,       ///< an effort source's value (Psupl, Ps, Pbp) [Pa]: a fault candidate like a parameter
  kMeasurement,  ///< a measured channel (p_mi, p_mo, p_pp, w_m)
};

/// Temporal type of an edge.
enum class EdgeType {
  kInstant,     ///< to = gain·from (algebraic)
  kIntegral,    ///< d(to)/dt = gain·from: one delay ("dt" in the thesis)
  kDerivative,  ///< to = gain·d(from)/dt ("1/dt"); none in the thesis graph (all integral causality)
};

/// One node.
struct Node {
  std::string name;     ///< "e31", "f24", "Psupl", "p_pp"
  NodeKind kind;
  int bond;             ///< bond number for efforts and flows; 0 otherwise
  std::string meaning;  ///< physical reading, e.g. "Ppp, loading-pump outlet pressure"
  double value;         ///< value at the operating point [Pa, m³/s, N·m or rad/s]
};

/// One directed edge from → to.
struct Edge {
  int from;               ///< source node index
  int to;                 ///< target node index
  int sign;               ///< gain sign, +1 or −1
  EdgeType type;
  std::string param;      ///< parameter on the edge ("Rpl", "Kpp", "J1"), empty if none
  int param_sign;         ///< sign of ∂to/∂param with positive signals (thesis convention); 0 if none
  std::string element;    ///< bond-graph element the relation comes from ("R33", "0_pp", "TF26/29")
  std::string relation;   ///< the relation in words, e.g. "f33 = e33/Rpl"
  double gain;            ///< |∂to/∂from| at the operating point (∂(dto/dt)/∂from for dt edges) [to/from units]
  double injection;       ///< ∂to/∂ln(param) at the operating point (rate for dt edges) [to units]; 0 if none
};

/// A temporal causal graph. Node and edge indices are stable once added.
class CausalGraph {
 public:
  /// Adds a node; returns its index. @throws std::invalid_argument on a duplicate name
  int add_node(Node n);
  /// Adds an edge between existing nodes; returns its index.
  /// @throws std::invalid_argument on a bad index or a sign other than ±1
  int add_edge(Edge e);

  const std::vector<Node>& nodes() const noexcept { return nodes_; }
  const std::vector<Edge>& edges() const noexcept { return edges_; }
  /// Node index by name, or −1.
  int find(std::string_view name) const;
  /// Node index by name. @throws std::invalid_argument if absent
  int at(std::string_view name) const;
  /// Indices of the edges into node n, in insertion order (empty for no such node).
  const std::vector<int>& in_edges(int n) const;
  /// Indices of the edges out of node n, in insertion order (empty for no such node).
  const std::vector<int>& out_edges(int n) const;
  /// Distinct parameter names on edges, in first-appearance order.
  std::vector<std::string> parameters() const;

 private:
  std::vector<Node> nodes_;
  std::vector<Edge> edges_;
  std::vector<std::vector<int>> in_, out_;  ///< per node: the edges into and out of it (the propagations ask per node)
};

/// Name of an edge type as in the thesis: "" (instantaneous), "dt", "1/dt".
const char* edge_type_symbol(EdgeType t) noexcept;

}  // namespace hstmon::fdi
