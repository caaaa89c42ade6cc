/* A Cortex-M4F image against the installed hstmon package (find_package, the arm-none-eabi
 * build's hstmon::c_api): a monitor started at the steady state and fed its own estimate
 * with sensor-like scatter stays healthy and nominal for 200 ticks. Output through
 * semihosting; exit status 0 = pass (QEMU's exit status). */
#include <stdint.h>

#include "hstmon_c.h"
#include "hstmon_mps2/semihosting.h"

static hstmon_monitor_storage storage;
static const float kDither[HSTMON_CHANNELS] = {50.0f, -50.0f, 50.0f, 0.05f};

int main(void) {
  hstmon_config cfg;
  hstmon_inputs u;
  hstmon_monitor* m = 0;
  hstmon_report r;
  hstmon_sample s;
  int k, i;
  hstmon_default_config(&cfg);
  hstmon_default_inputs(&u);
  if (hstmon_create(&storage, sizeof storage, &cfg, &m) != HSTMON_OK || hstmon_reset_steady(m, &u) != HSTMON_OK) {
    semihost_write0("consumer: create/reset_steady failed\n");
    return 1;
  }
  s.u = u;
  s.valid = 0x0F;
  for (k = 0; k < 200; ++k) {
    hstmon_read(m, &r);
    s.t_s = (float)k * cfg.tick_s;
    for (i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = r.estimate[i] + ((k & 1) ? kDither[i] : -kDither[i]);
    hstmon_step(m, &s);
  }
  hstmon_read(m, &r);
  if (r.ticks != 200u || hstmon_health(m) != 0u || hstmon_match_status(m) != HSTMON_MATCH_NOMINAL) {
    semihost_write0("consumer: monitor not healthy and nominal after 200 ticks\n");
    return 1;
  }
  semihost_write0("consumer: Cortex-M4F, 200 ticks, health 0, diagnosis ");
  semihost_write0(hstmon_match_name(hstmon_match_status(m)));
  semihost_write0("\n");
  return 0;
}
