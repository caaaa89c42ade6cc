// Circuit monitor image: the log embedded at build time through a circuit's whole monitor
// (fw_circuit_monitor.hpp: generated circuit header + generated fault table), printing the
// JSON lines of `hstmon replay --circuit --json` and one %a residual line per row over
// semihosting. Compared byte for byte with the host float build and, within the float
// tolerance, with the host CLI (tests/firmware: firmware.circuit_monitor_*). A last line,
// {"type":"circuit_monitor_footprint",…}, gives the deepest stack of the whole replay
// (painting, below main's frame), the static objects' sizes and the SysTick counts of the
// whole replay with their calibration (instructions under `-icount shift=0`,
// hstmon_mps2/cycles.h) for scripts/footprint.sh; the host build has no such line.
#include <cstdint>

#include "fw_circuit_monitor.hpp"
#include "fw_json.hpp"
#include "hstmon_fw_log_data.hpp"
#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/semihosting.h"
#include "hstmon_mps2/stack_paint.h"

namespace {

hstmon::fw::CircuitFwMonitor monitor;  // static: no heap, not on the stack

constexpr std::uint32_t kCalibLoop = 100000;  // as main_circuit_footprint.cpp

}  // namespace

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  const hstmon::fw::LogColumns columns{d::kColumn, d::kUnit};
  cycles_start();
  const std::uint32_t c1 = cycles_known_loop(kCalibLoop);
  const std::uint32_t c2 = cycles_known_loop(2u * kCalibLoop);
  std::uintptr_t sp_main;
  __asm volatile("mov %0, sp" : "=r"(sp_main));
  stack_paint();
  const std::uint32_t t0 = cycles_now();
  const std::uint32_t health = hstmon::fw::circuit_monitor_replay(monitor, log, columns, semihost_write0);
  const std::uint32_t replay_counts = cycles_elapsed(t0, cycles_now());
  const auto stack = static_cast<std::uint64_t>(sp_main - stack_low_water());
  hstmon::fw::Line line(semihost_write0);
  line.begin().str("type", "circuit_monitor_footprint").uint("stack_bytes", stack)
      .uint("monitor_bytes", sizeof monitor).uint("model_bytes", sizeof(hstmon::fw::CircuitFwModel))
      .uint("log_bytes", sizeof d::kData).uint("calib_instructions", 2u * kCalibLoop).uint("calib_counts", c2 - c1)
      .uint("counts_replay", replay_counts).uint("ticks", monitor.observer().ticks()).end();
  return health == ~0u ? 1 : 0;
}
