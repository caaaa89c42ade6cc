#pragma once
/// @file sim_circuit.hpp
/// hstmon-sim: a synthetic log of a circuit file (circuit_sim.hpp), the built-in thesis.json
/// when none is given, driven by steps, faults, a named scenario or a logged run.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim_app {

/// The command line of hstmon-sim.
struct CircuitSimArgs {
  std::string circuit;              ///< circuit file ("" = the built-in thesis.json)
  std::string params;               ///< parameter file ("" = <stem>.params.json beside it, else the file's values)
  double duration = 0.0;            ///< [s]; 0 = the scenario's, else 10 s
  double rate = 0.0;                ///< [Hz]; 0 = the preset's, else 100 Hz
  std::uint64_t seed = 1;
  std::string out = "-";
  std::string start;  ///< "rest" | "steady" ("" = the scenario's, else steady)
  bool no_noise = false;
  bool ideal = false;              ///< the reference solution itself: no noise, lag or ADC
  double lag = 0.0;                ///< transducer time constant of every channel [s]; 0 = none
  double pressure_step = 0.0;      ///< pressure channels' quantisation step [Pa]; 0 = none
  int adc_bits = 0;                ///< ADC bits over each pressure channel's range; 0 = none
  double param_error = 0.0;        ///< the machine: uncertain parameters off by uniform ±this [-] (machine_spread.hpp)
  std::uint64_t machine_seed = 1;  ///< seed of that error
  std::vector<std::string> steps;   ///< "INPUT=VALUE@T"
  std::vector<std::string> faults;  ///< "PARAM=FACTOR@T" or "INPUT=FACTOR@T"
  std::optional<sim::ThesisScenario> scenario;  ///< a named scenario: its inputs first, then steps and faults
  std::string preset;                           ///< a sensor preset's name ("" = the sensors section)
  std::optional<sim::SensorConfig> logger;      ///< that preset, --lag, --quant and --adc-bits applied
  std::string inputs;               ///< a log whose input columns drive the run ("" = none; logged_run.hpp)
  std::string inputs_hold = "linear";  ///< "linear" | "step": the logged inputs between rows (input_profile.hpp)
  bool compare = false;             ///< with inputs: the residual measured − simulated per sensor channel
  std::string pressure_unit;        ///< "bar" | "Pa": pressure columns in this unit ("" = the circuit file's)
  bool rpm = false;                 ///< speed columns in rpm (else the circuit file's unit)
  bool list = false;                ///< list what --step, --fault and the log name, then exit
};

/// Runs it. @return 0, 1 on a bad option, 2 on a bad circuit/parameter/input log (message
/// file:line:column on stderr) or a failed simulation. The comparison (compare) goes to
/// standard output, or to standard error when the log itself does.
int run_circuit_sim(const CircuitSimArgs& a);

}  // namespace hstmon::sim_app
