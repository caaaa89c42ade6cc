/// @file causal_graph.cpp
#include "hstmon_fdi/causal_graph.hpp"

#include <algorithm>
#include <stdexcept>

namespace hstmon::fdi {

int CausalGraph::add_node(Node n) {
  if (find(n.name) >= 0) throw std::invalid_argument("duplicate node " + n.name);
  nodes_.push_back(std::move(n));
  in_.emplace_back();
  out_.emplace_back();
  return static_cast<int>(nodes_.size()) - 1;
}

int CausalGraph::add_edge(Edge e) {
  const int n = static_cast<int>(nodes_.size());
  if (e.from < 0 || e.from >= n || e.to < 0 || e.to >= n) throw std::invalid_argument("edge node index out of range");
  if (e.sign != 1 && e.sign != -1) throw std::invalid_argument("edge sign must be +1 or -1");
  if (e.param.empty() != (e.param_sign == 0)) throw std::invalid_argument("edge parameter sign without parameter");
  const int index = static_cast<int>(edges_.size());
  in_[static_cast<std::size_t>(e.to)].push_back(index);
  out_[static_cast<std::size_t>(e.from)].push_back(index);
  edges_.push_back(std::move(e));
  return index;
}

int CausalGraph::find(std::string_view name) const {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int CausalGraph::at(std::string_view name) const {
  const int i = find(name);
  if (i < 0) throw std::invalid_argument("no node " + std::string(name));
  return i;
}

const std::vector<int>& CausalGraph::in_edges(int n) const {
  static const std::vector<int> none;
  return n >= 0 && static_cast<std::size_t>(n) < in_.size() ? in_[static_cast<std::size_t>(n)] : none;
}

const std::vector<int>& CausalGraph::out_edges(int n) const {
  static const std::vector<int> none;
  return n >= 0 && static_cast<std::size_t>(n) < out_.size() ? out_[static_cast<std::size_t>(n)] : none;
}

std::vector<std::string> CausalGraph::parameters() const {
  std::vector<std::string> r;
  for (const Edge& e : edges_) {
    if (!e.param.empty() && std::find(r.begin(), r.end(), e.param) == r.end()) r.push_back(e.param);
  }
  return r;
}

const char* edge_type_symbol(EdgeType t) noexcept {
  switch (t) {
    case EdgeType::kIntegral: return "dt";
    case EdgeType::kDerivative: return "1/dt";
    default: return "";
  }
}

}  // namespace hstmon::fdi
