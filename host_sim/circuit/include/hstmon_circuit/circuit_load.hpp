#pragma once
/// @file circuit_load.hpp
/// A circuit file with its values, as the host tools (hstmon-sim --circuit, hstmon replay
/// --circuit) load it: the circuit file, then the parameter file given, else
/// `<stem>.params.json` beside the circuit file when there is one, else the circuit file's
/// own values. No circuit file is the thesis rig built into the tools (builtin_rig.hpp),
/// whose own values are Table 2.2's. A parameter file's
/// transmitter ranges ("sensors") replace the circuit file's. Errors are file:line:column
/// (SourceError); nothing throws.

#include <optional>
#include <string>

#include "hstmon_circuit/builtin_rig.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::circuit_tools {

/// A circuit and the values bound to it. The description's stiff mask is 0 (every
/// volume a state): callers set it for their tick (circuit::auto_stiff_mask).
struct LoadedCircuit {
  host::CircuitFile file;
  host::CircuitValues values;
  std::string params_path;  ///< the parameter file used ("" = the circuit file's values)

  /// True for the built-in thesis rig (loaded from no circuit file).
  bool builtin() const noexcept { return file.path == kBuiltinCircuitName; }
};

/// Loads `circuit_path` and its values (see the file note) into out.
/// @param circuit_path  circuit file; "" = the built-in thesis rig
/// @param params_path  parameter file; "" = `<stem>.params.json` if it exists, else none
/// @return the first error, or nothing
std::optional<host::SourceError> load_circuit(const std::string& circuit_path, const std::string& params_path,
                                              LoadedCircuit& out);

}  // namespace hstmon::circuit_tools
