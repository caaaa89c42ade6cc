// Circuit monitor image: the log embedded at build time through a circuit's whole monitor
// (fw_circuit_monitor.hpp: generated circuit header + generated fault table), printing the
// JSON lines of `hstmon replay --circuit --json` and one %a residual line per row over
// semihosting. Compared byte for byte with the host float build and, within the float
// tolerance, with the host CLI (tests/firmware: firmware.circuit_monitor_*).
#include "fw_circuit_monitor.hpp"
#include "hstmon_fw_log_data.hpp"
#include "hstmon_mps2/semihosting.h"

namespace {
hstmon::fw::CircuitFwMonitor monitor;  // static: no heap, not on the stack
}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  const hstmon::fw::LogColumns columns{d::kColumn, d::kUnit};
  return hstmon::fw::circuit_monitor_replay(monitor, log, columns, semihost_write0) == ~0u ? 1 : 0;
}
