/// @file circuit_bond_graph.cpp
/// Element-by-element bond graph of a circuit file, then sequential causality assignment
/// (Karnopp's SCAP): fixed causalities, integral storages, propagation, free R last.
#include "hstmon_fdi/circuit_bond_graph.hpp"

#include <cstddef>
#include <initializer_list>
#include <map>

#include "hstmon/circuit/laws.hpp"

namespace hstmon::fdi {

namespace {

using CKind = circuit::ElementKind;
using circuit::Ref;
using circuit::RefKind;

/// The core element of a hydraulic element's bond graph: a resistance, a transformer
/// (machine displacement) or a flow source.
struct HydraulicCore {
  CKind element;
  const char* prefix;  ///< of the core's name, before the element's
  ElementKind kind;
  const char* meaning;  ///< what it stands for, before the element's name
  circuit::Slot slot;   ///< the number it is given by (an orifice's or valve's: k or area)
};

constexpr HydraulicCore kHydraulicCores[] = {
    {CKind::kOrifice, "R_", ElementKind::kR, "orifice", circuit::kK},
    {CKind::kPoppet, "R_", ElementKind::kR, "relief or check valve", circuit::kK},
    {CKind::kLaminar, "R_", ElementKind::kR, "laminar leakage", circuit::kR},
    {CKind::kCompPump, "R_", ElementKind::kR, "pressure-compensated pump (flow falls with its pressure rise)",
     circuit::kQ0},
    {CKind::kMachine, "TF_", ElementKind::kTF, "pump or motor displacement", circuit::kD},
    {CKind::kFlowSource, "Sf_", ElementKind::kSf, "flow source", circuit::kQ},
};

/// The core of element kind k; nullptr for a kind with none (friction, torque).
const HydraulicCore* hydraulic_core(CKind k) {
  for (const HydraulicCore& hc : kHydraulicCores) {
    if (hc.element == k) return &hc;
  }
  return nullptr;
}

/// The first of refs given (kind ≠ none), or a none Ref.
Ref first_given(std::initializer_list<Ref> refs) {
  for (Ref r : refs) {
    if (r.kind != RefKind::kNone) return r;
  }
  return Ref{};
}

class Builder {
 public:
  Builder(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel& at, const std::vector<double>& z,
          CircuitBondGraph& g)
      : f_(c.file), m_(at), z_(z), g_(g) {}

  std::optional<std::string> build() {
    const host::HostCircuit& d = f_.circuit;
    node_junction_.assign(d.n_nodes, "");
    shaft_junction_.assign(d.n_shafts, "");
    for (int i = 0; i < d.n_nodes; ++i) add_node(i);
    for (int s = 0; s < d.n_shafts; ++s) add_shaft(s);
    for (int e = 0; e < d.n_elements; ++e) add_element(e);
    for (int ch = 0; ch < d.n_channels; ++ch) add_sensor(ch);
    return assign_causality();
  }

 private:
  int add(const std::string& name, ElementKind kind, const std::string& parameter, const std::string& meaning,
          CircuitElementSource src) {
    g_.graph.elements.push_back(Element{name, kind, parameter, meaning});
    g_.sources.push_back(src);
    return static_cast<int>(g_.graph.elements.size()) - 1;
  }
  void bond(const std::string& from, const std::string& to) {
    g_.graph.bonds.push_back(Bond{static_cast<int>(g_.graph.bonds.size()) + 1, from, to});
  }

  /// The parameter name on an element: "<owner>.<field>" when r names a circuit parameter
  /// or input, "" when the number is a literal (nothing to diagnose).
  std::string param(const std::string& owner, const char* field, Ref r) const {
    return named_ref(f_, r).empty() ? "" : graph_parameter_name(owner, field);
  }
  /// Adds number r as an extra parameter "<owner>.<field>" of src when it names a circuit
  /// parameter or input other than the element's own.
  void add_extra(CircuitElementSource& src, const std::string& owner, const char* field, Ref r) const {
    if (named_ref(f_, r).empty() || (r.kind == src.ref.kind && r.index == src.ref.index)) return;
    src.extra.emplace_back(graph_parameter_name(owner, field), r);
  }
  /// A source's name: the input or parameter it is, else "<owner>.<field>".
  std::string source_name(const std::string& owner, const char* field, Ref r) const {
    const std::string n = named_ref(f_, r);
    return n.empty() ? graph_parameter_name(owner, field) : n;
  }

