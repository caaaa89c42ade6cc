#include "hstmon_host/params_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <system_error>

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_host/units.hpp"
#include "json_errors.hpp"
#include "json_locations.hpp"
#include "text_util.hpp"

namespace hstmon::host {

namespace {

using Params = ThesisParams<double>;
using Inputs = ThesisInputs<double>;
using Json = nlohmann::json;

/// What a field's value must satisfy.
enum class Rule { kPositive, kNonNegative, kFinite };

/// One key of "params" or "inputs".
template <typename S>
struct FieldSpec {
  const char* name;
  double S::*member;
  Quantity quantity;  ///< kNone: numbers only; otherwise strings with a unit too
  const char* unit;   ///< SI unit for messages
  Rule rule;
};

const FieldSpec<Params> kParamFields[] = {
    {"Dm", &Params::Dm, Quantity::kNone, "m3/rad", Rule::kPositive},
    {"Dp", &Params::Dp, Quantity::kNone, "m3/rad", Rule::kPositive},
    {"Rlkg", &Params::Rlkg, Quantity::kNone, "Pa*s/m3", Rule::kPositive},
    {"Ripl", &Params::Ripl, Quantity::kNone, "Pa*s/m3", Rule::kPositive},
    {"Rf", &Params::Rf, Quantity::kNone, "N*m*s/rad", Rule::kNonNegative},
    {"Rbl", &Params::Rbl, Quantity::kNone, "N*m*s/rad", Rule::kNonNegative},
    {"kf", &Params::kf, Quantity::kKp, "m3/(s*Pa^0.5)", Rule::kPositive},
    {"J", &Params::J, Quantity::kNone, "kg*m2", Rule::kPositive},
    {"K", &Params::K, Quantity::kNone, "Pa/m3", Rule::kPositive},
    {"dp_t_dcv", &Params::dp_t_dcv, Quantity::kPressure, "Pa", Rule::kPositive},
    {"dp_t_prv", &Params::dp_t_prv, Quantity::kPressure, "Pa", Rule::kPositive},
};

const FieldSpec<Inputs> kInputFields[] = {
    {"Psupl", &Inputs::Psupl, Quantity::kPressure, "Pa", Rule::kFinite},
    {"Ps", &Inputs::Ps, Quantity::kPressure, "Pa", Rule::kFinite},
    {"Pbp", &Inputs::Pbp, Quantity::kPressure, "Pa", Rule::kFinite},
    {"kp", &Inputs::kp, Quantity::kKp, "m3/(s*Pa^0.5)", Rule::kNonNegative},
};

template <typename S, std::size_t N>
std::string key_list(const FieldSpec<S> (&fields)[N]) {
  std::string s;
  for (const auto& f : fields) {
    if (!s.empty()) s += ", ";
    s += f.name;
  }
  return s;
}

/// Reads one parameter file; each step that fails sets error and returns false.
class Reader {
 public:
  Reader(std::string_view text, std::string path, ParamsFileResult& out)
      : text_(text), path_(std::move(path)), out_(out) {}

  void run() {
    Json j;
    if (!parse(j)) return;
    loc_ = detail::locate_json_members(text_);
    if (loc_.duplicate) {
      const std::string& ptr = loc_.duplicate->first;
      fail(loc_.duplicate->second, "duplicate key '" + ptr.substr(ptr.rfind('/') + 1) + "' in " + where(ptr));
      return;
    }
    if (!j.is_object()) {
      fail(first_non_blank(), "the top level must be an object {\"model\": \"thesis\", ...}");
      return;
    }
    for (const auto& [key, value] : j.items()) {
      if (key != "model" && key != "description" && key != "params" && key != "inputs" && key != "sensors") {
        fail_key("/" + detail::json_pointer_token(key), "unknown key '" + detail::printable(key) +
                                                            "' (known: model, description, params, inputs) or 'sensors' (transmitter ranges)");
        return;
      }
    }
    const auto model = j.find("model");
    if (model == j.end()) {
      fail(first_non_blank(), "missing key 'model' (must be \"thesis\")");
      return;
    }
    if (!model->is_string() || model->get<std::string>() != "thesis") {
      fail_value("/model", "'model' must be \"thesis\" (other models are not read by this tool), got " +
                               detail::printable(model->dump(), 60));
      return;
    }
    if (const auto d = j.find("description"); d != j.end()) {
      if (!d->is_string()) {
        fail_value("/description", "'description' must be a string");
        return;
      }
      out_.description = d->get<std::string>();
    }
    Params p;
    Inputs u;
    if (const auto it = j.find("params"); it != j.end() && !read_fields(*it, "params", kParamFields, p)) return;
    if (const auto it = j.find("inputs"); it != j.end() && !read_fields(*it, "inputs", kInputFields, u)) return;
    if (!(p.Rf + p.Rbl > 0.0)) {
      fail_value(j.contains("params") ? "/params" : "", "Rf + Rbl must be > 0 (the shaft needs some damping)");
      return;
    }
    if (!ThesisCircuitModel<double>::params_valid(p)) {
      fail_value(j.contains("params") ? "/params" : "", "parameters refused by the model (params_valid)");
      return;
    }
    if (!ThesisCircuitModel<double>::inputs_valid(u)) {
      fail_value(j.contains("inputs") ? "/inputs" : "", "inputs refused by the model (inputs_valid)");
      return;
    }
    if (const auto it = j.find("sensors"); it != j.end()) {
      SensorRanges r = thesis_sensor_ranges();
      if (!read_sensors(*it, r)) return;
      out_.sensors = r;
    }
    out_.params = p;
    out_.inputs = u;
  }

