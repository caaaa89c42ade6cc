// Host build of the firmware's circuit replay (ports/cortex_m4_mps2/portable
// fw_circuit_replay.cpp): the same source, generated circuit and embedded log, float,
// -ffp-contract=off — so its output must equal the Cortex-M4F image's byte for byte
// (test firmware.circuit_bitexact).
#include <cstdio>

#include "fw_circuit.hpp"
#include "hstmon_fw_log_data.hpp"

namespace {
hstmon::fw::CircuitFwObserver obs;
}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  return hstmon::fw::circuit_replay_trace(obs, log, [](const char* s) { std::fputs(s, stdout); }) == ~0u ? 1 : 0;
}
