// Host build of the firmware's circuit monitor replay (ports/cortex_m4_mps2/portable
// fw_circuit_monitor.cpp): the same source, generated headers and embedded log, float,
// -ffp-contract=off — so its output must equal the Cortex-M4F image's byte for byte
// (test firmware.circuit_monitor_bitexact).
#include <cstdint>

#include "fw_circuit_monitor.hpp"
#include "fw_host.hpp"

namespace {
hstmon::fw::CircuitFwMonitor monitor;
}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogColumns columns{d::kColumn, d::kUnit};
  const std::uint32_t health =
      hstmon::fw::circuit_monitor_replay(monitor, hstmon_fw_host::embedded_log(), columns, hstmon_fw_host::print);
  return health == ~0u ? 1 : 0;
}
