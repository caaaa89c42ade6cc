#pragma once
/// @file sim_scenario.hpp
/// hstmon-sim's named runs and logger set-ups on a circuit. A thesis rig scenario
/// (hstmon_sim/thesis_scenarios.hpp, rig_run.hpp) is a schedule of the inputs Psupl, Ps,
/// Pbp and kp, the true ones and the logged ones; on a circuit with inputs of those names
/// (thesis.json) it becomes the circuit simulator's input steps, and where the machine's
/// input differs from the logged one (a PRV blockage), an input fault. A sensor preset
/// (hstmon_sensors/sensor_presets.hpp) gives each of the circuit's sensors its chain by name.

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim_app {

/// A scenario as the circuit simulator runs it.
struct ScenarioRun {
  std::vector<circuit_tools::InputStep> steps;  ///< every input the scenario sets at 0, then each change
  double duration = 0.0;                        ///< [s]
  bool from_rest = false;                       ///< the scenario's initial condition
};

/// The run of scenario sc on circuit file f.
/// @return an error message (f lacks one of the scenario's inputs, or a machine's input is
///         no positive multiple of the logged one), or nothing with out set
std::optional<std::string> scenario_run(const sim::ThesisScenario& sc, const host::CircuitFile& f, ScenarioRun& out);

/// The chain of each of f's sensors from preset cfg, matched by name, in f's order.
/// @param preset  the preset's name, for the message
/// @return an error message naming the sensor the preset has no channel for, or nothing
std::optional<std::string> preset_channels(const std::string& preset, const sim::SensorConfig& cfg,
                                           const host::CircuitFile& f, std::vector<sim::ChannelSpec>& out);

}  // namespace hstmon::sim_app
