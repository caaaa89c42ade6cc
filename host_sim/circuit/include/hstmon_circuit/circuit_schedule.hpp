#pragma once
/// @file circuit_schedule.hpp
/// A simple schedule for simulating a circuit, applied on top of the nominal values of
/// the parameter file: input steps `INPUT=VALUE@T` (the input's name, a value with an
/// optional unit of its quantity, the time in seconds), parameter faults
/// `PARAM=FACTOR@T` (the parameter multiplied by FACTOR from T on: `Rmlkg=0.5@3` is the
/// fault Rmlkg− at 3 s) and input faults `INPUT=FACTOR@T` (the machine gets FACTOR times
/// the logged input from T on, while the log keeps what was set: `kp=0.5@80` is a PRV
/// half blocked at 80 s, the fault kp−).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/circuit_file.hpp"

namespace hstmon::circuit_tools {

/// One timed change of a simulated run, in one of three forms:
///  - an input step (input ≥ 0): input `input` (index) is set to `value` [SI] at t;
///  - a parameter fault (param ≥ 0, input −1): parameter `param` becomes its nominal value
///    × `factor` at t;
///  - an input fault (input ≥ 0, input_fault): from t on the machine gets `factor` × the
///    value the log records for input `input` (a port partly blocked, a supply that falls
///    short of its setting); `value` is unused.
struct InputStep {
  double t = 0.0;            ///< time the change takes effect [s]
  int input = -1;            ///< input index, −1 for a parameter fault
  double value = 0.0;        ///< an input step's new value [SI]
  int param = -1;            ///< parameter index of a parameter fault, else −1
  double factor = 1.0;       ///< a fault's factor on the nominal parameter or the logged input [-], > 0
  bool input_fault = false;  ///< with input ≥ 0: an input fault, not a step
};

/// Parses "INPUT=VALUE@T", e.g. "throttle=0.7@5", "T_L=300 N*m@3", "n_e=1800 rpm@2.5".
/// @return an error message, or nothing with `out` set
std::optional<std::string> parse_input_step(std::string_view text, const host::CircuitFile& c, InputStep& out);

/// Parses "PARAM=FACTOR@T", e.g. "Rmlkg=0.5@3" (a named parameter of c, FACTOR > 0): a
/// parameter fault; or "INPUT=FACTOR@T", e.g. "kp=0.5@80" (an input of c): an input fault.
/// @return an error message, or nothing with `out` set
std::optional<std::string> parse_param_fault(std::string_view text, const host::CircuitFile& c, InputStep& out);

/// Sorts steps by time, keeping the given order among equal times.
void sort_steps(std::vector<InputStep>& steps);

}  // namespace hstmon::circuit_tools
