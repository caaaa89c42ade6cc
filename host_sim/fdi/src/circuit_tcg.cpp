/// @file circuit_tcg.cpp
/// Bond graph → temporal causal graph: one relation per junction and element in the
/// causality SCAP assigned, with the engine's slopes at the operating point as gains.
#include "hstmon_fdi/circuit_tcg.hpp"

#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>

#include "hstmon/circuit/laws.hpp"

namespace hstmon::fdi {

namespace {

using Model = host::HostCircuitModel;
using CKind = circuit::ElementKind;
using circuit::Ref;
using circuit::RefKind;

/// The model with the number r scaled by factor (other elements sharing r change too;
/// callers read one element's law only).
Model scaled(const Model& m, Ref r, double factor) {
  Model s = m;
  Model::Params p = m.params();
  Model::Inputs u = m.inputs();
  if (r.kind == RefKind::kParam) p.v[r.index] *= factor;
  if (r.kind == RefKind::kInput) u.v[r.index] *= factor;
  s.set_params(p);
  s.set_inputs(u);
  return s;
}

/// ∂law/∂ln θ for θ the number r, by a central difference (the laws are smooth in their
/// coefficients; linear ones give it to rounding).
template <class Law>
double log_derivative(const Model& m, Ref r, Law law) {
  if (r.kind == RefKind::kNone) return 0.0;
  constexpr double h = 1e-6;
  return (law(scaled(m, r, 1.0 + h)) - law(scaled(m, r, 1.0 - h))) / (std::log1p(h) - std::log1p(-h));
}

int sign_of(double v) { return v < 0.0 ? -1 : 1; }

class TcgBuilder {
 public:
  TcgBuilder(const circuit_tools::LoadedCircuit& c, const CircuitOperatingPoint& op, CircuitTcg& t)
      : f_(c.file), op_(op), m_(op.model), t_(t), bg_(t.bond_graph), els_(t.bond_graph.graph.elements),
        bonds_(t.bond_graph.graph.bonds) {}

  void build() {
    bond_values();
    // An effort detector's bond has no flow, a flow detector's no effort.
    for (const Bond& b : bonds_) {
      if (b.to.rfind("Df_", 0) != 0) add_node("e" + std::to_string(b.number), NodeKind::kEffort, b.number, e_val_[idx(b)], effort_meaning(b));
      if (b.to.rfind("De_", 0) != 0) add_node("f" + std::to_string(b.number), NodeKind::kFlow, b.number, f_val_[idx(b)], flow_meaning(b));
    }
    for (std::size_t i = 0; i < els_.size(); ++i) element_relations(i);
    for (std::size_t i = 0; i < els_.size(); ++i) sensor(i);
  }

 private:
  std::size_t idx(const Bond& b) const { return static_cast<std::size_t>(b.number - 1); }
  const CircuitElementSource& src(const std::string& name) const {
    return bg_.sources[static_cast<std::size_t>(bg_.element_index(name))];
  }
  bool is_kind(const std::string& name, ElementKind k) const {
    const int i = bg_.element_index(name);
    return i >= 0 && els_[static_cast<std::size_t>(i)].kind == k;
  }
  bool is_shaft_junction(const std::string& name) const {
    return is_kind(name, ElementKind::kOne) && src(name).shaft >= 0 && src(name).element < 0;
  }
  std::vector<std::size_t> bonds_of(const std::string& name) const {
    std::vector<std::size_t> r;
    for (std::size_t b = 0; b < bonds_.size(); ++b) {
      if (bonds_[b].from == name || bonds_[b].to == name) r.push_back(b);
    }
    return r;
  }
  /// +1 if bond b points into element `name`, −1 if it leaves it.
  int into(std::size_t b, const std::string& name) const { return bonds_[b].to == name ? 1 : -1; }
  const std::string& other(std::size_t b, const std::string& name) const {
    return bonds_[b].to == name ? bonds_[b].from : bonds_[b].to;
  }
  double zv(int k) const { return op_.z[static_cast<std::size_t>(k)]; }
  double omega(int shaft) const { return zv(Model::kNodes + shaft); }

