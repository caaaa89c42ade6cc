#include "hstmon_host/circuit_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <system_error>
#include <vector>

#include "circuit_checks.hpp"
#include "hstmon/circuit/validate.hpp"
#include "json_errors.hpp"
#include "json_locations.hpp"
#include "text_util.hpp"

namespace hstmon::host {

namespace {

using Json = nlohmann::ordered_json;
using circuit::ElementKind;
using circuit::NodeKind;
using circuit::Ref;
using circuit::RefKind;

/// Thrown inside the reader only, to unwind to run() with the error already recorded.
struct Stop {};

std::string tok(const std::string& key) { return detail::json_pointer_token(key); }

template <typename V>
int index_of(const V& v, std::string_view n) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == n) return static_cast<int>(i);
  }
  return -1;
}

/// A number of a component: its slot, its key, the quantity it is, whether it must be given.
struct ComponentField {
  circuit::Slot slot;
  const char* key;
  CircuitQuantity q;
  bool required;
};

/// A component type that is its ports ("from", "to") or shaft and a few numbers, read alike.
struct PlainComponent {
  const char* type;
  const char* alias;  ///< another name of the type, or nullptr
  ElementKind kind;
  bool ports, shaft;
  ComponentField fields[5];  ///< in the order they are read; unused ones have no key
};

constexpr PlainComponent kPlainComponents[] = {
    {"laminar_leakage",
     nullptr,
     ElementKind::kLaminar,
     true,
     false,
     {{circuit::kR, "R", CircuitQuantity::kResistance, true}}},
    {"flow_source",
     nullptr,
     ElementKind::kFlowSource,
     true,
     false,
     {{circuit::kQ, "flow", CircuitQuantity::kFlow, true}}},
    {"pump",
     "motor",
     ElementKind::kMachine,
     true,
     true,
     {{circuit::kD, "displacement", CircuitQuantity::kDisplacement, true},
      {circuit::kFraction, "fraction", CircuitQuantity::kFraction, false}}},
    {"compensated_pump",
     nullptr,
     ElementKind::kCompPump,
     true,
     false,
     {{circuit::kQ0, "Q0", CircuitQuantity::kFlow, true},
      {circuit::kRleak, "R", CircuitQuantity::kResistance, true},
      {circuit::kPc, "Pc", CircuitQuantity::kPressure, true},
      {circuit::kPk, "Pk", CircuitQuantity::kPressure, true},
      {circuit::kPmax, "Pmax", CircuitQuantity::kPressure, true}}},
    {"load_torque",
     nullptr,
     ElementKind::kTorque,
     false,
     true,
     {{circuit::kTau, "torque", CircuitQuantity::kTorque, true}}},
    {"friction", nullptr, ElementKind::kFriction, false, true, {{circuit::kC, "c", CircuitQuantity::kDamping, true}}},
};

const PlainComponent* plain_component(const std::string& type) {
  for (const PlainComponent& p : kPlainComponents) {
    if (type == p.type || (p.alias != nullptr && type == p.alias)) return &p;
  }
  return nullptr;
}

class Reader {
 public:
  Reader(std::string_view text, std::string path, CircuitFileResult& out) : text_(text), path_(std::move(path)), out_(out) {
    f_.path = path_;
  }