  void add_node(int i) {
    const circuit::Node& n = f_.circuit.nodes[i];
    const std::string& name = f_.nodes[static_cast<std::size_t>(i)];
    CircuitElementSource src;
    src.node = i;
    if (n.kind == circuit::NodeKind::kBoundary) {
      // A boundary held at a literal pressure (tank, drain) is a constant: no junction.
      if (named_ref(f_, n.pressure).empty()) return;
      const std::string j = "0_" + name;
      add(j, ElementKind::kZero, "", "boundary " + name + ": common pressure", src);
      src.ref = n.pressure;
      add("Se_" + name, ElementKind::kSe, source_name(name, "p", n.pressure), "pressure held at " + name, src);
      bond("Se_" + name, j);
      node_junction_[static_cast<std::size_t>(i)] = j;
      return;
    }
    const std::string j = "0_" + name;
    add(j, ElementKind::kZero, "", "volume " + name + ": common pressure", src);
    const bool by_K = n.K.kind != RefKind::kNone;
    src.ref = by_K ? n.K : n.beta;
    if (!by_K) add_extra(src, name, "V", n.volume);
    add("C_" + name, ElementKind::kC, param(name, by_K ? "K" : "beta", src.ref), "compressibility of " + name, src);
    bond(j, "C_" + name);
    node_junction_[static_cast<std::size_t>(i)] = j;
  }

  void add_shaft(int s) {
    const circuit::Shaft& sh = f_.circuit.shafts[s];
    const std::string& name = f_.shafts[static_cast<std::size_t>(s)];
    const std::string j = "1_shaft_" + name;
    CircuitElementSource src;
    src.shaft = s;
    add(j, ElementKind::kOne, "", "shaft " + name + ": common speed", src);
    shaft_junction_[static_cast<std::size_t>(s)] = j;
    if (sh.driven) {
      src.ref = sh.speed;
      add("Sf_" + name, ElementKind::kSf, source_name(name, "speed", sh.speed), "speed imposed on " + name, src);
      bond("Sf_" + name, j);
    } else {
      src.ref = sh.J;
      add("I_" + name, ElementKind::kI, param(name, "J", sh.J), "inertia of " + name, src);
      bond(j, "I_" + name);
    }
  }

  void add_element(int e) {
    const circuit::Element& el = f_.circuit.elements[e];
    const std::string& name = f_.elements[static_cast<std::size_t>(e)];
    CircuitElementSource src;
    src.element = e;
    switch (el.kind) {
      case CKind::kFriction: {
        src.ref = el.r[circuit::kC];
        add("R_" + name, ElementKind::kR, param(name, "c", src.ref), "viscous friction on the shaft", src);
        bond(shaft_junction_[static_cast<std::size_t>(el.shaft)], "R_" + name);
        return;
      }
      case CKind::kTorque: {
        src.ref = el.r[circuit::kTau];
        add("Se_" + name, ElementKind::kSe, source_name(name, "tau", src.ref), "load torque", src);
        bond(shaft_junction_[static_cast<std::size_t>(el.shaft)], "Se_" + name);
        return;
      }
      default:
        break;
    }
    // A shut orifice (a directional valve's closed paths) or a valve below its cracking
    // pressure passes nothing and has no conductance at this point.
    if ((el.kind == CKind::kOrifice || el.kind == CKind::kPoppet) &&
        circuit::element_flow(el.kind, m_.coeffs(e), z_[el.a], z_[el.b], 0.0).dpa == 0.0) {
      return;
    }
    const std::string& ja = node_junction_[el.a];
    const std::string& jb = node_junction_[el.b];
    if (ja.empty() && jb.empty()) return;  // between two held pressures: no state sees it
    const HydraulicCore* hc = hydraulic_core(el.kind);
    if (hc == nullptr) return;
    const bool orifice_like = el.kind == CKind::kOrifice || el.kind == CKind::kPoppet;
    // An orifice or valve is given by k, else by its area (with Cd and rho).
    src.ref = orifice_like ? first_given({el.r[circuit::kK], el.r[circuit::kArea]}) : el.r[hc->slot];
    const std::string core = hc->prefix + name;
    const ElementKind kind = hc->kind;
    const std::string meaning = hc->meaning;
    if (orifice_like) {
      if (el.r[circuit::kK].kind == RefKind::kNone) {
        add_extra(src, name, "Cd", el.r[circuit::kCd]);
        add_extra(src, name, "rho", el.r[circuit::kRho]);
      }
      if (el.kind == CKind::kOrifice) add_extra(src, name, "opening", el.r[circuit::kOpening]);
      if (el.kind == CKind::kPoppet) {
        add_extra(src, name, "crack", el.r[circuit::kCrack]);
        add_extra(src, name, "full", el.r[circuit::kFull]);
      }
    } else if (el.kind == CKind::kCompPump) {
      add_extra(src, name, "R", el.r[circuit::kRleak]);
      add_extra(src, name, "Pc", el.r[circuit::kPc]);
      add_extra(src, name, "Pk", el.r[circuit::kPk]);
      add_extra(src, name, "Pmax", el.r[circuit::kPmax]);
    } else if (el.kind == CKind::kMachine) {
      add_extra(src, name, "fraction", el.r[circuit::kFraction]);
    }
    const char* field = el.kind == CKind::kMachine    ? "D"
                        : el.kind == CKind::kLaminar  ? "R"
                        : el.kind == CKind::kCompPump ? "Q0"
                        : el.kind == CKind::kFlowSource ? "Q"
                        : (orifice_like && el.r[circuit::kK].kind == RefKind::kNone) ? "A"
                                                                                  : "k";
    const std::string parameter =
        kind == ElementKind::kSf ? source_name(name, field, src.ref) : param(name, field, src.ref);
    add(core, kind, parameter, meaning + " " + name, src);
    std::string hydraulic_end;  // where the core element's hydraulic bond attaches
    if (!ja.empty() && !jb.empty()) {
      hydraulic_end = "1_" + name;
      add(hydraulic_end, ElementKind::kOne, "", name + ": common flow", src);
      bond(ja, hydraulic_end);
      bond(hydraulic_end, jb);
    }
    if (kind == ElementKind::kSf) {
      if (!hydraulic_end.empty()) bond(core, hydraulic_end);
      else if (!ja.empty()) bond(ja, core);
      else bond(core, jb);
    } else if (!hydraulic_end.empty()) {
      bond(hydraulic_end, core);
    } else if (!ja.empty()) {
      bond(ja, core);
    } else if (kind == ElementKind::kTF) {
      bond(core, jb);  // a pump from a held pressure: power from the shaft into node b
    } else {
      bond(jb, core);
    }
    if (kind == ElementKind::kTF) bond(core, shaft_junction_[static_cast<std::size_t>(el.shaft)]);
    element_hydraulic_[e] = hydraulic_end;
  }