  circuit::Flow<double> flow_of(const Model& m, int e) const {
    const circuit::Element& el = f_.circuit.elements[e];
    return circuit::element_flow(el.kind, m.coeffs(e), zv(el.a), zv(el.b), el.shaft >= 0 ? omega(el.shaft) : 0.0);
  }
  double torque_of(const Model& m, int e) const {
    const circuit::Element& el = f_.circuit.elements[e];
    double da, db, dw;
    const bool ports = circuit::has_ports(el.kind);
    return circuit::element_torque(el.kind, m.coeffs(e), ports ? zv(el.a) : 0.0, ports ? zv(el.b) : 0.0,
                                   omega(el.shaft), da, db, dw);
  }
  /// Sign of a hydraulic bond's flow relative to element e's flow a→b: +1 leaving node a's
  /// junction or entering node b's, or inside the element (1-junction ↔ core); −1 otherwise.
  int port_sign(std::size_t b, int e) const {
    const circuit::Element& el = f_.circuit.elements[e];
    for (const std::string* end : {&bonds_[b].from, &bonds_[b].to}) {
      if (!is_kind(*end, ElementKind::kZero)) continue;
      const int node = src(*end).node;
      const bool leaves = bonds_[b].from == *end;
      if (node == el.a) return leaves ? 1 : -1;
      if (node == el.b) return leaves ? -1 : 1;
    }
    return 1;
  }

  // ---- values at the operating point ----------------------------------------------

  void bond_values() {
    const std::size_t n = bonds_.size();
    std::vector<std::optional<double>> e(n), f(n);
    for (std::size_t b = 0; b < n; ++b) {
      const Bond& bd = bonds_[b];
      for (const std::string* end : {&bd.from, &bd.to}) {
        if (is_kind(*end, ElementKind::kZero)) e[b] = zv(src(*end).node);
        if (is_shaft_junction(*end)) f[b] = omega(src(*end).shaft);
      }
      if (bd.to.rfind("De_", 0) == 0) f[b] = 0.0;
      if (bd.to.rfind("Df_", 0) == 0) e[b] = 0.0;
      // Element bonds: flows of two-ports, torques on shafts.
      for (const std::string* end : {&bd.from, &bd.to}) {
        const CircuitElementSource& s = src(*end);
        if (s.element < 0 || s.channel >= 0) continue;
        const CKind k = f_.circuit.elements[s.element].kind;
        const std::string& o = other(b, *end);
        if (is_shaft_junction(o)) {
          // TF → shaft: the machine's torque; shaft → R or Se: the torque drawn (friction, load).
          const double tq = torque_of(m_, s.element);
          e[b] = bd.to == o ? tq : -tq;
        } else if (circuit::has_ports(k)) {
          f[b] = port_sign(b, s.element) * flow_of(m_, s.element).q;
        }
      }
    }
    // The rest from the junctions: a 0-junction's flows and a 1-junction's efforts sum to
    // zero with the half-arrows' signs; its common variable is shared.
    for (bool changed = true; changed;) {
      changed = false;
      for (const Element& el : els_) {
        const bool zero = el.kind == ElementKind::kZero;
        if (!zero && el.kind != ElementKind::kOne) continue;
        auto& common = zero ? e : f;
        auto& summed = zero ? f : e;
        const std::vector<std::size_t> bs = bonds_of(el.name);
        std::optional<double> c;
        for (std::size_t b : bs) {
          if (common[b]) c = common[b];
        }
        for (std::size_t b : bs) {
          if (!common[b] && c && !is_detector_other(b, el.name, !zero)) {
            common[b] = c;
            changed = true;
          }
        }
        int open = 0;
        std::size_t k = 0;
        double sum = 0.0;
        for (std::size_t b : bs) {
          if (is_detector_other(b, el.name, zero)) continue;
          if (!summed[b]) {
            ++open;
            k = b;
          } else {
            sum += into(b, el.name) * *summed[b];
          }
        }
        if (open == 1) {
          summed[k] = -into(k, el.name) * sum;
          changed = true;
        }
      }
    }
    e_val_.resize(n);
    f_val_.resize(n);
    for (std::size_t b = 0; b < n; ++b) {
      e_val_[b] = e[b].value_or(0.0);
      f_val_[b] = f[b].value_or(0.0);
    }
  }
  /// True when bond b of junction j goes to a detector that has no variable of this kind
  /// (an effort detector has no flow, a flow detector no effort).
  bool is_detector_other(std::size_t b, const std::string& j, bool flow) const {
    const std::string& o = other(b, j);
    return flow ? o.rfind("De_", 0) == 0 : o.rfind("Df_", 0) == 0;
  }

