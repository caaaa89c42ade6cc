#pragma once
/// @file circuit_schedule.hpp
/// A simple schedule for simulating a circuit, applied on top of the nominal values of
/// the parameter file: input steps `INPUT=VALUE@T` (the input's name, a value with an
/// optional unit of its quantity, the time in seconds) and parameter faults
/// `PARAM=FACTOR@T` (the parameter multiplied by FACTOR from T on: `Rmlkg=0.5@3` is the
/// fault Rmlkg− at 3 s).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/circuit_file.hpp"

namespace hstmon::circuit_tools {

/// At time t [s] input `input` (index) becomes `value` [SI]; or, for a parameter fault
/// (param ≥ 0, input −1), parameter `param` becomes its nominal value × `factor`.
struct InputStep {
  double t = 0.0;
  int input = -1;
  double value = 0.0;
  int param = -1;
  double factor = 1.0;
};

/// Parses "INPUT=VALUE@T", e.g. "throttle=0.7@5", "T_L=300 N*m@3", "n_e=1800 rpm@2.5".
/// @return an error message, or nothing with `out` set
std::optional<std::string> parse_input_step(std::string_view text, const host::CircuitFile& c, InputStep& out);

/// Parses "PARAM=FACTOR@T", e.g. "Rmlkg=0.5@3" (a named parameter of c, FACTOR > 0).
/// @return an error message, or nothing with `out` set
std::optional<std::string> parse_param_fault(std::string_view text, const host::CircuitFile& c, InputStep& out);

/// Sorts steps by time, keeping the given order among equal times.
void sort_steps(std::vector<InputStep>& steps);

}  // namespace hstmon::circuit_tools