  void add_sensor(int ch) {
    const circuit::Channel& c = f_.circuit.channels[ch];
    const std::string& name = f_.sensors[static_cast<std::size_t>(ch)].name;
    CircuitElementSource src;
    src.channel = ch;
    if (c.kind == circuit::ChannelKind::kPressure) {
      src.node = c.index;
      add("De_" + name, ElementKind::kDetector, "", "pressure sensor " + name, src);
      const std::string& j = node_junction_[c.index];
      if (!j.empty()) bond(j, "De_" + name);
    } else if (c.kind == circuit::ChannelKind::kSpeed) {
      src.shaft = c.index;
      add("Df_" + name, ElementKind::kDetector, "", "speed sensor " + name, src);
      bond(shaft_junction_[c.index], "Df_" + name);
    } else {
      src.element = c.index;
      add("Df_" + name, ElementKind::kDetector, "", "flow sensor " + name, src);
      const auto it = element_hydraulic_.find(c.index);
      // Through a two-port's common-flow junction; a one-port's flow is read off its bond.
      if (it != element_hydraulic_.end() && !it->second.empty()) bond(it->second, "Df_" + name);
    }
  }

  // ---- causality -------------------------------------------------------------------
  // effort_by per bond: +1 the 'to' element imposes the effort, −1 the 'from' one, 0 open.

  int end_code(std::size_t b, const std::string& element) const {
    return g_.graph.bonds[b].to == element ? 1 : -1;
  }
  bool set(std::size_t b, int code) {
    if (cause_[b] == code) return false;
    if (cause_[b] != 0) {
      conflict_ = "bond " + std::to_string(g_.graph.bonds[b].number) + " (" + g_.graph.bonds[b].from + " -> " +
                  g_.graph.bonds[b].to + ") is asked for both causalities";
      return false;
    }
    cause_[b] = code;
    return true;
  }
  std::vector<std::size_t> bonds_of(const std::string& element) const {
    std::vector<std::size_t> r;
    for (std::size_t b = 0; b < g_.graph.bonds.size(); ++b) {
      if (g_.graph.bonds[b].from == element || g_.graph.bonds[b].to == element) r.push_back(b);
    }
    return r;
  }