  // ---- nodes and edges ------------------------------------------------------------

  void add_node(const std::string& name, NodeKind kind, int bond, double value, const std::string& meaning) {
    t_.graph.add_node(Node{name, kind, bond, meaning, value});
  }
  std::string e_(std::size_t b) const { return "e" + std::to_string(bonds_[b].number); }
  std::string f_n(std::size_t b) const { return "f" + std::to_string(bonds_[b].number); }
  std::string effort_meaning(const Bond& b) const {
    if (is_kind(b.from, ElementKind::kZero)) return "pressure " + f_.nodes[static_cast<std::size_t>(src(b.from).node)];
    if (is_kind(b.to, ElementKind::kZero)) return "pressure " + f_.nodes[static_cast<std::size_t>(src(b.to).node)];
    if (is_shaft_junction(b.to) || is_shaft_junction(b.from)) return "torque on " + f_.shafts[static_cast<std::size_t>(src(is_shaft_junction(b.to) ? b.to : b.from).shaft)];
    return "effort " + b.from + " -> " + b.to;
  }
  std::string flow_meaning(const Bond& b) const {
    if (is_shaft_junction(b.from) || is_shaft_junction(b.to)) return "speed of " + f_.shafts[static_cast<std::size_t>(src(is_shaft_junction(b.to) ? b.to : b.from).shaft)];
    return "flow " + b.from + " -> " + b.to;
  }

  void link(const std::string& from, const std::string& to, int sign, const std::string& element, const std::string& relation) {
    t_.graph.add_edge(Edge{t_.graph.at(from), t_.graph.at(to), sign, EdgeType::kInstant, "", 0, element, relation, 1.0, 0.0});
  }
  /// The value a relation computes, as a function of the model's numbers (for injections).
  using Law = std::function<double(const Model&)>;

  /// An element relation from → to carrying the element's parameter and, as parallel
  /// edges of gain 0 (the relation's slope is counted once), each extra parameter with its
  /// own injection from `law`.
  void param_edge(const std::string& from, const std::string& to, int sign, EdgeType type, const Element& el,
                  int structural_sign, double gain, double injection, double scale, const std::string& relation,
                  const Law& law = nullptr) {
    const CircuitElementSource& s = src(el.name);
    add_param_edge(from, to, sign, type, el.name, el.parameter, s.ref, structural_sign, gain, injection, scale, relation);
    for (const auto& [name, ref] : s.extra) {
      const double inj = law ? log_derivative(m_, ref, law) : 0.0;
      // Without an injection here (a storage's V), its sign with positive signals: K = β/V.
      add_param_edge(from, to, sign, type, el.name, name, ref, type == EdgeType::kIntegral ? -structural_sign : 1, 0.0,
                     inj, scale, relation + " (" + name + ")");
    }
  }
  void add_param_edge(const std::string& from, const std::string& to, int sign, EdgeType type, const std::string& element,
                      const std::string& p, Ref ref, int structural_sign, double gain, double injection, double scale,
                      const std::string& relation) {
    int ps = 0;
    if (!p.empty()) {
      // The sign of the parameter's influence at the operating point; where it injects
      // nothing there (C, I at a steady state, a shut valve), its sign with positive signals.
      ps = std::fabs(injection) > 1e-12 * scale ? sign_of(injection) : structural_sign;
      register_param(p, ref, false);
    }
    t_.graph.add_edge(Edge{t_.graph.at(from), t_.graph.at(to), sign, type, p, ps, element, relation, gain,
                           p.empty() ? 0.0 : injection});
  }
  void register_param(const std::string& name, Ref r, bool source) {
    for (const GraphParameter& g : t_.parameters) {
      if (g.name == name) return;
    }
    t_.parameters.push_back(GraphParameter{name, named_ref(f_, r), r, source});
  }

