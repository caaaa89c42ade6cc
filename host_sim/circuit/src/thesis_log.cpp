#include "hstmon_circuit/thesis_log.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace hstmon::circuit_tools {

CircuitLog thesis_circuit_log(const sim::ThesisMeasurements& ms, const host::CircuitFile& c) {
  const auto missing = [&c](const char* what, const char* name) {
    return std::invalid_argument("circuit " + c.name + " has no " + what + " '" + name + "' of the thesis rig");
  };
  int in[4];
  for (int i = 0; i < 4; ++i) {
    in[i] = c.input_index(kThesisInputFields[i].name);
    if (in[i] < 0) throw missing("input", kThesisInputFields[i].name);
  }
  const char* const sensors[4] = {"p_mi", "p_mo", "p_pp", "w_m"};  // the measurements' channel order
  int ch[4];
  for (int i = 0; i < 4; ++i) {
    ch[i] = c.sensor_index(sensors[i]);
    if (ch[i] < 0) throw missing("sensor", sensors[i]);
  }
  CircuitLog log;
  log.path = "thesis reference";
  log.inputs.assign(c.inputs.size(), {});
  log.sensors.assign(c.sensors.size(), {});
  for (int i = 0; i < 4; ++i) {
    log.inputs[static_cast<std::size_t>(in[i])].reserve(ms.size());
    log.sensors[static_cast<std::size_t>(ch[i])].reserve(ms.size());
  }
  log.t.reserve(ms.size());
  for (const auto& m : ms) {
    log.t.push_back(m.t);
    for (int i = 0; i < 4; ++i) {
      log.inputs[static_cast<std::size_t>(in[i])].push_back(m.u.*kThesisInputFields[i].member);
      log.sensors[static_cast<std::size_t>(ch[i])].push_back(m.y[static_cast<std::size_t>(i)]);
    }
  }
  return log;
}

}  // namespace hstmon::circuit_tools
