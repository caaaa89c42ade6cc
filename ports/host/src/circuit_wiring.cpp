// Wiring checks of a circuit file (circuit_checks.hpp): every node is some component's
// port, and every state is connected to something that can move it. A state nothing
// reaches stays at rest whatever the machine does, so its channel would compare the
// readings with a constant.
#include <vector>

#include "circuit_checks.hpp"
#include "hstmon/circuit/laws.hpp"
#include "json_locations.hpp"

namespace hstmon::host::detail {

namespace {

using circuit::ElementKind;
using std::size_t;

/// Union-find over the nodes, then the shafts.
class Groups {
 public:
  explicit Groups(size_t n) : up_(n) {
    for (size_t i = 0; i < n; ++i) up_[i] = i;
  }
  size_t root(size_t i) const {
    while (up_[i] != i) i = up_[i];
    return i;
  }
  void join(size_t a, size_t b) { up_[root(a)] = root(b); }

 private:
  std::vector<size_t> up_;
};

/// Elements that set a flow or a torque whatever the states: they move what they touch.
bool drives(ElementKind k) noexcept {
  return k == ElementKind::kFlowSource || k == ElementKind::kCompPump || k == ElementKind::kTorque;
}

/// Boundaries and driven shafts hold their values: sources too.
std::vector<bool> held(const HostCircuit& c) {
  std::vector<bool> s;
  s.reserve(static_cast<std::size_t>(c.n_nodes + c.n_shafts));
  for (int i = 0; i < c.n_nodes; ++i) s.push_back(c.nodes[i].kind == circuit::NodeKind::kBoundary);
  for (int i = 0; i < c.n_shafts; ++i) s.push_back(c.shafts[i].driven);
  return s;
}

}  // namespace

std::optional<WiringProblem> wiring_problem(const CircuitFile& f) {
  const HostCircuit& c = f.circuit;
  const size_t nodes = f.nodes.size();
  std::vector<bool> used(nodes, false);
  std::vector<bool> source = held(c);
  Groups g(source.size());
  for (int k = 0; k < c.n_elements; ++k) {
    const circuit::Element& e = c.elements[k];
    const size_t shaft = nodes + static_cast<size_t>(e.shaft);
    const size_t at = circuit::has_ports(e.kind) ? e.a : shaft;
    if (circuit::has_ports(e.kind)) {
      used[e.a] = used[e.b] = true;
      g.join(e.a, e.b);
    }
    if (circuit::has_shaft(e.kind)) g.join(at, shaft);
    if (drives(e.kind)) source[at] = true;
  }
  for (size_t i = 0; i < nodes; ++i) {
    if (!used[i]) {
      return WiringProblem{"/nodes/" + json_pointer_token(f.nodes[i]),
                           "node '" + f.nodes[i] + "' is no component's port (connect it or remove it)"};
    }
  }
  std::vector<bool> reached(source.size(), false);
  for (size_t z = 0; z < source.size(); ++z) {
    if (source[z]) reached[g.root(z)] = true;
  }
  for (size_t z = 0; z < source.size(); ++z) {
    if (reached[g.root(z)]) continue;
    const bool node = z < nodes;
    const std::string& name = node ? f.nodes[z] : f.shafts[z - nodes];
    return WiringProblem{(node ? "/nodes/" : "/shafts/") + json_pointer_token(name),
                         (node ? "node '" : "shaft '") + name +
                             "' is a state that no boundary, driven shaft, flow source or load torque reaches through "
                             "the components: it would stay at rest"};
  }
  return std::nullopt;
}

}  // namespace hstmon::host::detail
