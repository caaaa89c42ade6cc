// Firmware replay image: runs the log embedded at build time through the float observer
// and prints `hstmon replay --json` lines over semihosting. Built twice: plain, and with
// HSTMON_FW_TRACE=1 (per-row residuals in %a hex, for the bit-exactness check).
#include "fw_replay.hpp"
#include "hstmon_fw_log_data.hpp"
#include "hstmon_mps2/semihosting.h"

#ifndef HSTMON_FW_TRACE
#define HSTMON_FW_TRACE 0
#endif

int main() {
  namespace d = hstmon::fw::log_data;
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  hstmon::fw::ReplayOptions opt;
  opt.trace = HSTMON_FW_TRACE != 0;
  (void)hstmon::fw::replay_json(log, semihost_write0, opt);
  return 0;  // as `hstmon replay`: unhealthy ticks are reported, not an error
}