  void run() {
    try {
      Json j;
      if (!parse(j)) return;
      loc_ = detail::locate_json_members(text_, 4);
      if (loc_.duplicate) {
        const std::string& ptr = loc_.duplicate->first;
        fail(loc_.duplicate->second, "duplicate key '" + ptr.substr(ptr.rfind('/') + 1) + "'");
      }
      if (!j.is_object()) fail(first_non_blank(), "the top level must be an object {\"circuit\": NAME, \"nodes\": ..., ...}");
      check_keys(j, "", {"circuit", "description", "envelope", "parameters", "inputs", "nodes", "shafts", "components", "sensors"});
      const auto name = j.find("circuit");
      if (name == j.end() || !name->is_string() || name->get<std::string>().empty()) {
        fail_at(name == j.end() ? "" : "/circuit", "'circuit' must name the circuit (a non-empty string)");
      }
      f_.name = name->get<std::string>();
      if (const auto d = j.find("description"); d != j.end()) {
        if (!d->is_string()) fail_value("/description", "'description' must be a string");
        f_.description = d->get<std::string>();
      }
      if (const auto p = j.find("parameters"); p != j.end()) read_parameters(*p);
      if (const auto u = j.find("inputs"); u != j.end()) read_inputs(*u);
      const auto nodes = j.find("nodes");
      if (nodes == j.end()) fail(first_non_blank(), "missing key 'nodes'");
      read_nodes(*nodes);
      if (const auto s = j.find("shafts"); s != j.end()) read_shafts(*s);
      const auto comps = j.find("components");
      if (comps == j.end()) fail(first_non_blank(), "missing key 'components'");
      read_components(*comps);
      check_held_nodes(*nodes);
      const auto env = j.find("envelope");
      if (env == j.end()) fail(first_non_blank(), "missing key 'envelope' ({\"pressure\": \"400 bar\", \"speed\": \"3000 rpm\"})");
      read_envelope(*env);
      if (const auto s = j.find("sensors"); s != j.end()) read_sensors(*s);
      finish();
      out_.file = std::move(f_);
    } catch (const Stop&) {
    }
  }

 private:
  // ---- JSON and positions ----
  bool parse(Json& j) {
    auto e = detail::parse_json(text_, j, [this](const std::string&) { return text_.size(); });
    if (e) record(e->offset, std::move(e->message));
    return !e;
  }

  std::size_t first_non_blank() const { return detail::first_non_blank(text_); }

  void record(std::size_t offset, std::string message) {
    out_.error = detail::error_at(text_, path_, offset, std::move(message));
  }

  [[noreturn]] void fail(std::size_t offset, std::string message) {
    record(offset, std::move(message));
    throw Stop{};
  }

  /// Fails at the value at JSON pointer ptr (or its nearest recorded ancestor).
  [[noreturn]] void fail_value(const std::string& ptr, std::string message) {
    fail(position(loc_.value, ptr), std::move(message));
  }
  [[noreturn]] void fail_key(const std::string& ptr, std::string message) {
    fail(position(loc_.key, ptr), std::move(message));
  }
  [[noreturn]] void fail_at(const std::string& ptr, std::string message) { fail_value(ptr, std::move(message)); }

  /// Line and column of the value at ptr, kept for the value checks after the values are bound.
  void at(const std::string& ptr, std::size_t& line, std::size_t& column) const {
    const detail::LineCol lc = detail::locate(text_, position(loc_.value, ptr));
    line = lc.line;
    column = lc.column;
  }

  std::size_t position(const std::map<std::string, std::size_t>& m, std::string ptr) const {
    for (;;) {
      const auto it = m.find(ptr);
      if (it != m.end()) return it->second;
      const std::size_t slash = ptr.rfind('/');
      if (slash == std::string::npos || ptr.empty()) return first_non_blank();
      ptr.erase(slash);
      if (ptr.empty()) return first_non_blank();
    }
  }

