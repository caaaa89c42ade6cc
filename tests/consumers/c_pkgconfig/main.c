/* A C program built against the installed C API with nothing but pkg-config:
 *   cc main.c $(pkg-config --cflags --libs hstmon-c)
 * A monitor started at the steady state and fed its own estimate stays nominal. */
#include <stdio.h>

#include "hstmon_c.h"

static hstmon_monitor_storage storage;
/* Sensor-like scatter (a constant reading would be flagged as a stuck sensor). */
static const float kDither[HSTMON_CHANNELS] = {50.0f, -50.0f, 50.0f, 0.05f};

int main(void) {
  hstmon_config cfg;
  hstmon_inputs u;
  hstmon_monitor* m = NULL;
  hstmon_report r;
  hstmon_sample s;
  int k, i;
  hstmon_default_config(&cfg);
  hstmon_default_inputs(&u);
  if (hstmon_create(&storage, sizeof storage, &cfg, &m) != HSTMON_OK || hstmon_reset_steady(m, &u) != HSTMON_OK) {
    puts("consumer: create/reset_steady failed");
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
  printf("consumer: %u ticks, health %u, diagnosis %s\n", (unsigned)r.ticks, (unsigned)hstmon_health(m),
         hstmon_match_name(hstmon_match_status(m)));
  return (r.ticks == 200u && hstmon_health(m) == 0u && hstmon_match_status(m) == HSTMON_MATCH_NOMINAL) ? 0 : 1;
}
