/* The run every C consumer of the installed C API makes: a monitor started at the steady
 * state and fed its own estimate with sensor-like scatter (a constant reading would be
 * flagged as a stuck sensor) stays healthy and nominal for 200 ticks. Included by the
 * consumers' main.c, each reporting through its own output (stdio, semihosting). */
#ifndef HSTMON_CONSUMER_STEADY_TICKS_H
#define HSTMON_CONSUMER_STEADY_TICKS_H

#include "hstmon_c.h"

enum { kConsumerTicks = 200 };

/* Runs the check on a monitor in `storage`; *m is the monitor (NULL if it was not created).
 * Returns NULL when it passed, else what failed. */
static const char* consumer_steady_ticks(hstmon_monitor_storage* storage, hstmon_monitor** m) {
  static const float kDither[HSTMON_CHANNELS] = {50.0f, -50.0f, 50.0f, 0.05f};
  hstmon_config cfg;
  hstmon_inputs u;
  hstmon_report r;
  hstmon_sample s;
  int k, i;
  *m = 0;
  hstmon_default_config(&cfg);
  hstmon_default_inputs(&u);
  if (hstmon_create(storage, sizeof *storage, &cfg, m) != HSTMON_OK || hstmon_reset_steady(*m, &u) != HSTMON_OK) {
    return "create/reset_steady failed";
  }
  s.u = u;
  s.valid = 0x0F;
  for (k = 0; k < kConsumerTicks; ++k) {
    hstmon_read(*m, &r);
    s.t_s = (float)k * cfg.tick_s;
    for (i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = r.estimate[i] + ((k & 1) ? kDither[i] : -kDither[i]);
    hstmon_step(*m, &s);
  }
  hstmon_read(*m, &r);
  if (r.ticks != (unsigned)kConsumerTicks || hstmon_health(*m) != 0u ||
      hstmon_match_status(*m) != HSTMON_MATCH_NOMINAL) {
    return "monitor not healthy and nominal after 200 ticks";
  }
  return 0;
}

#endif