  void element_relations(std::size_t i) {
    const Element& el = els_[i];
    const CircuitElementSource& s = bg_.sources[i];
    const std::vector<std::size_t> bs = bonds_of(el.name);
    switch (el.kind) {
      case ElementKind::kZero:
      case ElementKind::kOne:
        junction(el, bs);
        break;
      case ElementKind::kC: {
        const std::size_t b = bs.at(0);
        const double K = m_.node_stiffness(s.node);
        param_edge(f_n(b), e_(b), into(b, el.name), EdgeType::kIntegral, el, 1, K, 0.0, 1.0,
                   "d" + e_(b) + "/dt = K*" + f_n(b));
        break;
      }
      case ElementKind::kI: {
        const std::size_t b = bs.at(0);
        // The engine keeps 1/J beside the capacitances, after the nodes.
        const double inv_J = m_.node_stiffness(Model::kNodes + s.shaft);
        param_edge(e_(b), f_n(b), into(b, el.name), EdgeType::kIntegral, el, -1, inv_J, 0.0, 1.0,
                   "d" + f_n(b) + "/dt = " + e_(b) + "/J");
        break;
      }
      case ElementKind::kR:
        resistance(el, s, bs.at(0));
        break;
      case ElementKind::kTF:
        transformer(el, s, bs);
        break;
      case ElementKind::kSe:
      case ElementKind::kSf: {
        const std::size_t b = bs.at(0);
        const bool effort = el.kind == ElementKind::kSe;
        if (t_.graph.find(el.parameter) < 0) {
          add_node(el.parameter, NodeKind::kSource, bonds_[b].number, effort ? e_val_[b] : f_val_[b], el.meaning);
          register_param(el.parameter, src(el.name).ref, true);
        }
        link(el.parameter, effort ? e_(b) : f_n(b), 1, el.name, (effort ? e_(b) : f_n(b)) + " = " + el.parameter);
        break;
      }
      default:
        break;
    }
  }

  void junction(const Element& el, const std::vector<std::size_t>& bs) {
    const bool zero = el.kind == ElementKind::kZero;
    // The bond that imposes the common variable: at a 0-junction the one bringing the
    // effort in, at a 1-junction the one the junction gives the effort to.
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::size_t k = kNone;
    for (std::size_t b : bs) {
      if ((bg_.effort_by[b] == el.name) != zero) k = b;
    }
    if (k == kNone) return;
    const std::string common_k = zero ? e_(k) : f_n(k);
    const std::string sum_k = zero ? f_n(k) : e_(k);
    std::string rel = sum_k + " =";
    for (std::size_t b : bs) {
      if (b == k || is_detector_other(b, el.name, zero)) continue;
      rel += (-into(b, el.name) * into(k, el.name) > 0 ? " + " : " - ") + (zero ? f_n(b) : e_(b));
    }
    for (std::size_t b : bs) {
      if (b == k) continue;
      if (!is_detector_other(b, el.name, !zero)) {
        link(common_k, zero ? e_(b) : f_n(b), 1, el.name, zero ? "common pressure" : "common flow");
      }
      if (!is_detector_other(b, el.name, zero)) {
        link(zero ? f_n(b) : e_(b), sum_k, -into(b, el.name) * into(k, el.name), el.name, rel);
      }
    }
  }

