#include "hstmon_host/circuit_values.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "circuit_checks.hpp"
#include "json_locations.hpp"
#include "text_util.hpp"

namespace hstmon::host {

namespace {

using Json = nlohmann::json;

/// Fills v with the circuit file's own values; `missing` names what has none.
void defaults(const CircuitFile& cf, CircuitValues& v, std::vector<bool>& p_set, std::vector<bool>& u_set) {
  p_set.assign(cf.params.size(), false);
  u_set.assign(cf.inputs.size(), false);
  v.uncertainty.assign(cf.params.size(), std::nullopt);
  for (std::size_t i = 0; i < cf.params.size(); ++i) {
    if (cf.params[i].value) {
      v.params.v[i] = *cf.params[i].value;
      p_set[i] = true;
    }
  }
  for (std::size_t i = 0; i < cf.inputs.size(); ++i) {
    if (cf.inputs[i].value) {
      v.inputs.v[i] = *cf.inputs[i].value;
      u_set[i] = true;
    }
  }
}

std::string missing(const CircuitFile& cf, const std::vector<bool>& p_set, const std::vector<bool>& u_set) {
  for (std::size_t i = 0; i < p_set.size(); ++i) {
    if (!p_set[i]) return "parameter '" + cf.params[i].name + "' has no value";
  }
  for (std::size_t i = 0; i < u_set.size(); ++i) {
    if (!u_set[i]) return "input '" + cf.inputs[i].name + "' has no nominal value";
  }
  return {};
}

/// A value problem located where the circuit file writes the value (no position when it
/// writes none, or the problem is not one value's).
SourceError in_circuit_file(const CircuitFile& cf, const detail::ValueProblem& p) {
  SourceError e{cf.path, 0, 0, p.message};
  const bool param = p.ref.kind == circuit::RefKind::kParam, input = p.ref.kind == circuit::RefKind::kInput;
  if (param || input) {
    e.line = param ? cf.params[p.ref.index].value_line : cf.inputs[p.ref.index].value_line;
    e.column = param ? cf.params[p.ref.index].value_column : cf.inputs[p.ref.index].value_column;
  }
  if (e.line == 0) e.column = 0;
  return e;
}

class Reader {
 public:
  Reader(std::string_view text, std::string path, const CircuitFile& cf, CircuitValuesResult& out)
      : text_(text), path_(std::move(path)), cf_(cf), out_(out) {}

  void run() {
    Json j;
    try {
      j = Json::parse(text_.begin(), text_.end());
    } catch (const Json::exception& e) {
      const auto* pe = dynamic_cast<const Json::parse_error*>(&e);
      std::string what = e.what();
      const std::size_t c = what.find("column ");
      const std::size_t colon = c == std::string::npos ? std::string::npos : what.find(": ", c);
      fail(pe != nullptr && pe->byte > 0 ? pe->byte - 1 : text_.size(),
           "JSON: " + detail::printable(colon == std::string::npos ? what : what.substr(colon + 2), 200));
      return;
    }
    loc_ = detail::locate_json_members(text_, 2);
    if (loc_.duplicate) {
      const std::string& ptr = loc_.duplicate->first;
      fail(loc_.duplicate->second, "duplicate key '" + ptr.substr(ptr.rfind('/') + 1) + "'");
      return;
    }
    if (!j.is_object()) {
      fail(0, "the top level must be an object {\"circuit\": NAME, \"params\": {...}, \"inputs\": {...}}");
      return;
    }
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (it.key() != "circuit" && it.key() != "model" && it.key() != "description" && it.key() != "params" &&
          it.key() != "inputs" && it.key() != "uncertainty" && it.key() != "sensors") {
        fail_key("/" + detail::json_pointer_token(it.key()),
                 "unknown key '" + detail::printable(it.key()) +
                     "' (known: circuit, description, params, inputs, uncertainty, sensors)");
        return;
      }
    }
    // "model" names the circuit as the thesis rig's parameter files (Table 2.2) write it.
    if (j.contains("circuit") && j.contains("model")) {
      fail_key("/model", "give the circuit's name once: 'circuit' or 'model', not both");
      return;
    }
    const char* const name_key = j.contains("model") ? "model" : "circuit";
    const auto c = j.find(name_key);
    if (c == j.end() || !c->is_string() || c->get<std::string>() != cf_.name) {
      fail_value(c == j.end() ? "" : std::string("/") + name_key,
                 std::string("'") + name_key + "' must be \"" + cf_.name + "\" (the circuit file's name)");
      return;
    }
    CircuitValues v;
    std::vector<bool> p_set, u_set;
    defaults(cf_, v, p_set, u_set);
    if (const auto d = j.find("description"); d != j.end()) {
      if (!d->is_string()) {
        fail_value("/description", "'description' must be a string");
        return;
      }
      v.description = d->get<std::string>();
    }
    if (const auto p = j.find("params"); p != j.end() && !section(*p, "params", true, v, p_set)) return;
    if (const auto u = j.find("inputs"); u != j.end() && !section(*u, "inputs", false, v, u_set)) return;
    if (const auto e = j.find("uncertainty"); e != j.end() && !uncertainty(*e, v)) return;
    if (const auto e = j.find("sensors"); e != j.end() && !sensors(*e, v)) return;
    const std::string m = missing(cf_, p_set, u_set);
    if (!m.empty()) {
      fail(0, m + " (give it in this file or in the circuit file)");
      return;
    }
    if (const auto p = detail::value_problem(cf_, v)) {
      locate(*p);
      return;
    }
    out_.values = v;
  }

