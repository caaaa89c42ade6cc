// Host build of the firmware's circuit monitor replay (ports/cortex_m4_mps2/portable
// fw_circuit_monitor.cpp): the same source, generated headers and embedded log, float,
// -ffp-contract=off — so its output must equal the Cortex-M4F image's byte for byte
// (test firmware.circuit_monitor_bitexact).
#include <cstdio>

#include "fw_circuit_monitor.hpp"
#include "hstmon_fw_log_data.hpp"

namespace {
hstmon::fw::CircuitFwMonitor monitor;
}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  const hstmon::fw::LogColumns columns{d::kColumn, d::kUnit};
  return hstmon::fw::circuit_monitor_replay(monitor, log, columns, [](const char* s) { std::fputs(s, stdout); }) == ~0u
             ? 1
             : 0;
}
