#include "hstmon_circuit/added_sensors.hpp"

#include <cmath>
#include <cstdint>

namespace hstmon::circuit_tools {

namespace {

double typical_sigma(const LoadedCircuit& c, host::CircuitQuantity q, double fallback) {
  for (const auto& s : c.file.sensors) {
    if (s.quantity == q && s.noise > 0.0) return s.noise;
  }
  return fallback;
}

AddedSensor added(std::string name, circuit::ChannelKind kind, int index, host::CircuitQuantity q, double sigma) {
  AddedSensor a;
  a.name = std::move(name);
  a.channel = {kind, static_cast<std::uint8_t>(index)};
  a.sensor.name = a.name;
  a.sensor.quantity = q;
  a.sensor.noise = sigma;
  a.sensor.lo = -HUGE_VAL;
  a.sensor.hi = HUGE_VAL;
  return a;
}

}  // namespace

std::vector<AddedSensor> added_sensors(const LoadedCircuit& c) {
  const host::HostCircuit& d = c.file.circuit;
  std::vector<AddedSensor> out;
  if (d.n_channels >= host::CircuitCap::kChannels) return out;
  const host::HostCircuitModel m(d, c.values.params, c.values.inputs);
  auto measured = [&](circuit::ChannelKind k, int index) {
    for (int i = 0; i < d.n_channels; ++i) {
      if (d.channels[i].kind == k && d.channels[i].index == index) return true;
    }
    return false;
  };
  const double sp = typical_sigma(c, host::CircuitQuantity::kPressure, 0.01 * m.pressure_envelope());
  const double sw = typical_sigma(c, host::CircuitQuantity::kSpeed, 0.01 * m.speed_envelope());
  const double sq = typical_sigma(c, host::CircuitQuantity::kFlow, 1e-6);
  for (int i = 0; i < d.n_nodes; ++i) {
    if (d.nodes[i].kind != circuit::NodeKind::kVolume || measured(circuit::ChannelKind::kPressure, i)) continue;
    out.push_back(added("p(" + c.file.nodes[static_cast<std::size_t>(i)] + ")", circuit::ChannelKind::kPressure, i,
                        host::CircuitQuantity::kPressure, sp));
  }
  for (int s = 0; s < d.n_shafts; ++s) {
    if (d.shafts[s].driven || measured(circuit::ChannelKind::kSpeed, s)) continue;
    out.push_back(added("w(" + c.file.shafts[static_cast<std::size_t>(s)] + ")", circuit::ChannelKind::kSpeed, s,
                        host::CircuitQuantity::kSpeed, sw));
  }
  for (int e = 0; e < d.n_elements; ++e) {
    if (!circuit::has_ports(d.elements[e].kind) || measured(circuit::ChannelKind::kFlow, e)) continue;
    out.push_back(added("q(" + c.file.elements[static_cast<std::size_t>(e)] + ")", circuit::ChannelKind::kFlow, e,
                        host::CircuitQuantity::kFlow, sq));
  }
  return out;
}

LoadedCircuit with_added_sensor(const LoadedCircuit& c, const AddedSensor& s) {
  LoadedCircuit a = c;
  a.file.circuit.channels[a.file.circuit.n_channels++] = s.channel;
  a.file.sensors.push_back(s.sensor);
  return a;
}

}  // namespace hstmon::circuit_tools
