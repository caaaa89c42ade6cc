// Host build of the firmware's circuit replay (ports/cortex_m4_mps2/portable
// fw_circuit_replay.cpp): the same source, generated circuit and embedded log, float,
// -ffp-contract=off — so its output must equal the Cortex-M4F image's byte for byte
// (test firmware.circuit_bitexact).
#include "fw_circuit.hpp"
#include "fw_host.hpp"

namespace {
hstmon::fw::CircuitFwObserver obs;
}  // namespace

int main() {
  return hstmon::fw::circuit_replay_trace(obs, hstmon_fw_host::embedded_log(), hstmon_fw_host::print) == ~0u ? 1 : 0;
}