  void resistance(const Element& el, const CircuitElementSource& s, std::size_t b) {
    const int e = s.element;
    const CKind k = f_.circuit.elements[e].kind;
    const double scale = std::fabs(e_val_[b]) + std::fabs(f_val_[b]);
    if (k == CKind::kFriction) {
      // Torque drawn c·ω: resistance form (the shaft's speed in, torque out).
      const double c = m_.coeffs(e).c[0];
      const double inj = log_derivative(m_, s.ref, [&](const Model& m) { return -torque_of(m, e); });
      if (bg_.effort_by[b] == el.name) {
        param_edge(f_n(b), e_(b), 1, EdgeType::kInstant, el, 1, c, inj, scale, e_(b) + " = c*" + f_n(b));
      } else {
        param_edge(e_(b), f_n(b), 1, EdgeType::kInstant, el, -1, 1.0 / c, -inj / c, scale, f_n(b) + " = " + e_(b) + "/c");
      }
      return;
    }
    const int ps = port_sign(b, e);
    const double g = flow_of(m_, e).dpa;
    const double inj = log_derivative(m_, s.ref, [&](const Model& m) { return ps * flow_of(m, e).q; });
    const int structural = k == CKind::kLaminar ? -1 : 1;
    if (bg_.effort_by[b] == el.name) {
      if (!(g > 0.0)) throw std::invalid_argument(el.name + ": resistance causality at zero conductance");
      param_edge(f_n(b), e_(b), 1, EdgeType::kInstant, el, -structural, 1.0 / g, -inj / g, scale,
                 e_(b) + " = Q^-1(" + f_n(b) + ")");
    } else {
      param_edge(e_(b), f_n(b), 1, EdgeType::kInstant, el, structural, g, inj, scale,
                 f_n(b) + " = Q(" + e_(b) + ")", [&, e, ps](const Model& m) { return ps * flow_of(m, e).q; });
    }
  }

  void transformer(const Element& el, const CircuitElementSource& s, const std::vector<std::size_t>& bs) {
    const int e = s.element;
    std::size_t h = bs.at(0), m = bs.at(1);
    if (is_shaft_junction(other(h, el.name))) std::swap(h, m);
    const double D = m_.coeffs(e).c[0];
    // The hydraulic bond carries pa − pb unless it enters node b from the machine (a pump
    // from a held pressure): then its effort is pb and the torque is −D·pb.
    const int se = bonds_[h].from == el.name ? -1 : 1;
    const int sd = sign_of(D);
    const double aD = std::fabs(D);
    const double scale_m = std::fabs(e_val_[m]) + 1e-300, scale_h = std::fabs(f_val_[h]) + 1e-300;
    const double inj_tq = log_derivative(m_, s.ref, [&](const Model& mm) { return torque_of(mm, e); });
    const double inj_q = log_derivative(m_, s.ref, [&](const Model& mm) { return port_sign(h, e) * flow_of(mm, e).q; });
    if (bg_.effort_by[h] != el.name) {
      param_edge(e_(h), e_(m), sd * se, EdgeType::kInstant, el, 1, aD, inj_tq, scale_m, e_(m) + " = D*" + e_(h),
                 [&, e](const Model& mm) { return torque_of(mm, e); });
      param_edge(f_n(m), f_n(h), sd, EdgeType::kInstant, el, 1, aD, inj_q, scale_h, f_n(h) + " = D*" + f_n(m),
                 [&, e, h](const Model& mm) { return port_sign(h, e) * flow_of(mm, e).q; });
    } else {
      param_edge(e_(m), e_(h), sd * se, EdgeType::kInstant, el, -1, 1.0 / aD, -e_val_[h], std::fabs(e_val_[h]) + 1e-300,
                 e_(h) + " = " + e_(m) + "/D");
      param_edge(f_n(h), f_n(m), sd, EdgeType::kInstant, el, -1, 1.0 / aD, -f_val_[m], std::fabs(f_val_[m]) + 1e-300,
                 f_n(m) + " = " + f_n(h) + "/D");
    }
  }

