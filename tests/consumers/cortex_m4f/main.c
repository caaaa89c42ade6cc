/* A Cortex-M4F image against the installed hstmon package (find_package, the arm-none-eabi
 * build's hstmon::c_api): a monitor started at the steady state and fed its own estimate
 * with sensor-like scatter stays healthy and nominal for 200 ticks
 * (../common/steady_ticks.h). Output through semihosting; exit status 0 = pass (QEMU's exit
 * status). */
#include "../common/steady_ticks.h"
#include "hstmon_mps2/semihosting.h"

static hstmon_monitor_storage storage;

int main(void) {
  hstmon_monitor* m = 0;
  const char* failed = consumer_steady_ticks(&storage, &m);
  if (failed != 0) {
    semihost_write0("consumer: ");
    semihost_write0(failed);
    semihost_write0("\n");
    return 1;
  }
  semihost_write0("consumer: Cortex-M4F, 200 ticks, health 0, diagnosis ");
  semihost_write0(hstmon_match_name(hstmon_match_status(m)));
  semihost_write0("\n");
  return 0;
}
