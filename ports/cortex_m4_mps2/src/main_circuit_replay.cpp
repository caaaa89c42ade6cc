// Circuit replay image: the log embedded at build time through the circuit engine on the
// generated circuit (fw_circuit.hpp), one %a residual line per row and a digest, over
// semihosting; compared byte for byte with the host float build (firmware.circuit_bitexact).
#include "fw_circuit.hpp"
#include "hstmon_fw_log_data.hpp"
#include "hstmon_mps2/semihosting.h"

namespace {
hstmon::fw::CircuitFwObserver obs;  // static: no heap, not on the stack
}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  return hstmon::fw::circuit_replay_trace(obs, log, semihost_write0) == ~0u ? 1 : 0;
}
