// Host build of the firmware's portable replay loop (ports/cortex_m4_mps2/portable):
// the same source, the same embedded log, float observer, -ffp-contract=off — so its
// output must equal the Cortex-M4F image's byte for byte (test firmware.qemu_bitexact).
//   hstmon_fw_replay_host [--trace]
#include <cstdio>
#include <cstring>

#include "fw_host.hpp"
#include "fw_replay.hpp"

int main(int argc, char** argv) {
  hstmon::fw::ReplayOptions opt;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--trace") == 0) {
      opt.trace = true;
    } else {
      std::fprintf(stderr, "usage: %s [--trace]\n", argv[0]);
      return 1;
    }
  }
  (void)hstmon::fw::replay_json(hstmon_fw_host::embedded_log(), hstmon_fw_host::print, opt);
  return 0;
}
