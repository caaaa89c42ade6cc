/// @file fault_tree.cpp
#include "hstmon_fdi/fault_tree.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

class TreeBuilder {
 public:
  /// Precomputes each node's distance from the root along in-edges, so that every
  /// variable is expanded at one of its shallowest places (as the thesis's trees read).
  TreeBuilder(const CausalGraph& g, int root) : g_(g), dist_(g.nodes().size(), -1) {
    std::vector<int> frontier{root};
    dist_[static_cast<std::size_t>(root)] = 0;
    for (std::size_t k = 0; k < frontier.size(); ++k) {
      const int n = frontier[k];
      for (int ei : g_.in_edges(n)) {
        const int m = g_.edges()[static_cast<std::size_t>(ei)].from;
        if (dist_[static_cast<std::size_t>(m)] >= 0) continue;
        dist_[static_cast<std::size_t>(m)] = dist_[static_cast<std::size_t>(n)] + 1;
        frontier.push_back(m);
      }
    }
  }

  FaultTreeNode expand(int n, QualSign s, int depth, std::vector<int>& path) {
    const Node& node = g_.nodes()[static_cast<std::size_t>(n)];
    FaultTreeNode t{node.name, s, TreeLeaf::kNone, depth, {}};
    if (node.kind == NodeKind::kSource) {
      t.leaf = TreeLeaf::kSource;
      return t;
    }
    for (int p : path) {
      if (p == n) {
        t.leaf = TreeLeaf::kLoop;
        return t;
      }
    }
    if (depth > dist_[static_cast<std::size_t>(n)] || !expanded_.insert(n).second) {
      t.leaf = TreeLeaf::kSeeAbove;
      return t;
    }
    path.push_back(n);
    for (int ei : g_.in_edges(n)) {
      const Edge& e = g_.edges()[static_cast<std::size_t>(ei)];
      if (!e.param.empty()) {
        t.children.push_back(FaultTreeNode{e.param, qual_mul(e.param_sign, s), TreeLeaf::kParameter, depth + 1, {}});
      }
      t.children.push_back(expand(e.from, qual_mul(e.sign, s), depth + 1, path));
    }
    path.pop_back();
    return t;
  }

 private:
  const CausalGraph& g_;
  std::vector<int> dist_;
  std::set<int> expanded_;
};

void render(const FaultTreeNode& t, std::string& out) {
  out.append(static_cast<std::size_t>(2 * t.depth), ' ');
  out += t.name;
  out += qual_symbol(t.sign);
  switch (t.leaf) {
    case TreeLeaf::kParameter: out += "  [parameter]"; break;
    case TreeLeaf::kSource: out += "  [input]"; break;
    case TreeLeaf::kLoop: out += "  [loop]"; break;
    case TreeLeaf::kSeeAbove: out += "  [see above]"; break;
    default: break;
  }
  out += '\n';
  for (const FaultTreeNode& c : t.children) render(c, out);
}

void collect(const FaultTreeNode& t, std::vector<TreeCause>& out) {
  if (t.leaf == TreeLeaf::kParameter || t.leaf == TreeLeaf::kSource) {
    for (TreeCause& c : out) {
      if (c.name != t.name) continue;
      if (t.depth < c.depth) c = TreeCause{t.name, t.sign, t.depth, false};
      else if (t.depth == c.depth && t.sign != c.sign) c.ambiguous = true;
      return;
    }
    out.push_back(TreeCause{t.name, t.sign, t.depth, false});
  }
  for (const FaultTreeNode& c : t.children) collect(c, out);
}

}  // namespace

FaultTreeNode fault_tree(const CausalGraph& g, const std::string& root, int sign) {
  TreeBuilder b(g, g.at(root));
  std::vector<int> path;
  return b.expand(g.at(root), qual_of(sign), 0, path);
}

std::string render_fault_tree(const FaultTreeNode& tree) {
  std::string out;
  render(tree, out);
  return out;
}

std::vector<TreeCause> tree_causes(const FaultTreeNode& tree) {
  std::vector<TreeCause> out;
  collect(tree, out);
  std::stable_sort(out.begin(), out.end(), [](const TreeCause& a, const TreeCause& b) { return a.depth < b.depth; });
  return out;
}

}  // namespace hstmon::fdi
