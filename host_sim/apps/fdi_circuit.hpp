#pragma once
// hstmon-fdi isolability|sensors --circuit FILE: detectability, isolability classes and
// sensor placement of any circuit (hstmon_circuit circuit_isolability.hpp), as text or JSON.
#include <string>

namespace hstmon::fdi {

/// Prints the isolability report of the circuit; @return 0, or 2 for a bad circuit file
int run_isolability(const std::string& circuit, const std::string& params, bool json);

/// Prints the added sensors ranked; @return 0, or 2 for a bad circuit file
int run_sensor_placement(const std::string& circuit, const std::string& params, bool json);

}  // namespace hstmon::fdi