 private:
  bool section(const Json& obj, const char* name, bool params, CircuitValues& v, std::vector<bool>& set) {
    const std::string base = std::string("/") + name;
    if (!is_object(obj, base, std::string("'") + name + "' must be an object of name: value pairs")) return false;
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string ptr = base + "/" + detail::json_pointer_token(it.key());
      const int i = params ? cf_.param_index(it.key()) : cf_.input_index(it.key());
      if (!known(i, params ? "parameter" : "input", it.key(), ptr)) return false;
      const CircuitQuantity q = params ? cf_.params[static_cast<std::size_t>(i)].quantity : cf_.inputs[static_cast<std::size_t>(i)].quantity;
      double x;
      if (!quantity_value(*it, q, ptr, it.key(),
                          it.key() + " must be a number [" + circuit_si_unit(q) + "] or a string with a unit", x)) {
        return false;
      }
      if (!std::isfinite(x)) {
        fail_value(ptr, it.key() + " must be finite");
        return false;
      }
      (params ? v.params.v : v.inputs.v)[i] = x;
      set[static_cast<std::size_t>(i)] = true;
      (params ? p_ptr_ : u_ptr_)[static_cast<std::size_t>(i)] = ptr;
    }
    return true;
  }

  /// Whether section `obj` at ptr is an object; else fails there with `message`.
  bool is_object(const Json& obj, const std::string& ptr, const std::string& message) {
    if (!obj.is_object()) fail_value(ptr, message);
    return obj.is_object();
  }

  /// Whether `key` at ptr names a `what` of the circuit (its index is >= 0); else fails there.
  bool known(int index, const char* what, const std::string& key, const std::string& ptr) {
    if (index < 0) {
      fail_key(ptr, std::string("no ") + what + " '" + detail::printable(key) + "' in circuit '" + cf_.name + "'");
    }
    return index >= 0;
  }

  /// A value of quantity q: an SI number, or a string with a unit ("35 bar"). Else fails at
  /// ptr: "label: <the unit's error>" for a string it cannot read, `wrong_type` for any
  /// other JSON value.
  bool quantity_value(const Json& e, CircuitQuantity q, const std::string& ptr, const std::string& label,
                      const std::string& wrong_type, double& x) {
    if (e.is_number()) {
      x = e.get<double>();
      return true;
    }
    if (e.is_string()) {
      const ValueResult r = parse_circuit_value(q, e.get<std::string>());
      if (!r.ok()) {
        fail_value(ptr, label + ": " + r.error);
        return false;
      }
      x = r.value;
      return true;
    }
    fail_value(ptr, wrong_type);
    return false;
  }

