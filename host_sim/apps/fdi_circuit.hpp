#pragma once
// hstmon-fdi isolability|sensors|table --circuit FILE: detectability, isolability classes,
// sensor placement and the constexpr fault table of any circuit (hstmon_circuit circuit_isolability.hpp), as text or JSON.
// Isolability and placement are judged on the monitor's table (circuit_signature_table:
// steady signs and directions, slopes, orders), or with steady_only on the steady part alone.
#include <string>

namespace hstmon::fdi {

/// Prints the isolability report of the circuit; @return 0, or 2 for a bad circuit file
/// @throws std::runtime_error when the circuit has no steady state at its nominal inputs
int run_isolability(const std::string& circuit, const std::string& params, bool json, bool steady_only);

/// Prints the added sensors ranked; @return 0, or 2 for a bad circuit file
/// @throws std::runtime_error when the circuit has no steady state at its nominal inputs
int run_sensor_placement(const std::string& circuit, const std::string& params, bool json, bool steady_only);

/// Writes the circuit's fault table as a constexpr header (out "-" = stdout);
/// @return 0, 1 for a bad name or an unwritable file, 2 for a bad circuit file
int run_table_header(const std::string& circuit, const std::string& params, const std::string& name,
                     const std::string& out);

}  // namespace hstmon::fdi