  void check_keys(const Json& obj, const std::string& base, const std::vector<const char*>& known) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      bool ok = false;
      for (const char* k : known) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        fail_key(base + "/" + tok(it.key()), "unknown key '" + detail::printable(it.key()) + "' (known: " + list + ")");
      }
    }
  }

  const Json& object(const Json& j, const std::string& ptr, const char* what) {
    if (!j.is_object()) fail_value(ptr, std::string(what) + " must be an object");
    return j;
  }

  std::string string_field(const Json& obj, const std::string& base, const char* key, bool required) {
    const auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail_value(base, std::string("missing key '") + key + "'");
      return {};
    }
    if (!it->is_string()) fail_value(base + "/" + key, std::string("'") + key + "' must be a string");
    return it->get<std::string>();
  }

  // ---- numbers ----
  double number(const Json& v, const std::string& ptr, CircuitQuantity q, const std::string& label) {
    if (v.is_number()) {
      const double d = v.get<double>();
      if (!std::isfinite(d)) fail_value(ptr, label + " must be finite");
      return d;
    }
    if (v.is_string()) {
      const ValueResult r = parse_circuit_value(q, v.get<std::string>());
      if (!r.ok()) fail_value(ptr, label + ": " + r.error);
      return r.value;
    }
    fail_value(ptr, label + " must be a number [" + circuit_si_unit(q) + "] or a string with a unit, got " + v.type_name());
  }

  static bool looks_like_name(const std::string& s) {
    if (s.empty() || !((s[0] >= 'A' && s[0] <= 'Z') || (s[0] >= 'a' && s[0] <= 'z') || s[0] == '_')) return false;
    for (char c : s) {
      if (c == ' ') return false;
    }
    return true;
  }

  /// A field's number: a parameter or input name, or a literal (a new parameter named
  /// literal_name). The quantity of a named one must be q.
  Ref ref(const Json& v, const std::string& ptr, CircuitQuantity q, const std::string& literal_name) {
    if (v.is_string()) {
      const std::string s = v.get<std::string>();
      const int p = f_.param_index(s);
      if (p >= 0 && !f_.params[static_cast<std::size_t>(p)].literal) {
        check_quantity(f_.params[static_cast<std::size_t>(p)].quantity, q, ptr, "parameter '" + s + "'", literal_name);
        return circuit::param_ref(p);
      }
      const int u = f_.input_index(s);
      if (u >= 0) {
        check_quantity(f_.inputs[static_cast<std::size_t>(u)].quantity, q, ptr, "input '" + s + "'", literal_name);
        return circuit::input_ref(u);
      }
      const ValueResult r = parse_circuit_value(q, s);
      if (!r.ok()) {
        if (looks_like_name(s)) {
          fail_value(ptr, literal_name + ": '" + detail::printable(s) +
                              "' is neither a declared parameter nor an input (declare it under \"parameters\" or \"inputs\")");
        }
        fail_value(ptr, literal_name + ": " + r.error);
      }
      return literal(r.value, q, literal_name, ptr);
    }
    return literal(number(v, ptr, q, literal_name), q, literal_name, ptr);
  }

  void check_quantity(CircuitQuantity have, CircuitQuantity want, const std::string& ptr, const std::string& what,
                      const std::string& field) {
    if (have != want) {
      fail_value(ptr, field + " is a quantity '" + circuit_quantity_name(want) + "', but " + what + " is declared as '" +
                          circuit_quantity_name(have) + "'");
    }
  }

  Ref literal(double v, CircuitQuantity q, const std::string& name, const std::string& ptr) {
    if (f_.params.size() >= static_cast<std::size_t>(CircuitCap::kParams)) {
      fail_value(ptr, "too many parameters (literals count too): at most " + std::to_string(CircuitCap::kParams));
    }
    CircuitParam p;
    p.name = name;
    p.quantity = q;
    p.value = v;
    p.literal = true;
    at(ptr, p.value_line, p.value_column);
    f_.params.push_back(p);
    return circuit::param_ref(static_cast<int>(f_.params.size() - 1));
  }

  /// An optional field: Ref{} when absent.
  Ref opt_ref(const Json& obj, const std::string& base, const char* key, CircuitQuantity q, const std::string& owner) {
    const auto it = obj.find(key);
    if (it == obj.end()) return Ref{};
    return ref(*it, base + "/" + key, q, owner + "." + key);
  }

  Ref req_ref(const Json& obj, const std::string& base, const char* key, CircuitQuantity q, const std::string& owner) {
    if (obj.find(key) == obj.end()) fail_value(base, owner + ": missing key '" + key + "' (" + circuit_quantity_name(q) + ")");
    return opt_ref(obj, base, key, q, owner);
  }

  // ---- sections ----
  void declared_name(const std::string& name, const std::string& ptr) {
    if (!looks_like_name(name) || name.find('.') != std::string::npos) {
      fail_key(ptr, "'" + detail::printable(name) + "' is not a name (a letter or '_' first, no blanks or dots)");
    }
    if (f_.param_index(name) >= 0 || f_.input_index(name) >= 0) {
      fail_key(ptr, "'" + name + "' is declared twice (parameters and inputs share one name space)");
    }
  }

  CircuitQuantity quantity(const Json& obj, const std::string& base) {
    const std::string qn = string_field(obj, base, "quantity", true);
    CircuitQuantity q;
    if (!parse_circuit_quantity(qn, q)) {
      fail_value(base + "/quantity", "unknown quantity '" + detail::printable(qn) + "' (known: " + circuit_quantity_list() + ")");
    }
    return q;
  }

  void read_parameters(const Json& j) {
    object(j, "/parameters", "'parameters'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string base = entry(it, "parameters", "parameter", f_.params.size(), CircuitCap::kParams,
                                     {"quantity", "value", "description"});
      declared_name(it.key(), base);
      CircuitParam p;
      p.name = it.key();
      p.quantity = quantity(*it, base);
      declared_value(*it, base, p);
      p.description = string_field(*it, base, "description", false);
      f_.params.push_back(p);
    }
  }

  /// The optional "value" of parameter or input d declared at base, and where it is written.
  template <class Declared>
  void declared_value(const Json& obj, const std::string& base, Declared& d) {
    if (const auto v = obj.find("value"); v != obj.end()) {
      d.value = number(*v, base + "/value", d.quantity, d.name);
      at(base + "/value", d.value_line, d.value_column);
    }
  }

  void read_inputs(const Json& j) {
    object(j, "/inputs", "'inputs'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string base = entry(it, "inputs", "input", f_.inputs.size(), CircuitCap::kInputs,
                                     {"quantity", "column", "unit", "value", "description"});
      declared_name(it.key(), base);
      CircuitInput u;
      u.name = it.key();
      u.quantity = quantity(*it, base);
      u.column = string_field(*it, base, "column", false);
      if (u.column.empty()) u.column = u.name;
      u.unit = string_field(*it, base, "unit", false);
      if (!u.unit.empty()) {
        const UnitResult r = parse_circuit_unit(u.quantity, u.unit);
        if (!r.ok()) fail_value(base + "/unit", u.name + ": " + r.error);
      }
      declared_value(*it, base, u);
      (void)string_field(*it, base, "description", false);
      f_.inputs.push_back(u);
    }
  }

  /// Opens entry `it` of section `section` (one of `kind`) and returns its JSON pointer:
  /// the section has room for one more (`count` read of at most `cap`), the entry is an
  /// object, and it holds only `keys`.
  std::string entry(const Json::const_iterator& it, const char* section, const char* kind, std::size_t count, int cap,
                    const std::vector<const char*>& keys) {
    std::string base = std::string("/") + section + "/" + tok(it.key());
    if (count >= static_cast<std::size_t>(cap)) {
      fail_key(base, std::string("too many ") + section + ": at most " + std::to_string(cap));
    }
    object(*it, base, (std::string(kind) + " '" + it.key() + "'").c_str());
    check_keys(*it, base, keys);
    return base;
  }

  void read_nodes(const Json& j) {
    object(j, "/nodes", "'nodes'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& name = it.key();
      const std::string base = entry(it, "nodes", "node", f_.nodes.size(), CircuitCap::kNodes,
                                     {"K", "beta", "volume", "boundary", "description"});
      (void)string_field(*it, base, "description", false);
      circuit::Node n;
      const bool has_K = it->contains("K"), has_b = it->contains("beta"), has_v = it->contains("volume");
      if (it->contains("boundary")) {
        if (has_K || has_b || has_v) fail_value(base, "node '" + name + "': a boundary has no capacitance (drop K/beta/volume)");
        n.kind = NodeKind::kBoundary;
        n.pressure = ref(it->at("boundary"), base + "/boundary", CircuitQuantity::kPressure, name + ".boundary");
      } else if (has_K) {
        if (has_b || has_v) fail_value(base, "node '" + name + "': give K, or beta and volume, not both");
        n.K = ref(it->at("K"), base + "/K", CircuitQuantity::kStiffness, name + ".K");
      } else if (has_b || has_v) {
        if (!(has_b && has_v)) fail_value(base, "node '" + name + "': beta and volume go together");
        n.beta = ref(it->at("beta"), base + "/beta", CircuitQuantity::kPressure, name + ".beta");
        n.volume = ref(it->at("volume"), base + "/volume", CircuitQuantity::kVolume, name + ".volume");
      } else {
        n.kind = NodeKind::kBoundary;  // held by a pressure_source (check_held_nodes)
        held_.push_back(static_cast<int>(f_.nodes.size()));
      }
      f_.circuit.nodes[f_.nodes.size()] = n;
      f_.nodes.push_back(name);
    }
    f_.circuit.n_nodes = static_cast<std::uint8_t>(f_.nodes.size());
  }

  void read_shafts(const Json& j) {
    object(j, "/shafts", "'shafts'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& name = it.key();
      const std::string base = entry(it, "shafts", "shaft", f_.shafts.size(), CircuitCap::kShafts,
                                     {"J", "friction", "speed", "description"});
      (void)string_field(*it, base, "description", false);
      circuit::Shaft s;
      const int index = static_cast<int>(f_.shafts.size());
      if (it->contains("speed")) {
        if (it->contains("J") || it->contains("friction")) {
          fail_value(base, "shaft '" + name + "': a driven shaft (speed given) has no J or friction");
        }
        s.driven = true;
        s.speed = ref(it->at("speed"), base + "/speed", CircuitQuantity::kSpeed, name + ".speed");
      } else {
        s.J = req_ref(*it, base, "J", CircuitQuantity::kInertia, name);
        if (it->contains("friction")) {
          circuit::Element e;
          e.kind = ElementKind::kFriction;
          e.shaft = static_cast<std::int8_t>(index);
          e.r[circuit::kC] = ref(it->at("friction"), base + "/friction", CircuitQuantity::kDamping, name + ".friction");
          add_element(e, name + ".friction", base);
        }
      }
      f_.circuit.shafts[index] = s;
      f_.shafts.push_back(name);
    }
    f_.circuit.n_shafts = static_cast<std::uint8_t>(f_.shafts.size());
  }

  int node(const Json& obj, const std::string& base, const char* key, const std::string& owner) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail_value(base, owner + ": missing port '" + key + "' (a node name)");
    if (!it->is_string()) fail_value(base + "/" + key, owner + "." + key + " must be a node name");
    const int n = f_.node_index(it->get<std::string>());
    if (n < 0) fail_value(base + "/" + key, owner + "." + key + ": no node '" + detail::printable(it->get<std::string>()) + "'");
    return n;
  }

  int shaft(const Json& obj, const std::string& base, const std::string& owner) {
    const auto it = obj.find("shaft");
    if (it == obj.end()) fail_value(base, owner + ": missing key 'shaft'");
    if (!it->is_string()) fail_value(base + "/shaft", owner + ".shaft must be a shaft name");
    const int s = f_.shaft_index(it->get<std::string>());
    if (s < 0) fail_value(base + "/shaft", owner + ".shaft: no shaft '" + detail::printable(it->get<std::string>()) + "'");
    return s;
  }

  void add_element(const circuit::Element& e, const std::string& name, const std::string& ptr) {
    if (f_.elements.size() >= static_cast<std::size_t>(CircuitCap::kElements)) {
      fail_key(ptr, "too many elements: at most " + std::to_string(CircuitCap::kElements) + " (a directional valve is up to four)");
    }
    f_.circuit.elements[f_.elements.size()] = e;
    f_.elements.push_back(name);
    f_.circuit.n_elements = static_cast<std::uint8_t>(f_.elements.size());
  }

  /// k, or area + Cd + rho, of an orifice, valve path or poppet.
  void coefficient(const Json& obj, const std::string& base, const std::string& name, circuit::Element& e) {
    const bool k = obj.contains("k");
    const bool a = obj.contains("area"), cd = obj.contains("Cd"), rho = obj.contains("rho");
    if (k && (a || cd || rho)) fail_value(base, name + ": give 'k', or 'area', 'Cd' and 'rho', not both");
    if (k) {
      e.r[circuit::kK] = ref(obj.at("k"), base + "/k", CircuitQuantity::kOrifice, name + ".k");
    } else if (a && cd && rho) {
      e.r[circuit::kArea] = ref(obj.at("area"), base + "/area", CircuitQuantity::kArea, name + ".area");
      e.r[circuit::kCd] = ref(obj.at("Cd"), base + "/Cd", CircuitQuantity::kFraction, name + ".Cd");
      e.r[circuit::kRho] = ref(obj.at("rho"), base + "/rho", CircuitQuantity::kDensity, name + ".rho");
    } else {
      fail_value(base, name + ": needs a flow coefficient: 'k' [m3/(s*Pa^0.5)], or 'area', 'Cd' and 'rho'");
    }
    e.r[circuit::kDpT] = opt_ref(obj, base, "dp_t", CircuitQuantity::kPressure, name);
  }

  void read_components(const Json& j) {
    object(j, "/components", "'components'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string base = "/components/" + tok(it.key());
      const std::string& name = it.key();
      object(*it, base, ("component '" + name + "'").c_str());
      const std::string type = string_field(*it, base, "type", true);
      read_component(*it, base, name, type);
    }
  }

  void read_component(const Json& c, const std::string& base, const std::string& name, const std::string& type) {
    if (const PlainComponent* p = plain_component(type)) return read_plain_component(c, base, name, *p);
    circuit::Element e;
    using Q = CircuitQuantity;
    if (type == "orifice") {
      check_keys(c, base, {"type", "from", "to", "k", "area", "Cd", "rho", "opening", "dp_t", "description"});
      e.kind = ElementKind::kOrifice;
      ports(c, base, name, e);
      coefficient(c, base, name, e);
      e.r[circuit::kOpening] = opt_ref(c, base, "opening", Q::kFraction, name);
      add_element(e, name, base);
    } else if (type == "directional_valve") {
      check_keys(c, base, {"type", "P", "T", "A", "B", "k", "area", "Cd", "rho", "spool", "dp_t", "description"});
      e.kind = ElementKind::kOrifice;
      coefficient(c, base, name, e);
      e.r[circuit::kOpening] = req_ref(c, base, "spool", Q::kFraction, name);
      const int P = node(c, base, "P", name), T = node(c, base, "T", name), A = node(c, base, "A", name),
                B = node(c, base, "B", name);
      // A literal spool is fixed: the paths it shuts are left out.
      const Ref s = e.r[circuit::kOpening];
      const bool fixed = s.kind == RefKind::kParam && f_.params[s.index].literal;
      const double sv = fixed ? *f_.params[s.index].value : 0.0;
      struct Path {
        const char* n;
        int a, b, sign;
      };
      const Path paths[] = {{"PA", P, A, 1}, {"BT", B, T, 1}, {"PB", P, B, -1}, {"AT", A, T, -1}};
      for (const Path& p : paths) {
        if (fixed && !(p.sign * sv > 0.0)) continue;
        circuit::Element pe = e;
        pe.a = static_cast<std::uint8_t>(p.a);
        pe.b = static_cast<std::uint8_t>(p.b);
        pe.opening_sign = static_cast<std::int8_t>(p.sign);
        if (pe.a == pe.b) fail_value(base, name + ": path " + p.n + " joins a node to itself");
        add_element(pe, name + "." + p.n, base);
      }
    } else if (type == "relief_valve" || type == "check_valve") {
      const bool relief = type == "relief_valve";
      if (relief) {
        check_keys(c, base, {"type", "from", "to", "setting", "cracking", "k", "area", "Cd", "rho", "dp_t", "description"});
      } else {
        check_keys(c, base, {"type", "from", "to", "cracking", "full_open", "k", "area", "Cd", "rho", "dp_t", "description"});
      }
      e.kind = ElementKind::kPoppet;
      ports(c, base, name, e);
      coefficient(c, base, name, e);
      e.r[circuit::kFull] = req_ref(c, base, relief ? "setting" : "full_open", Q::kPressure, name);
      e.r[circuit::kCrack] = relief ? req_ref(c, base, "cracking", Q::kPressure, name) : opt_ref(c, base, "cracking", Q::kPressure, name);
      add_element(e, name, base);
    } else if (type == "pressure_source") {
      check_keys(c, base, {"type", "node", "pressure", "description"});
      const int n = node(c, base, "node", name);
      bool held = false;
      for (int h : held_) held = held || h == n;
      if (!held) fail_value(base + "/node", name + ": node '" + f_.nodes[static_cast<std::size_t>(n)] +
                                                "' must be declared {} (no capacitance) to be held by a pressure source");
      for (int h : holders_) {
        if (h == n) fail_value(base + "/node", name + ": node '" + f_.nodes[static_cast<std::size_t>(n)] + "' is held twice");
      }
      holders_.push_back(n);
      f_.circuit.nodes[n].pressure = req_ref(c, base, "pressure", Q::kPressure, name);
    } else {
      fail_value(base + "/type", name + ": unknown type '" + detail::printable(type) +
                                     "' (known: orifice, directional_valve, relief_valve, check_valve, laminar_leakage, "
                                     "flow_source, pump, motor, compensated_pump, load_torque, friction, pressure_source)");
    }
  }

  void read_plain_component(const Json& c, const std::string& base, const std::string& name, const PlainComponent& p) {
    std::vector<const char*> known{"type"};
    if (p.ports) known.insert(known.end(), {"from", "to"});
    if (p.shaft) known.push_back("shaft");
    for (const ComponentField& f : p.fields) {
      if (f.key != nullptr) known.push_back(f.key);
    }
    known.push_back("description");
    check_keys(c, base, known);
    circuit::Element e;
    e.kind = p.kind;
    if (p.ports) ports(c, base, name, e);
    if (p.shaft) e.shaft = static_cast<std::int8_t>(shaft(c, base, name));
    for (const ComponentField& f : p.fields) {
      if (f.key == nullptr) break;
      e.r[f.slot] = f.required ? req_ref(c, base, f.key, f.q, name) : opt_ref(c, base, f.key, f.q, name);
    }
    add_element(e, name, base);
  }

  void ports(const Json& c, const std::string& base, const std::string& name, circuit::Element& e) {
    const int a = node(c, base, "from", name);
    const int b = node(c, base, "to", name);
    if (a == b) fail_value(base + "/to", name + ": 'from' and 'to' are the same node");
    e.a = static_cast<std::uint8_t>(a);
    e.b = static_cast<std::uint8_t>(b);
  }

  void check_held_nodes(const Json& nodes) {
    for (int h : held_) {
      bool found = false;
      for (int s : holders_) found = found || s == h;
      if (!found) {
        fail_key("/nodes/" + tok(f_.nodes[static_cast<std::size_t>(h)]),
                 "node '" + f_.nodes[static_cast<std::size_t>(h)] +
                     "' has neither a capacitance (K, or beta and volume) nor a boundary pressure nor a pressure_source");
      }
    }
    (void)nodes;
  }

  void read_envelope(const Json& j) {
    object(j, "/envelope", "'envelope'");
    check_keys(j, "/envelope", {"pressure", "speed"});
    f_.circuit.pressure_max = req_ref(j, "/envelope", "pressure", CircuitQuantity::kPressure, "envelope");
    f_.circuit.speed_max = req_ref(j, "/envelope", "speed", CircuitQuantity::kSpeed, "envelope");
  }

  void read_sensors(const Json& j) {
    object(j, "/sensors", "'sensors'");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& name = it.key();
      const std::string base = entry(it, "sensors", "sensor", f_.sensors.size(), CircuitCap::kChannels,
                                     {"node", "shaft", "flow", "column", "unit", "range", "noise", "description"});
      const int kinds = (it->contains("node") ? 1 : 0) + (it->contains("shaft") ? 1 : 0) + (it->contains("flow") ? 1 : 0);
      if (kinds != 1) fail_value(base, "sensor '" + name + "' measures exactly one of: node (pressure), shaft (speed), flow (a component)");
      circuit::Channel ch;
      CircuitSensor s;
      s.name = name;
      const char* key = it->contains("node") ? "node" : it->contains("shaft") ? "shaft" : "flow";
      const Json& target = it->at(key);
      if (!target.is_string()) fail_value(base + "/" + key, "sensor '" + name + "': '" + key + "' must be a name");
      const std::string t = target.get<std::string>();
      int index;
      if (it->contains("node")) {
        ch.kind = circuit::ChannelKind::kPressure;
        s.quantity = CircuitQuantity::kPressure;
        index = f_.node_index(t);
      } else if (it->contains("shaft")) {
        ch.kind = circuit::ChannelKind::kSpeed;
        s.quantity = CircuitQuantity::kSpeed;
        index = f_.shaft_index(t);
      } else {
        ch.kind = circuit::ChannelKind::kFlow;
        s.quantity = CircuitQuantity::kFlow;
        index = f_.element_index(t);
        if (index >= 0 && !circuit::has_ports(f_.circuit.elements[index].kind)) index = -1;
      }
      if (index < 0) fail_value(base + "/" + key, "sensor '" + name + "': no " + key + " '" + detail::printable(t) + "'" +
                                                      (ch.kind == circuit::ChannelKind::kFlow ? " with a flow (valve paths: name.PA, ...)" : ""));
      ch.index = static_cast<std::uint8_t>(index);
      s.column = string_field(*it, base, "column", false);
      if (s.column.empty()) s.column = name;
      s.unit = string_field(*it, base, "unit", false);
      if (!s.unit.empty()) {
        const UnitResult r = parse_circuit_unit(s.quantity, s.unit);
        if (!r.ok()) fail_value(base + "/unit", name + ": " + r.error);
      }
      s.lo = -std::numeric_limits<double>::infinity();
      s.hi = std::numeric_limits<double>::infinity();
      if (const auto r = it->find("range"); r != it->end()) {
        if (!r->is_array() || r->size() != 2) fail_value(base + "/range", name + ".range must be [low, high] (null for no end)");
        if (!(*r)[0].is_null()) s.lo = number((*r)[0], base + "/range", s.quantity, name + ".range low end");
        if (!(*r)[1].is_null()) s.hi = number((*r)[1], base + "/range", s.quantity, name + ".range high end");
        if (!(s.lo < s.hi)) fail_value(base + "/range", name + ".range: the low end must be below the high end");
      }
      if (const auto n = it->find("noise"); n != it->end()) {
        s.noise = number(*n, base + "/noise", s.quantity, name + ".noise");
        if (!(s.noise >= 0.0)) fail_value(base + "/noise", name + ".noise must be >= 0");
      }
      (void)string_field(*it, base, "description", false);
      f_.circuit.channels[f_.sensors.size()] = ch;
      f_.sensors.push_back(s);
    }
    f_.circuit.n_channels = static_cast<std::uint8_t>(f_.sensors.size());
  }

  void finish() {
    f_.circuit.n_params = static_cast<std::uint8_t>(f_.params.size());
    f_.circuit.n_inputs = static_cast<std::uint8_t>(f_.inputs.size());
    const circuit::CircuitError e = circuit::validate(f_.circuit);
    if (e == circuit::CircuitError::kTooManyStates) {
      fail(first_non_blank(), "more volumes and free shafts than the host build holds as states (" +
                                  std::to_string(CircuitCap::kStates) + ")");
    }
    if (e != circuit::CircuitError::kOk) {
      fail(first_non_blank(), "internal: the circuit does not validate (error " + std::to_string(static_cast<int>(e)) + ")");
    }
    if (const auto w = detail::wiring_problem(f_)) fail_key(w->pointer, w->message);
  }

  std::string_view text_;
  std::string path_;
  CircuitFileResult& out_;
  CircuitFile f_;
  detail::JsonLocations loc_;
  std::vector<int> held_;     ///< nodes declared {} (to be held by a pressure source)
  std::vector<int> holders_;  ///< nodes a pressure source holds
};

}  // namespace