  /// The "uncertainty" section: parameter name → relative uncertainty, a fraction or a
  /// string with a fraction unit ("5 %"), read as any value of that quantity.
  bool uncertainty(const Json& obj, CircuitValues& v) {
    if (!is_object(obj, "/uncertainty", "'uncertainty' must be an object of parameter: relative uncertainty pairs")) {
      return false;
    }
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string ptr = "/uncertainty/" + detail::json_pointer_token(it.key());
      const int i = cf_.param_index(it.key());
      if (!known(i, "parameter", it.key(), ptr)) return false;
      double x;
      if (!quantity_value(*it, CircuitQuantity::kFraction, ptr, it.key(),
                          it.key() + " must be a fraction (0.05) or a percentage (\"5 %\")", x)) {
        return false;
      }
      if (!(x >= 0.0 && x <= 0.5)) {
        fail_value(ptr, it.key() + ": a relative uncertainty must be from 0 to 50 %");
        return false;
      }
      v.uncertainty[static_cast<std::size_t>(i)] = x;
    }
    return true;
  }

  /// The "sensors" section: sensor name → transmitter range [low end, high end], each an
  /// SI number, a string with a unit of the sensor's quantity, or null for no end.
  bool sensors(const Json& obj, CircuitValues& v) {
    if (!is_object(obj, "/sensors", "'sensors' must be an object of sensor: [low end, high end] pairs")) return false;
    v.ranges.assign(cf_.sensors.size(), std::nullopt);
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string ptr = "/sensors/" + detail::json_pointer_token(it.key());
      const int index = cf_.sensor_index(it.key());
      if (!known(index, "sensor", it.key(), ptr)) return false;
      const auto i = static_cast<std::size_t>(index);
      const CircuitQuantity q = cf_.sensors[i].quantity;
      if (!it->is_array() || it->size() != 2) {
        fail_value(ptr, it.key() + ": a range is [low end, high end] (numbers [" + circuit_si_unit(q) +
                            "], strings with a unit, or null for no end)");
        return false;
      }
      double end[2] = {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
      for (std::size_t k = 0; k < 2; ++k) {
        const Json& e = (*it)[k];
        if (e.is_null()) continue;
        if (!quantity_value(
                e, q, ptr, it.key(),
                it.key() + ": a range end is a number [" + circuit_si_unit(q) + "], a string with a unit, or null",
                end[k])) {
          return false;
        }
        if (!std::isfinite(end[k])) {
          fail_value(ptr, it.key() + ": a range end must be finite (null for no end)");
          return false;
        }
      }
      if (!(end[0] < end[1])) {
        fail_value(ptr, it.key() + ": the low end must be below the high end");
        return false;
      }
      v.ranges[i] = SensorRange{end[0], end[1]};
    }
    return true;
  }

  /// At the value in this file when it set the value, else where the circuit file writes it.
  void locate(const detail::ValueProblem& p) {
    const std::size_t i = p.ref.index;
    const std::string* ptr = p.ref.kind == circuit::RefKind::kParam   ? &p_ptr_[i]
                             : p.ref.kind == circuit::RefKind::kInput ? &u_ptr_[i]
                                                                      : nullptr;
    if (ptr != nullptr && !ptr->empty()) {
      fail_value(*ptr, p.message);
    } else if (ptr != nullptr) {
      out_.error = in_circuit_file(cf_, p);
    } else {
      out_.error = SourceError{path_, 0, 0, p.message};
    }
  }

  void fail(std::size_t offset, std::string message) {
    const detail::LineCol lc = detail::locate(text_, offset);
    out_.error = SourceError{path_, lc.line, lc.column, std::move(message)};
  }
  void fail_key(const std::string& ptr, std::string message) {
    const auto it = loc_.key.find(ptr);
    fail(it != loc_.key.end() ? it->second : 0, std::move(message));
  }
  void fail_value(const std::string& ptr, std::string message) {
    const auto it = loc_.value.find(ptr);
    fail(it != loc_.value.end() ? it->second : 0, std::move(message));
  }

  std::string_view text_;
  std::string path_;
  const CircuitFile& cf_;
  CircuitValuesResult& out_;
  detail::JsonLocations loc_;
  std::vector<std::string> p_ptr_ = std::vector<std::string>(cf_.params.size());  ///< where this file sets each
  std::vector<std::string> u_ptr_ = std::vector<std::string>(cf_.inputs.size());
};

}  // namespace

CircuitValuesResult circuit_file_values(const CircuitFile& circuit) {
  CircuitValuesResult out;
  CircuitValues v;
  std::vector<bool> p_set, u_set;
  defaults(circuit, v, p_set, u_set);
  const std::string m = missing(circuit, p_set, u_set);
  if (!m.empty()) {
    out.error = SourceError{circuit.path, 0, 0, m};
    return out;
  }
  if (const auto p = detail::value_problem(circuit, v)) {
    out.error = in_circuit_file(circuit, *p);
    return out;
  }
  out.values = v;
  return out;
}

CircuitValuesResult parse_circuit_values_json(std::string_view text, std::string path_for_messages,
                                              const CircuitFile& circuit) {
  CircuitValuesResult out;
  Reader r(text, std::move(path_for_messages), circuit, out);
  r.run();
  if (out.error) out.values.reset();
  return out;
}

void apply_sensor_ranges(const CircuitValues& values, CircuitFile& circuit) {
  for (std::size_t i = 0; i < values.ranges.size() && i < circuit.sensors.size(); ++i) {
    if (!values.ranges[i]) continue;
    circuit.sensors[i].lo = values.ranges[i]->lo;
    circuit.sensors[i].hi = values.ranges[i]->hi;
  }
}

CircuitValuesResult read_circuit_values(const std::string& path, const CircuitFile& circuit) {
  std::string text;
  if (auto e = read_text_file(path, text)) {
    CircuitValuesResult out;
    out.error = *e;
    return out;
  }
  return parse_circuit_values_json(text, path, circuit);
}

}  // namespace hstmon::host
