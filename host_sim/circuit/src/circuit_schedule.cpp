#include "hstmon_circuit/circuit_schedule.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "hstmon_host/circuit_units.hpp"
#include "text_util.hpp"  // ports/host/src: the host port's trim

namespace hstmon::circuit_tools {

namespace {

using host::detail::trim;

/// True when text is a number and nothing else (no blanks, no unit), read into v.
bool whole_number(std::string_view text, double& v) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

/// True when a value's text is a number alone, with no unit after it ("2.5", not "2.5 mm2").
bool bare_number(std::string_view value) {
  double v = 0.0;
  return whole_number(trim(value), v);
}

/// True when text is a time in seconds >= 0, read into t.
bool step_time(std::string_view text, double& t) { return whole_number(text, t) && std::isfinite(t) && t >= 0.0; }

/// "NAME=VALUE@T" cut at the first '=' and the last '@'.
struct TimedAssignment {
  std::string name;
  std::string_view value;  ///< between '=' and '@'
  std::string_view time;   ///< after '@'
};

/// Nothing when text has no '=' before a '@', or no name before the '='.
std::optional<TimedAssignment> split_timed_assignment(std::string_view text) {
  const std::size_t eq = text.find('=');
  const std::size_t at = text.rfind('@');
  if (eq == std::string_view::npos || at == std::string_view::npos || at < eq || eq == 0) return std::nullopt;
  return TimedAssignment{std::string(text.substr(0, eq)), text.substr(eq + 1, at - eq - 1), text.substr(at + 1)};
}

/// Quantities an engineer rarely writes in SI (bar, rpm, L/min, cc/rev, mm², L): a bare
/// number for one of these is more likely a slip than m² or Pa. The others (torque in N·m,
/// orifice coefficients, resistances, …) are written in SI anyway.
bool needs_unit(host::CircuitQuantity q) {
  using Q = host::CircuitQuantity;
  return q == Q::kPressure || q == Q::kSpeed || q == Q::kFlow || q == Q::kDisplacement || q == Q::kArea ||
         q == Q::kVolume;
}

}  // namespace

std::optional<std::string> parse_input_step(std::string_view text, const host::CircuitFile& c, InputStep& out) {
  const std::optional<TimedAssignment> parts = split_timed_assignment(text);
  if (!parts) return "--step takes INPUT=VALUE@T (e.g. throttle=0.7@5), got '" + std::string(text) + "'";
  const std::string& name = parts->name;
  const int i = c.input_index(name);
  if (i < 0) {
    std::string known;
    for (const auto& in : c.inputs) known += (known.empty() ? "" : ", ") + in.name;
    return "--step: circuit " + c.name + " has no input '" + name + "' (inputs: " + known + ")";
  }
  const host::CircuitInput& in = c.inputs[static_cast<std::size_t>(i)];
  const std::string_view value_text = parts->value;
  if (needs_unit(in.quantity) && bare_number(value_text)) {
    const std::string unit = in.unit.empty() ? host::circuit_si_unit(in.quantity) : in.unit;
    return "--step " + std::string(text) + ": give the unit of " + name + " (" +
           host::circuit_quantity_name(in.quantity) + "), e.g. '" + name + "=" + std::string(trim(value_text)) + " " +
           unit + "@" + std::string(parts->time) + "'";
  }
  const host::ValueResult v = host::parse_circuit_value(in.quantity, value_text);
  if (!v.ok()) return "--step " + std::string(text) + ": " + v.error;
  double t = 0.0;
  if (!step_time(parts->time, t)) return "--step " + std::string(text) + ": the time after '@' must be seconds >= 0";
  out = InputStep{t, i, v.value};
  return std::nullopt;
}

std::optional<std::string> parse_param_fault(std::string_view text, const host::CircuitFile& c, InputStep& out) {
  const std::optional<TimedAssignment> parts = split_timed_assignment(text);
  if (!parts)
    return "--fault takes PARAM=FACTOR@T or INPUT=FACTOR@T (e.g. Rmlkg=0.5@3, kp=0.5@80), got '" + std::string(text) +
           "'";
  const std::string& name = parts->name;
  const int i = c.param_index(name);
  const bool param = i >= 0 && !c.params[static_cast<std::size_t>(i)].literal;
  const int input = param ? -1 : c.input_index(name);
  if (!param && input < 0) {
    std::string known;
    for (const auto& p : c.params) {
      if (!p.literal) known += (known.empty() ? "" : ", ") + p.name;
    }
    std::string inputs;
    for (const auto& in : c.inputs) inputs += (inputs.empty() ? "" : ", ") + in.name;
    return "--fault: circuit " + c.name + " has no parameter or input '" + name + "' (parameters: " + known +
           "; inputs: " + inputs + ")";
  }
  double f = 0.0, t = 0.0;
  if (!(whole_number(parts->value, f) && std::isfinite(f) && f > 0.0)) {
    return "--fault " + std::string(text) + ": the factor between '=' and '@' must be a number > 0";
  }
  if (!step_time(parts->time, t)) return "--fault " + std::string(text) + ": the time after '@' must be seconds >= 0";
  out = InputStep{};
  out.t = t;
  out.factor = f;
  if (param) {
    out.param = i;
  } else {
    out.input = input;
    out.input_fault = true;
  }
  return std::nullopt;
}

void sort_steps(std::vector<InputStep>& steps) {
  std::stable_sort(steps.begin(), steps.end(), [](const InputStep& a, const InputStep& b) { return a.t < b.t; });
}

}  // namespace hstmon::circuit_tools