int CircuitFile::param_index(std::string_view n) const {
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params[i].name == n) return static_cast<int>(i);
  }
  return -1;
}
int CircuitFile::input_index(std::string_view n) const {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i].name == n) return static_cast<int>(i);
  }
  return -1;
}
int CircuitFile::node_index(std::string_view n) const { return index_of(nodes, n); }
int CircuitFile::shaft_index(std::string_view n) const { return index_of(shafts, n); }
int CircuitFile::element_index(std::string_view n) const { return index_of(elements, n); }
int CircuitFile::sensor_index(std::string_view n) const {
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    if (sensors[i].name == n) return static_cast<int>(i);
  }
  return -1;
}

CircuitFileResult parse_circuit_json(std::string_view text, std::string path_for_messages) {
  CircuitFileResult out;
  Reader r(text, std::move(path_for_messages), out);
  r.run();
  if (out.error) out.file.reset();
  return out;
}

std::optional<SourceError> read_text_file(const std::string& path, std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return SourceError{path, 0, 0, "cannot open: " + std::generic_category().message(errno)};
  char chunk[1 << 14];
  std::size_t n;
  text.clear();
  while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) text.append(chunk, n);
  const bool bad = std::ferror(f) != 0;
  std::fclose(f);
  if (bad) return SourceError{path, 0, 0, "cannot read"};
  return std::nullopt;
}

CircuitFileResult read_circuit_file(const std::string& path) {
  std::string text;
  if (auto e = read_text_file(path, text)) {
    CircuitFileResult out;
    out.error = *e;
    return out;
  }
  return parse_circuit_json(text, path);
}

}  // namespace hstmon::host
