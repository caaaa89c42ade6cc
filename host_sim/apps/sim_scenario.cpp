#include "sim_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hstmon_circuit/thesis_log.hpp"
#include "hstmon_host/number_text.hpp"

namespace hstmon::sim_app {

namespace {

using ThesisU = ThesisInputs<double>;
using circuit_tools::kThesisInputFields;
constexpr std::size_t kFieldCount = sizeof kThesisInputFields / sizeof kThesisInputFields[0];

/// Every time at which the true or the logged schedule changes, rising, from 0.
std::vector<double> change_times(const sim::ThesisScenario& sc) {
  std::vector<double> t;
  for (const auto& s : sc.schedule) t.push_back(s.t_start);
  for (const auto& s : sc.logged) t.push_back(s.t_start);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

}  // namespace

std::optional<std::string> scenario_run(const sim::ThesisScenario& sc, const host::CircuitFile& f, ScenarioRun& out) {
  int index[kFieldCount];
  for (std::size_t j = 0; j < kFieldCount; ++j) {
    index[j] = f.input_index(kThesisInputFields[j].name);
    if (index[j] < 0) {
      return "--scenario " + sc.name + " is the thesis rig's: it sets the inputs Psupl, Ps, Pbp and kp, and circuit " +
             f.name + " has no input '" + kThesisInputFields[j].name +
             "' (--step and --fault set a circuit's own inputs)";
    }
  }
  out = ScenarioRun{};
  out.duration = sc.duration;
  out.from_rest = sc.initial == sim::InitialCondition::kRest;
  double logged_before[kFieldCount] = {};
  double factor_before[kFieldCount] = {1.0, 1.0, 1.0, 1.0};
  bool first = true;
  for (const double t : change_times(sc)) {
    const ThesisU& machine = sim::inputs_at(sc, t);
    const ThesisU& logged = sim::logged_inputs_at(sc, t);
    for (std::size_t j = 0; j < kFieldCount; ++j) {
      const double lv = logged.*kThesisInputFields[j].member;
      const double tv = machine.*kThesisInputFields[j].member;
      if (first || lv != logged_before[j]) {
        circuit_tools::InputStep s;
        s.t = t;
        s.input = index[j];
        s.value = lv;
        out.steps.push_back(s);
        logged_before[j] = lv;
      }
      const double factor = tv == lv ? 1.0 : tv / lv;
      if (!(std::isfinite(factor) && factor > 0.0)) {
        return "--scenario " + sc.name + ": at " + host::number_text(t) + " s the machine's " +
               kThesisInputFields[j].name + " (" + host::number_text(tv) +
               ") is no positive multiple of the logged one (" + host::number_text(lv) + ")";
      }
      if (factor != factor_before[j]) {
        circuit_tools::InputStep s;
        s.t = t;
        s.input = index[j];
        s.factor = factor;
        s.input_fault = true;
        out.steps.push_back(s);
        factor_before[j] = factor;
      }
    }
    first = false;
  }
  return std::nullopt;
}

std::optional<std::string> preset_channels(const std::string& preset, const sim::SensorConfig& cfg,
                                           const host::CircuitFile& f, std::vector<sim::ChannelSpec>& out) {
  out.clear();
  for (const host::CircuitSensor& s : f.sensors) {
    const auto ch = std::find_if(cfg.channels.begin(), cfg.channels.end(),
                                 [&s](const sim::ChannelSpec& c) { return c.name == s.name; });
    if (ch == cfg.channels.end()) {
      std::string names;
      for (const auto& c : cfg.channels) names += (names.empty() ? "" : ", ") + c.name;
      return "--preset " + preset + " has no channel for sensor '" + s.name + "' of circuit " + f.name +
             " (its channels: " + names + ")";
    }
    out.push_back(*ch);
  }
  return std::nullopt;
}

}  // namespace hstmon::sim_app