  void sensor(std::size_t i) {
    const Element& el = els_[i];
    if (el.kind != ElementKind::kDetector) return;
    const CircuitElementSource& s = bg_.sources[i];
    const std::string& name = f_.sensors[static_cast<std::size_t>(s.channel)].name;
    const std::vector<std::size_t> bs = bonds_of(el.name);
    const bool pressure = el.name.rfind("De_", 0) == 0;
    std::string from;
    int sign = 1;
    double value = 0.0;
    if (!bs.empty()) {
      from = pressure ? e_(bs[0]) : f_n(bs[0]);
      value = pressure ? e_val_[bs[0]] : f_val_[bs[0]];
    } else if (pressure) {
      value = zv(s.node);  // a held pressure: a constant
    } else {
      // A one-port's flow (no common-flow junction): read off its hydraulic bond, with the
      // bond's sign relative to the element's a→b flow. None if the element is shut.
      value = flow_of(m_, s.element).q;
      for (std::size_t b = 0; b < bonds_.size() && from.empty(); ++b) {
        for (const std::string* end : {&bonds_[b].from, &bonds_[b].to}) {
          const CircuitElementSource& cs = src(*end);
          if (cs.element != s.element || cs.channel >= 0 || is_shaft_junction(other(b, *end))) continue;
          from = f_n(b);
          sign = port_sign(b, s.element);
        }
      }
    }
    add_node(name, NodeKind::kMeasurement, 0, value, "measured " + name);
    if (!from.empty()) link(from, name, sign, el.name, name + " = " + (sign > 0 ? "" : "-") + from);
    t_.measured.push_back(name);
  }

  const host::CircuitFile& f_;
  const CircuitOperatingPoint& op_;
  const Model& m_;
  CircuitTcg& t_;
  const CircuitBondGraph& bg_;
  const std::vector<Element>& els_;
  const std::vector<Bond>& bonds_;
  std::vector<double> e_val_, f_val_;
};

}  // namespace

std::optional<std::string> circuit_operating_point(const circuit_tools::LoadedCircuit& c, const Model::Params& p,
                                                   const Model::Inputs& u, CircuitOperatingPoint& out) {
  out.model = Model(c.file.circuit, p, u);
  if (!out.model.valid()) return "circuit " + c.file.name + ": the values make no physical circuit";
  double z[circuit::kExtent<Model::kZ>];
  if (!out.model.steady_full(z)) return "circuit " + c.file.name + ": no steady state at these inputs";
  out.z.assign(std::begin(z), std::end(z));
  return std::nullopt;
}

CircuitTcg circuit_tcg(const circuit_tools::LoadedCircuit& c, const CircuitOperatingPoint& op) {
  CircuitTcg t;
  if (const auto err = circuit_bond_graph(c, op.model, op.z, t.bond_graph)) throw std::invalid_argument(*err);
  TcgBuilder(c, op, t).build();
  // Measured nodes in channel order (the detectors were added in that order).
  return t;
}

std::vector<ParamStep> circuit_fault_steps(const CircuitTcg& t, const std::string& name, int sign) {
  std::vector<ParamStep> steps;
  for (const GraphParameter& g : t.parameters) {
    if (g.circuit_name == name) steps.push_back(ParamStep{g.name, sign});
  }
  if (!steps.empty()) return steps;
  for (const GraphParameter& g : t.parameters) {
    if (g.name == name) return {ParamStep{g.name, sign}};
  }
  throw std::invalid_argument("no parameter, input or graph parameter '" + name + "' on the graph");
}

std::vector<std::string> circuit_graph_faults(const CircuitTcg& t) {
  std::vector<std::string> r;
  for (const GraphParameter& g : t.parameters) {
    if (g.circuit_name.empty()) continue;
    bool seen = false;
    for (const std::string& n : r) seen = seen || n == g.circuit_name;
    if (!seen) r.push_back(g.circuit_name);
  }
  return r;
}

}  // namespace hstmon::fdi