  /// Junction and transformer rules until nothing changes; false on a conflict.
  bool propagate() {
    for (bool changed = true; changed && conflict_.empty();) {
      changed = false;
      for (const Element& el : g_.graph.elements) {
        const std::vector<std::size_t> bs = bonds_of(el.name);
        if (el.kind == ElementKind::kZero || el.kind == ElementKind::kOne) {
          // 0: exactly one bond brings the effort in; 1: exactly one bond takes it out
          // (that bond brings the common flow in).
          const bool zero = el.kind == ElementKind::kZero;
          int special = 0, open = 0;
          for (std::size_t b : bs) {
            if (cause_[b] == 0) ++open;
            else if ((cause_[b] == end_code(b, el.name)) != zero) ++special;
          }
          if (special > 1) {
            conflict_ = el.name + (zero ? " has two bonds imposing its effort" : " has two bonds imposing its flow");
            return false;
          }
          for (std::size_t b : bs) {
            if (cause_[b] != 0) continue;
            const int by_junction = end_code(b, el.name), by_other = -by_junction;
            if (special == 1) changed |= set(b, zero ? by_junction : by_other);
            else if (open == 1) changed |= set(b, zero ? by_other : by_junction);
          }
        } else if (el.kind == ElementKind::kTF && bs.size() == 2) {
          // One side takes the effort in, the other gives it out.
          for (int k = 0; k < 2; ++k) {
            const std::size_t b = bs[static_cast<std::size_t>(k)], o = bs[static_cast<std::size_t>(1 - k)];
            if (cause_[b] == 0 || cause_[o] != 0) continue;
            const bool by_tf = cause_[b] == end_code(b, el.name);
            changed |= set(o, by_tf ? -end_code(o, el.name) : end_code(o, el.name));
          }
        }
      }
    }
    return conflict_.empty();
  }

  std::optional<std::string> assign_causality() {
    const std::size_t n = g_.graph.bonds.size();
    cause_.assign(n, 0);
    auto fail = [&](const std::string& why) { return std::optional<std::string>("bond graph of " + f_.name + ": " + why); };
    // Fixed: sources, detectors. An effort detector takes the junction's effort; a flow
    // detector imposes zero effort and takes the flow.
    for (const Element& el : g_.graph.elements) {
      for (std::size_t b : bonds_of(el.name)) {
        const int own = end_code(b, el.name);
        if (el.kind == ElementKind::kSe) set(b, own);
        else if (el.kind == ElementKind::kSf) set(b, -own);
        else if (el.kind == ElementKind::kDetector) set(b, el.name.rfind("De_", 0) == 0 ? -own : own);
      }
    }
    if (!propagate()) return fail(conflict_);
    // Preferred: integral causality of every C (takes flow, gives effort) and I.
    for (ElementKind k : {ElementKind::kC, ElementKind::kI}) {
      for (const Element& el : g_.graph.elements) {
        if (el.kind != k) continue;
        for (std::size_t b : bonds_of(el.name)) {
          const int integral = k == ElementKind::kC ? end_code(b, el.name) : -end_code(b, el.name);
          if (cause_[b] == 0) {
            set(b, integral);
            if (!propagate()) return fail(conflict_);
          } else if (cause_[b] != integral) {
            return fail(el.name + " is forced into derivative causality; only integral causality is supported");
          }
        }
      }
    }
    // Free resistances: conductance form (the R takes the pressure difference).
    for (const Element& el : g_.graph.elements) {
      if (el.kind != ElementKind::kR) continue;
      for (std::size_t b : bonds_of(el.name)) {
        if (cause_[b] != 0) continue;
        set(b, -end_code(b, el.name));
        if (!propagate()) return fail(conflict_);
      }
    }
    g_.effort_by.clear();
    for (std::size_t b = 0; b < n; ++b) {
      if (cause_[b] == 0) return fail("bond " + std::to_string(g_.graph.bonds[b].number) + " has no causality");
      g_.effort_by.push_back(cause_[b] > 0 ? g_.graph.bonds[b].to : g_.graph.bonds[b].from);
    }
    return std::nullopt;
  }

  const host::CircuitFile& f_;
  const host::HostCircuitModel& m_;
  const std::vector<double>& z_;
  CircuitBondGraph& g_;
  std::vector<std::string> node_junction_, shaft_junction_;
  std::map<int, std::string> element_hydraulic_;
  std::vector<int> cause_;
  std::string conflict_;
};

}  // namespace

int CircuitBondGraph::element_index(std::string_view name) const {
  for (std::size_t i = 0; i < graph.elements.size(); ++i) {
    if (graph.elements[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string graph_parameter_name(const std::string& owner, const char* field) { return owner + "." + field; }

std::string named_ref(const host::CircuitFile& f, Ref r) {
  if (r.kind == RefKind::kInput && r.index < f.inputs.size()) return f.inputs[r.index].name;
  if (r.kind == RefKind::kParam && r.index < f.params.size() && !f.params[r.index].literal) return f.params[r.index].name;
  return "";
}

std::optional<std::string> circuit_bond_graph(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel& at,
                                              const std::vector<double>& z, CircuitBondGraph& out) {
  out = CircuitBondGraph{};
  if (z.size() < static_cast<std::size_t>(host::HostCircuitModel::kZ)) return std::string("circuit_bond_graph: no operating point");
  return Builder(c, at, z, out).build();
}

}  // namespace hstmon::fdi
