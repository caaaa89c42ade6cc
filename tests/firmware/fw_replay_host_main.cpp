// Host build of the firmware's portable replay loop (ports/cortex_m4_mps2/portable):
// the same source, the same embedded log, float observer, -ffp-contract=off — so its
// output must equal the Cortex-M4F image's byte for byte (test firmware.qemu_bitexact).
//   hstmon_fw_replay_host [--trace]
#include <cstdio>
#include <cstring>

#include "fw_replay.hpp"
#include "hstmon_fw_log_data.hpp"

int main(int argc, char** argv) {
  namespace d = hstmon::fw::log_data;
  hstmon::fw::ReplayOptions opt;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--trace") == 0) {
      opt.trace = true;
    } else {
      std::fprintf(stderr, "usage: %s [--trace]\n", argv[0]);
      return 1;
    }
  }
  const hstmon::fw::LogView log{d::kName, d::kRows, d::kCols, d::kSignal, d::kScale, &d::kData[0][0]};
  (void)hstmon::fw::replay_json(log, [](const char* s) { std::fputs(s, stdout); }, opt);
  return 0;
}
