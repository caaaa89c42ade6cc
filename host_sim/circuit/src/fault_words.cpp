#include "hstmon_circuit/fault_words.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <set>

namespace hstmon::circuit_tools {

namespace {

namespace hc = hstmon::circuit;

// The value a reference holds at c's nominal values; 0 when it holds none.
double ref_value(const LoadedCircuit& c, hc::Ref r) {
  if (r.kind == hc::RefKind::kParam) return c.values.params.v[r.index];
  if (r.kind == hc::RefKind::kInput) return c.values.inputs.v[r.index];
  return 0.0;
}

bool same_ref(hc::Ref r, hc::RefKind kind, int index) { return r.kind == kind && r.index == index; }

std::size_t at(int i) { return static_cast<std::size_t>(i); }

bool is_volume(const LoadedCircuit& c, int node) {
  return node >= 0 && node < c.file.circuit.n_nodes && c.file.circuit.nodes[node].kind == hc::NodeKind::kVolume;
}

// "line A" for a volume node (its name alone when that already says "line"), the node's
// name for a held one ("tank").
std::string node_words(const LoadedCircuit& c, int node) {
  const std::string& n = c.file.nodes[at(node)];
  std::string lower = n;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return is_volume(c, node) && lower.find("line") == std::string::npos ? "line " + n : n;
}

// A machine on a driven shaft is a pump (the shaft brings the power), on a free one a motor.
bool is_pump(const LoadedCircuit& c, const hc::Element& e) {
  if (e.kind == hc::ElementKind::kCompPump || e.kind == hc::ElementKind::kFlowSource) return true;
  return e.kind == hc::ElementKind::kMachine && e.shaft >= 0 && c.file.circuit.shafts[e.shaft].driven;
}

// The signed flow a machine moves from a to b at the nominal values [m³/s].
double machine_flow(const LoadedCircuit& c, const hc::Element& e) {
  const host::HostCircuit& d = c.file.circuit;
  const double frac = e.r[hc::kFraction].kind == hc::RefKind::kNone ? 1.0 : ref_value(c, e.r[hc::kFraction]);
  double w = 1.0;
  if (e.shaft >= 0 && d.shafts[e.shaft].driven) w = ref_value(c, d.shafts[e.shaft].speed);
  return frac * ref_value(c, e.r[hc::kD]) * w;
}

// Adds an element's volume ports to m.nodes (once each).
void add_ports(const LoadedCircuit& c, const hc::Element& e, FaultMeaning& m) {
  for (int n : {static_cast<int>(e.a), static_cast<int>(e.b)}) {
    if (is_volume(c, n) && std::find(m.nodes.begin(), m.nodes.end(), n) == m.nodes.end()) m.nodes.push_back(n);
  }
}

// A machine's (or a pump's) flow change: `more` says whether the change moves more flow.
void machine_effect(const LoadedCircuit& c, int ei, bool more, FaultMeaning& m) {
  const hc::Element& e = c.file.circuit.elements[ei];
  const std::string& name = c.file.elements[at(ei)];
  m.elements.push_back(ei);
  if (is_pump(c, e)) {
    m.effect = more ? FaultEffect::kDeliveryGain : FaultEffect::kDeliveryLoss;
    // The node it delivers into: b for a positive flow a→b (a compensated pump or a source: b).
    const bool forward = e.kind != hc::ElementKind::kMachine || machine_flow(c, e) >= 0.0;
    const int into = forward ? e.b : e.a;
    if (is_volume(c, into)) m.nodes.push_back(into);
    m.words = std::string(more ? "a delivery gain at " : "a delivery loss at ") + name;
  } else {
    m.effect = more ? FaultEffect::kDisplacementGain : FaultEffect::kDisplacementLoss;
    m.shaft = e.shaft;
    m.words = std::string(more ? "a displacement gain of " : "a displacement loss of ") + name;
  }
}

// What a change (up: +) of the number in slot `slot` of element ei does.
void element_effect(const LoadedCircuit& c, int ei, int slot, bool up, FaultMeaning& m) {
  const hc::Element& e = c.file.circuit.elements[ei];
  const std::string& name = c.file.elements[at(ei)];
  const std::string path = e.a == e.b ? name : node_words(c, e.a) + " and " + node_words(c, e.b);
  auto flow_path = [&](bool more) {
    m.effect = more ? FaultEffect::kLeak : FaultEffect::kRestriction;
    m.elements.push_back(ei);
    add_ports(c, e, m);
    const bool a_vol = is_volume(c, e.a), b_vol = is_volume(c, e.b);
    std::string where;
    if (a_vol && b_vol) {
      where = "between " + path;
    } else if (a_vol || b_vol) {
      where = "from " + node_words(c, a_vol ? e.a : e.b) + " to " + node_words(c, a_vol ? e.b : e.a);
    } else {
      where = "at " + name;
    }
    m.words = std::string(more ? "a leak " : "a restriction ") + where + (more ? "" : " (" + name + ")");
    if (more && e.kind != hc::ElementKind::kLaminar) m.words += " (" + name + " passes more)";
  };
  switch (e.kind) {
    case hc::ElementKind::kLaminar:
      if (slot == hc::kR) flow_path(!up);
      return;
    case hc::ElementKind::kOrifice:
    case hc::ElementKind::kPoppet:
      if (slot == hc::kK || slot == hc::kArea || slot == hc::kCd || slot == hc::kOpening) {
        flow_path(up);
      } else if (slot == hc::kRho) {
        flow_path(!up);
      } else if (e.kind == hc::ElementKind::kPoppet && (slot == hc::kCrack || slot == hc::kFull)) {
        m.effect = up ? FaultEffect::kOpensLate : FaultEffect::kOpensEarly;
        m.elements.push_back(ei);
        add_ports(c, e, m);
        m.words = name + (up ? " opening late (setting higher)" : " opening early (setting lower)");
      }
      return;
    case hc::ElementKind::kFlowSource:
      if (slot == hc::kQ) machine_effect(c, ei, up == (ref_value(c, e.r[hc::kQ]) >= 0.0), m);
      return;
    case hc::ElementKind::kMachine:
      if (slot == hc::kD || slot == hc::kFraction) machine_effect(c, ei, up == (machine_flow(c, e) >= 0.0), m);
      return;
    case hc::ElementKind::kCompPump:
      if (slot == hc::kQ0) {
        machine_effect(c, ei, up, m);
      } else if (slot == hc::kRleak) {
        machine_effect(c, ei, up, m);  // its internal leakage: less resistance, less delivery
      } else {
        m.effect = up ? FaultEffect::kSettingHigh : FaultEffect::kSettingLow;
        m.elements.push_back(ei);
        m.words = "the compensator setting of " + name + (up ? " higher" : " lower");
      }
      return;
    case hc::ElementKind::kTorque:
    case hc::ElementKind::kFriction: {
      const bool more = up == (ref_value(c, e.r[0]) >= 0.0);
      m.effect = more ? FaultEffect::kMoreTorque : FaultEffect::kLessTorque;
      m.elements.push_back(ei);
      m.shaft = e.shaft;
      const std::string shaft = e.shaft >= 0 ? c.file.shafts[at(e.shaft)] : name;
      m.words = std::string(more ? "more " : "less ") +
                (e.kind == hc::ElementKind::kTorque ? "load torque" : "friction") + " on shaft " + shaft;
      return;
    }
  }
}

// The phrase of an effect alone, for a list of distinct effects.
std::string effect_words(FaultEffect e) {
  switch (e) {
    case FaultEffect::kLeak: return "a leak";
    case FaultEffect::kRestriction: return "a restriction";
    case FaultEffect::kDeliveryLoss: return "a delivery loss";
    case FaultEffect::kDeliveryGain: return "a delivery gain";
    case FaultEffect::kDisplacementLoss: return "a motor displacement loss";
    case FaultEffect::kDisplacementGain: return "a motor displacement gain";
    case FaultEffect::kOpensEarly: return "a valve opening early";
    case FaultEffect::kOpensLate: return "a valve opening late";
    case FaultEffect::kSettingLow: return "a lower compensator setting";
    case FaultEffect::kSettingHigh: return "a higher compensator setting";
    case FaultEffect::kMoreTorque: return "more torque on a shaft";
    case FaultEffect::kLessTorque: return "less torque on a shaft";
    case FaultEffect::kPressureLow: return "a lower held pressure";
    case FaultEffect::kPressureHigh: return "a higher held pressure";
    case FaultEffect::kSensor: return "a sensor fault";
    case FaultEffect::kOther: break;
  }
  return "another fault";
}

// The volume nodes every meaning touches.
std::vector<int> common_nodes(const std::vector<FaultMeaning>& ms) {
  std::vector<int> common = ms.front().nodes;
  for (const FaultMeaning& m : ms) {
    std::vector<int> keep;
    for (int n : common) {
      if (std::find(m.nodes.begin(), m.nodes.end(), n) != m.nodes.end()) keep.push_back(n);
    }
    common = keep;
  }
  std::sort(common.begin(), common.end());
  return common;
}

std::string nodes_phrase(const LoadedCircuit& c, const std::vector<int>& nodes, const char* one, const char* two) {
  if (nodes.size() == 1) return std::string(one) + node_words(c, nodes[0]);
  return std::string(two) + node_words(c, nodes[0]) + " and " + node_words(c, nodes[1]);
}

}  // namespace

FaultMeaning fault_meaning(const LoadedCircuit& c, const std::string& fault) {
  FaultMeaning m;
  m.fault = fault;
  m.words = fault;
  const std::string sensor = "sensor_";
  if (fault.compare(0, sensor.size(), sensor) == 0) {
    m.effect = FaultEffect::kSensor;
    m.words = "a fault of sensor " + fault.substr(sensor.size());
    return m;
  }
  if (fault.size() < 2 || (fault.back() != '+' && fault.back() != '-')) return m;
  const std::string name = fault.substr(0, fault.size() - 1);
  const bool up = fault.back() == '+';
  const host::HostCircuit& d = c.file.circuit;
  hc::RefKind kind = hc::RefKind::kParam;
  int index = c.file.param_index(name);
  if (index < 0) {
    kind = hc::RefKind::kInput;
    index = c.file.input_index(name);
  }
  if (index < 0) return m;
  FaultMeaning found = m;
  bool any = false;
  for (int e = 0; e < d.n_elements && !any; ++e) {
    for (int s = 0; s < hc::kSlots; ++s) {
      if (!same_ref(d.elements[e].r[s], kind, index)) continue;
      element_effect(c, e, s, up, found);
      if (found.effect != FaultEffect::kOther) {
        any = true;
        break;
      }
    }
  }
  // A parameter shared by several elements of one kind (one case drain resistance for
  // both lines): the same effect on each, their nodes together.
  if (any) {
    for (int e = found.elements.front() + 1; e < d.n_elements; ++e) {
      for (int s = 0; s < hc::kSlots; ++s) {
        if (!same_ref(d.elements[e].r[s], kind, index)) continue;
        FaultMeaning more = m;
        element_effect(c, e, s, up, more);
        if (more.effect != found.effect) continue;
        found.elements.push_back(e);
        for (int n : more.nodes) {
          if (std::find(found.nodes.begin(), found.nodes.end(), n) == found.nodes.end()) found.nodes.push_back(n);
        }
        const std::string lead = effect_words(found.effect) + " ";
        found.words += " and " + (more.words.compare(0, lead.size(), lead) == 0 ? more.words.substr(lead.size()) : more.words);
        break;
      }
    }
    return found;
  }
  // A driven shaft's speed: the delivery of the pumps on it.
  for (int s = 0; s < d.n_shafts; ++s) {
    if (!d.shafts[s].driven || !same_ref(d.shafts[s].speed, kind, index)) continue;
    for (int e = 0; e < d.n_elements; ++e) {
      if (d.elements[e].shaft != s || d.elements[e].kind != hc::ElementKind::kMachine) continue;
      machine_effect(c, e, up == (ref_value(c, d.shafts[s].speed) >= 0.0), found);
      found.words += " (speed of shaft " + c.file.shafts[at(s)] + (up ? " higher)" : " lower)");
      return found;
    }
  }
  // A held pressure.
  for (int n = 0; n < d.n_nodes; ++n) {
    if (d.nodes[n].kind != hc::NodeKind::kBoundary || !same_ref(d.nodes[n].pressure, kind, index)) continue;
    found.effect = up ? FaultEffect::kPressureHigh : FaultEffect::kPressureLow;
    found.words = std::string(up ? "a higher pressure at " : "a lower pressure at ") + c.file.nodes[at(n)];
    return found;
  }
  return m;
}

std::string class_words(const LoadedCircuit& c, const std::vector<std::string>& faults) {
  if (faults.empty()) return {};
  std::vector<FaultMeaning> ms;
  for (const std::string& f : faults) ms.push_back(fault_meaning(c, f));
  if (ms.size() == 1) return ms.front().words;
  std::set<FaultEffect> effects;
  std::set<int> elements, shafts;
  for (const FaultMeaning& m : ms) {
    effects.insert(m.effect);
    elements.insert(m.elements.begin(), m.elements.end());
    shafts.insert(m.shaft);
  }
  const std::vector<int> common = common_nodes(ms);
  if (effects.size() == 1) {
    const FaultEffect e = *effects.begin();
    if (e == FaultEffect::kSensor) return "a sensor fault";
    if (e == FaultEffect::kOther) return "one of " + std::to_string(ms.size()) + " faults";
    const std::string what = effect_words(e);
    if (elements.size() == 1) return what + " at " + c.file.elements[at(*elements.begin())];
    if ((e == FaultEffect::kLeak || e == FaultEffect::kRestriction || e == FaultEffect::kDeliveryLoss ||
         e == FaultEffect::kDeliveryGain) &&
        !common.empty() && common.size() <= 2) {
      return what + nodes_phrase(c, common, e == FaultEffect::kLeak ? " from " : " at ", " between ");
    }
    if (shafts.size() == 1 && *shafts.begin() >= 0) return what + " on shaft " + c.file.shafts[at(*shafts.begin())];
    return what;
  }
  // Leaks and delivery losses both take flow out of a line: one flow loss there.
  const bool flow_loss = std::all_of(ms.begin(), ms.end(), [](const FaultMeaning& m) {
    return m.effect == FaultEffect::kLeak || m.effect == FaultEffect::kDeliveryLoss;
  });
  if (flow_loss && common.size() == 1) {
    return "a flow loss from " + node_words(c, common[0]) + " (a leak or a delivery loss)";
  }
  // Otherwise each effect with what its own candidates share ("a leak from line B"), in the
  // order the candidates first name it.
  std::vector<FaultEffect> order;
  for (const FaultMeaning& m : ms) {
    if (std::find(order.begin(), order.end(), m.effect) == order.end()) order.push_back(m.effect);
  }
  std::vector<std::string> parts;
  for (const FaultEffect e : order) {
    std::vector<std::string> same;
    for (const FaultMeaning& m : ms) {
      if (m.effect == e) same.push_back(m.fault);
    }
    parts.push_back(class_words(c, same));
  }
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : (i + 1 == parts.size() ? " or " : ", ")) + parts[i];
  return out;
}

std::string added_sensor_words(const std::string& channel) {
  if (channel.size() < 4 || channel[1] != '(' || channel.back() != ')') return channel;
  const std::string inside = channel.substr(2, channel.size() - 3);
  switch (channel[0]) {
    case 'p': return "a pressure sensor at node " + inside;
    case 'w': return "a speed sensor on shaft " + inside;
    case 'q': return "a flow meter on " + inside;
    default: return channel;
  }
}

}  // namespace hstmon::circuit_tools