 private:
  bool parse(Json& j) {
    auto e = detail::parse_json(text_, j, [this](const std::string& what) { return quoted_token(what); });
    if (e) fail(e->offset, std::move(e->message));
    return !e;
  }

  // Number overflow (out_of_range.406) has no position: where the token quoted in `what` is.
  std::size_t quoted_token(const std::string& what) const {
    const std::size_t q1 = what.find('\'');
    const std::size_t q2 = what.rfind('\'');
    if (q1 != std::string::npos && q2 > q1 + 1) {
      const std::size_t found = text_.find(what.substr(q1 + 1, q2 - q1 - 1));
      if (found != std::string_view::npos) return found;
    }
    return text_.size();
  }

  template <typename S, std::size_t N>
  bool read_fields(const Json& obj, const char* section, const FieldSpec<S> (&fields)[N], S& dst) {
    const std::string base = std::string("/") + section;
    if (!obj.is_object()) {
      fail_value(base, std::string("'") + section + "' must be an object of name: value pairs");
      return false;
    }
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string& key = it.key();
      const Json& value = it.value();
      const std::string ptr = base + "/" + detail::json_pointer_token(key);
      const FieldSpec<S>* spec = nullptr;
      for (const auto& f : fields) {
        if (key == f.name) spec = &f;
      }
      if (spec == nullptr) {
        fail_key(ptr, "unknown key '" + detail::printable(key) + "' in '" + section + "' (known: " +
                          key_list(fields) + ")");
        return false;
      }
      const std::string label = std::string(section) + "." + spec->name;
      double v;
      if (value.is_number()) {
        v = value.get<double>();
      } else if (value.is_string() && spec->quantity != Quantity::kNone) {
        const ValueResult r = parse_value_with_unit(spec->quantity, value.get<std::string>());
        if (!r.ok()) {
          fail_value(ptr, label + ": " + r.error);
          return false;
        }
        v = r.value;
      } else {
        fail_value(ptr, label + " must be a number [" + spec->unit + "]" +
                            (spec->quantity != Quantity::kNone ? " or a string with a unit" : "") + ", got " +
                            value.type_name());
        return false;
      }
      const bool ok = std::isfinite(v) && (spec->rule == Rule::kFinite || (spec->rule == Rule::kPositive ? v > 0.0 : v >= 0.0));
      if (!ok) {
        const char* need = spec->rule == Rule::kPositive ? "finite and > 0" : spec->rule == Rule::kNonNegative ? "finite and >= 0" : "finite";
        fail_value(ptr, label + " must be " + need + " [" + spec->unit + "], got " + number_text(v, 9));
        return false;
      }
      dst.*(spec->member) = v;
    }
    return true;
  }

  /// "sensors": {"p_mi": [lo, hi], ...}; each end a number (SI), a string with a unit, or null.
  bool read_sensors(const Json& obj, SensorRanges& r) {
    static const char* const kChannels[] = {"p_mi", "p_mo", "p_pp", "w_m"};
    if (!obj.is_object()) {
      fail_value("/sensors", "'sensors' must be an object of channel: [low, high] pairs");
      return false;
    }
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string& key = it.key();
      const std::string ptr = "/sensors/" + detail::json_pointer_token(key);
      int ch = -1;
      for (int c = 0; c < 4; ++c) {
        if (key == kChannels[c]) ch = c;
      }
      if (ch < 0) {
        fail_key(ptr, "unknown key '" + detail::printable(key) + "' in 'sensors' (known: p_mi, p_mo, p_pp, w_m)");
        return false;
      }
      const Quantity q = ch == 3 ? Quantity::kSpeed : Quantity::kPressure;
      const std::string label = "sensors." + key;
      const Json& range = it.value();
      if (!range.is_array() || range.size() != 2) {
        fail_value(ptr, label + " must be a range [low, high] (numbers in " + si_unit(q) +
                            ", strings with a unit, or null for no end)");
        return false;
      }
      double end[2];
      for (std::size_t e = 0; e < 2; ++e) {
        const Json& v = range[e];
        const char* which = e == 0 ? "low" : "high";
        if (v.is_null()) {
          end[e] = (e == 0 ? -1.0 : 1.0) * std::numeric_limits<double>::infinity();
        } else if (v.is_number()) {
          end[e] = v.get<double>();
        } else if (v.is_string()) {
          const ValueResult vr = parse_value_with_unit(q, v.get<std::string>());
          if (!vr.ok()) {
            fail_value(ptr, label + " " + which + " end: " + vr.error);
            return false;
          }
          end[e] = vr.value;
        } else {
          fail_value(ptr, label + " " + which + " end must be a number [" + si_unit(q) +
                              "], a string with a unit, or null, got " + v.type_name());
          return false;
        }
        if (!v.is_null() && !std::isfinite(end[e])) {
          fail_value(ptr, label + " " + which + " end must be finite (null for no end)");
          return false;
        }
      }
      if (!(end[0] < end[1])) {
        fail_value(ptr, label + ": the low end must be below the high end, got [" + number_text(end[0], 9) + ", " +
                            number_text(end[1], 9) + "] " + si_unit(q));
        return false;
      }
      r.lo[static_cast<std::size_t>(ch)] = end[0];
      r.hi[static_cast<std::size_t>(ch)] = end[1];
    }
    return true;
  }

