#pragma once
/// @file added_sensors.hpp
/// The channels sensor placement tries (circuit_isolability.hpp, rank_added_sensors): every
/// pressure node, free shaft and element flow a circuit does not measure yet, each as one
/// added channel. Its σ is that of the circuit's sensors of the same quantity, else 1 % of
/// the model's envelope (pressure, speed) or 1e-6 m³/s (flow); it has no range.

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// One channel sensor placement tries.
struct AddedSensor {
  std::string name;            ///< "p(Pmi)", "w(motor)", "q(dcv)"
  circuit::Channel channel{};  ///< what it measures
  host::CircuitSensor sensor;  ///< its sensors-section entry: `name`, the quantity, σ as above [SI], range ±inf
};

/// The channels c could add, in order: volume nodes, free shafts, then elements with ports,
/// each in c's order and not measured yet; none when c has no room for another channel
/// (host::CircuitCap::kChannels).
std::vector<AddedSensor> added_sensors(const LoadedCircuit& c);

/// c with s's channel appended (its last channel, and s.sensor its last sensor). c must have
/// room for it (added_sensors gives none otherwise).
LoadedCircuit with_added_sensor(const LoadedCircuit& c, const AddedSensor& s);

}  // namespace hstmon::circuit_tools
