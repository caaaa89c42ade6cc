#pragma once
/// @file circuit_values.hpp
/// Parameter files for circuits: they bind a value to every parameter and a nominal value
/// to every input of a circuit file (docs/circuits.md):
///
///     {"circuit": "thesis", "description": "Table 2.2",
///      "params": {"Dm": 7.96e-6, "kf": 3.226e-6, "K": "1e14"},
///      "inputs": {"Psupl": "35 bar", "kp": 4.41e-8},
///      "uncertainty": {"Dm": "5 %", "Rlkg": 0.3},
///      "sensors": {"p_pp": ["0 bar", "250 bar"], "w_m": [null, "3000 rpm"]}}
///
/// Values are SI numbers or strings with a unit of the parameter's quantity. The circuit
/// file's own values (declared "value"s, literals) are the defaults; a parameter or input
/// left without a value is an error. The optional "uncertainty" section states how well a
/// parameter's value is known, relative (a fraction, or a string in %), from 0 to 50 %:
/// the monitor's model bound takes it instead of its default (circuit_tools::
/// circuit_uncertainty). The optional "sensors" section gives a sensor's transmitter range
/// [low end, high end] in place of the circuit file's: numbers (SI), strings with a unit of
/// the sensor's quantity, or null for no end; low < high. The circuit's name may be given
/// as "model" instead of "circuit" (as the thesis rig's Table 2.2 files write it). Errors
/// carry file:line:column.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

/// A transmitter range [SI]; ±inf for no end.
struct SensorRange {
  double lo;  ///< low end [SI]
  double hi;  ///< high end [SI]
};

/// The values of a circuit's parameters and nominal inputs (SI, by index).
struct CircuitValues {
  HostCircuitModel::Params params{};
  HostCircuitModel::Inputs inputs{};
  /// Relative uncertainty stated per parameter [-], by parameter index (as many as the
  /// circuit has); empty where the parameter file states none.
  std::vector<std::optional<double>> uncertainty;
  /// Transmitter range per sensor, by sensor index (as many as the circuit has), where the
  /// parameter file gives one; empty when it has no "sensors" section.
  std::vector<std::optional<SensorRange>> ranges;
  std::string description;
};

/// Result of reading values: `values` on success, `error` otherwise.
struct CircuitValuesResult {
  std::optional<CircuitValues> values;
  std::optional<SourceError> error;
  bool ok() const noexcept { return !error.has_value(); }
};

/// The circuit file's own values; an error (at the circuit file, no position) naming the
/// first parameter or input it leaves without one.
CircuitValuesResult circuit_file_values(const CircuitFile& circuit);

/// Writes the ranges `values` gives into circuit's sensors (CircuitSensor::lo, hi).
void apply_sensor_ranges(const CircuitValues& values, CircuitFile& circuit);

/// Reads the parameter file at path for `circuit`.
CircuitValuesResult read_circuit_values(const std::string& path, const CircuitFile& circuit);

/// As read_circuit_values, from text; path_for_messages names it in errors.
CircuitValuesResult parse_circuit_values_json(std::string_view text, std::string path_for_messages,
                                              const CircuitFile& circuit);

}  // namespace hstmon::host