  static std::string where(const std::string& ptr) {
    const std::size_t slash = ptr.rfind('/');
    return slash == 0 || slash == std::string::npos ? "the top level" : "'" + ptr.substr(1, slash - 1) + "'";
  }

  std::size_t first_non_blank() const { return detail::first_non_blank(text_); }

  void fail(std::size_t offset, std::string message) {
    out_.error = detail::error_at(text_, path_, offset, std::move(message));
  }

  void fail_key(const std::string& ptr, std::string message) {
    const auto it = loc_.key.find(ptr);
    fail(it != loc_.key.end() ? it->second : first_non_blank(), std::move(message));
  }

  void fail_value(const std::string& ptr, std::string message) {
    const auto it = loc_.value.find(ptr);
    fail(it != loc_.value.end() ? it->second : first_non_blank(), std::move(message));
  }

  std::string_view text_;
  std::string path_;
  ParamsFileResult& out_;
  detail::JsonLocations loc_;
};

}  // namespace

ParamsFileResult parse_params_json(std::string_view text, std::string path_for_messages) {
  ParamsFileResult out;
  Reader r(text, std::move(path_for_messages), out);
  r.run();
  if (out.error) {
    out.params.reset();
    out.inputs.reset();
    out.sensors.reset();
  }
  return out;
}

ParamsFileResult read_params_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    ParamsFileResult out;
    out.error = SourceError{path, 0, 0, "cannot open: " + std::generic_category().message(errno)};
    return out;
  }
  std::string text;
  char chunk[1 << 14];
  std::size_t n;
  while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) text.append(chunk, n);
  const int err = errno;
  const bool bad = std::ferror(f) != 0;
  std::fclose(f);
  if (bad) {
    ParamsFileResult out;
    out.error = SourceError{path, 0, 0, "cannot read: " + std::generic_category().message(err != 0 ? err : EIO)};
    return out;
  }
  return parse_params_json(text, path);
}

std::string format_params_json(const ThesisParams<double>& params, const ThesisInputs<double>& inputs,
                               const std::string& description) {
  nlohmann::ordered_json j;
  j["model"] = "thesis";
  if (!description.empty()) j["description"] = description;
  nlohmann::ordered_json p = nlohmann::ordered_json::object();
  for (const auto& f : kParamFields) p[f.name] = params.*(f.member);
  nlohmann::ordered_json u = nlohmann::ordered_json::object();
  for (const auto& f : kInputFields) u[f.name] = inputs.*(f.member);
  j["params"] = std::move(p);
  j["inputs"] = std::move(u);
  return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::optional<SourceError> write_params_file(const std::string& path, const ThesisParams<double>& params,
                                             const ThesisInputs<double>& inputs, const std::string& description) {
  if (!ThesisCircuitModel<double>::params_valid(params) || !(params.Rf + params.Rbl > 0.0)) {
    return SourceError{path, 0, 0, "refusing to write parameters the model does not accept (params_valid)"};
  }
  if (!ThesisCircuitModel<double>::inputs_valid(inputs)) {
    return SourceError{path, 0, 0, "refusing to write inputs the model does not accept (inputs_valid)"};
  }
  const std::string text = format_params_json(params, inputs, description);
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) return SourceError{path, 0, 0, "cannot create " + tmp + ": " + std::generic_category().message(errno)};
  const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int werr = errno;
  const bool closed = std::fclose(f) == 0;
  if (!wrote || !closed) {
    std::remove(tmp.c_str());
    return SourceError{path, 0, 0, "write failed: " + std::generic_category().message(werr != 0 ? werr : EIO)};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int rerr = errno;
    std::remove(tmp.c_str());
    return SourceError{path, 0, 0, "cannot replace file: " + std::generic_category().message(rerr)};
  }
  return std::nullopt;
}

}  // namespace hstmon::host
