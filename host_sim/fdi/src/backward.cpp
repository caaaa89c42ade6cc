/// @file backward.cpp
#include "hstmon_fdi/backward.hpp"

#include <algorithm>
#include <functional>
#include <queue>
#include <stdexcept>
#include <tuple>

#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

void parse_observation(const std::string& text, std::string& node, int& sign) {
  if (text.size() < 2 || (text.back() != '+' && text.back() != '-')) {
    throw std::invalid_argument("observation must end in + or -: " + text);
  }
  sign = text.back() == '+' ? 1 : -1;
  node = text.substr(0, text.size() - 1);
}

BackwardResult backward_propagate(const CausalGraph& g, const std::string& start, int sign) {
  const int n0 = g.at(start);
  const std::size_t n = g.nodes().size();
  std::vector<QualSign> held(n, kQualZero);  // settled signs
  std::vector<int> parent(n, -1);
  BackwardResult r;
  auto path_to = [&](int node) {
    std::vector<std::string> p;
    for (int i = node; i >= 0; i = parent[static_cast<std::size_t>(i)]) p.insert(p.begin(), g.nodes()[static_cast<std::size_t>(i)].name);
    return p;
  };
  // Every parameter or source reached, kept until the end: the lowest-order finding of
  // each name is its candidate sign, and later findings of the other sign are conflicts.
  std::vector<Candidate> found;
  auto add_candidate = [&](const std::string& name, QualSign s, int order, bool input, int at) {
    found.push_back(Candidate{name, s, order, input, path_to(at)});
  };

  // Dijkstra on the number of dt edges: a node takes its sign when it is popped, so a
  // path with fewer integrations always wins over one found earlier with more.
  // Queue items: (order, sequence, node, sign, parent); ties in discovery order.
  using Item = std::tuple<int, int, int, int, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  int seq = 0;
  queue.emplace(0, seq++, n0, sign, -1);
  while (!queue.empty()) {
    const auto [order, unused, node, s_int, from] = queue.top();
    (void)unused;
    queue.pop();
    const QualSign s = qual_of(s_int);
    QualSign& h = held[static_cast<std::size_t>(node)];
    if (h != kQualZero) {
      if (h != s) r.conflicts.push_back(Conflict{g.nodes()[static_cast<std::size_t>(node)].name, h, s});
      continue;
    }
    h = s;
    parent[static_cast<std::size_t>(node)] = from;
    const Node& nd = g.nodes()[static_cast<std::size_t>(node)];
    if (nd.kind == NodeKind::kSource) {
      add_candidate(nd.name, s, order, true, node);
      continue;
    }
    for (int ei : g.in_edges(node)) {
      const Edge& e = g.edges()[static_cast<std::size_t>(ei)];
      const int next_order = order + (e.type == EdgeType::kIntegral ? 1 : 0);
      if (!e.param.empty()) add_candidate(e.param, qual_mul(e.param_sign, s), next_order, false, node);
      const QualSign want = qual_mul(e.sign, s);
      const QualSign hf = held[static_cast<std::size_t>(e.from)];
      if (hf == want) continue;
      if (hf != kQualZero) {
        r.conflicts.push_back(Conflict{g.nodes()[static_cast<std::size_t>(e.from)].name, hf, want});
        continue;
      }
      queue.emplace(next_order, seq++, e.from, static_cast<int>(want), node);
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.order < b.order; });
  for (Candidate& f : found) {
    bool seen = false;
    for (const Candidate& c : r.candidates) {
      if (c.name != f.name) continue;
      seen = true;
      if (c.sign != f.sign) r.conflicts.push_back(Conflict{f.name, c.sign, f.sign});
      break;
    }
    if (!seen) r.candidates.push_back(std::move(f));
  }
  return r;
}

}  // namespace hstmon::fdi
