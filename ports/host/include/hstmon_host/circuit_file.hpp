#pragma once
/// @file circuit_file.hpp
/// Circuit files (docs/circuits.md): a hydraulic circuit described in JSON, read into the
/// engine's description (hstmon/circuit/circuit.hpp) plus the names, units and sensor
/// data the host tools need. Every error is a SourceError with file:line:column; the
/// reader never throws and never crashes on bad input.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

/// Capacity of circuits read on the host.
using CircuitCap = circuit::HostCapacity;
/// The description a circuit file becomes.
using HostCircuit = circuit::Circuit<CircuitCap>;
/// The engine on the host (double).
using HostCircuitModel = circuit::CircuitModel<double, CircuitCap>;

/// A parameter: declared by name in "parameters", or a literal number written in a field
/// (named "<component>.<field>" then).
struct CircuitParam {
  std::string name;                 ///< e.g. "Dm", or "prv.dp_t" for a literal
  CircuitQuantity quantity{};       ///< what it measures (decides its units)
  std::optional<double> value;      ///< SI value from the circuit file, if it gives one
  bool literal = false;             ///< true: a number written in a field, not a name
  std::string description;          ///< free text from the file
  std::size_t value_line = 0, value_column = 0;  ///< where the circuit file writes the value (0: nowhere)
};

/// An input: a value that may change every tick, read from a log column.
struct CircuitInput {
  std::string name;                 ///< e.g. "Psupl"
  CircuitQuantity quantity{};
  std::string column;               ///< log column it is read from (default: the name)
  std::string unit;                 ///< the column's unit if the log does not say ("" = SI)
  std::optional<double> value;      ///< nominal SI value from the circuit file, if given
  std::size_t value_line = 0, value_column = 0;  ///< where the circuit file writes the value (0: nowhere)
};

/// A sensor channel: one model output and the log column that measures it.
struct CircuitSensor {
  std::string name;                 ///< channel name, e.g. "p_mi"
  std::string column;               ///< log column (default: the name)
  std::string unit;                 ///< the column's unit if the log does not say ("" = SI)
  CircuitQuantity quantity{};       ///< pressure, speed or flow
  double lo = 0.0, hi = 0.0;        ///< transmitter range [SI]; ±inf where not given
  double noise = 0.0;               ///< noise standard deviation [SI]; 0 if not given
};

/// A circuit file, read.
struct CircuitFile {
  std::string path;                 ///< where it was read from
  std::string name;                 ///< "circuit": its name
  std::string description;
  HostCircuit circuit{};            ///< the engine's description (stiff_mask 0: see auto_stiff_mask)
  std::vector<CircuitParam> params;          ///< by parameter index
  std::vector<CircuitInput> inputs;          ///< by input index
  std::vector<std::string> nodes;            ///< node names by index
  std::vector<std::string> shafts;           ///< shaft names by index
  std::vector<std::string> elements;         ///< element names by index ("dcv.PA" for a valve's path)
  std::vector<CircuitSensor> sensors;        ///< by channel index

  /// Index of the parameter / input / node / shaft / element / sensor named n, or −1.
  int param_index(std::string_view n) const;
  int input_index(std::string_view n) const;
  int node_index(std::string_view n) const;
  int shaft_index(std::string_view n) const;
  int element_index(std::string_view n) const;
  int sensor_index(std::string_view n) const;
};

/// Result of reading a circuit file: `file` on success, `error` otherwise.
struct CircuitFileResult {
  std::optional<CircuitFile> file;
  std::optional<SourceError> error;
  bool ok() const noexcept { return !error.has_value(); }
};

/// Reads and checks the circuit file at path.
CircuitFileResult read_circuit_file(const std::string& path);

/// As read_circuit_file, from text in memory; path_for_messages names it in errors.
CircuitFileResult parse_circuit_json(std::string_view text, std::string path_for_messages);

/// Reads a whole file into text; an error (no position) if it cannot be read.
std::optional<SourceError> read_text_file(const std::string& path, std::string& text);

}  // namespace hstmon::host
