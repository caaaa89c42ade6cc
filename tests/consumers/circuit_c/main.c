/* The C API of a pump test stand (examples/circuits/test_stand.json), generated and built
 * by an outside project: the monitor runs on the model's own outputs plus transmitter-like
 * noise (a reading that never changes is a stuck transmitter to the sensor checks) without
 * an event, then a 20 % offset on the first channel is detected. Exit 0 = pass. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hstmon_circuit_c.h"

/* The monitor's buffer: static, owned by the program (no heap). */
static hstmon_circuit_monitor_storage g_monitor;

/* Uniform noise in [-a, a] from a fixed linear congruential sequence. */
static float noise(float a) {
  static uint32_t x = 12345u;
  x = x * 1664525u + 1013904223u;
  return a * ((float)(x >> 8) / 8388608.0f - 1.0f);
}

int main(void) {
  hstmon_circuit_sample s;
  hstmon_circuit_monitor* m = NULL;
  hstmon_circuit_report r;
  hstmon_event e;
  const float tick = hstmon_circuit_tick();
  const int n = (int)(2.0f / tick);
  int k, events = 0, detected_at = -1;
  memset(&s, 0, sizeof s);
  hstmon_circuit_nominal_inputs(s.u);
  if (strcmp(hstmon_circuit_name(), "stand_circuit") != 0 || hstmon_circuit_channels() < 1) {
    printf("circuit: %s with %d channels\n", hstmon_circuit_name(), hstmon_circuit_channels());
    return 1;
  }
  if (hstmon_circuit_create(&g_monitor, sizeof g_monitor, &s, &m, NULL) != HSTMON_OK ||
      hstmon_circuit_reset_steady(m, s.u) != HSTMON_OK) {
    printf("create/reset_steady failed\n");
    return 1;
  }
  for (k = 0; k < 2 * n; ++k) {
    int c;
    hstmon_circuit_read(m, &r);
    s.t_s = (float)k * tick;
    /* The estimate is the model's output at the last tick's start: none before the first. */
    s.valid = k == 0 ? 0u : (uint8_t)((1u << hstmon_circuit_channels()) - 1u);
    /* About the file's noise (0.05 bar, 0.2 L/min) and well inside 3σ. */
    for (c = 0; c < hstmon_circuit_channels(); ++c) s.y[c] = r.estimate[c] * (1.0f + noise(2e-4f));
    if (k >= n) s.y[0] *= 1.2f; /* the first transmitter reads 20 % high from 2 s */
    (void)hstmon_circuit_step(m, &s);
    while (hstmon_circuit_pop_event(m, &e)) {
      if (k < n) {
        ++events;
        printf("unexpected event kind %d at %.3f s\n", (int)e.kind, (double)e.t_s);
      }
      if (k >= n && detected_at < 0) detected_at = k;
    }
  }
  printf("%s: %d channels, %d faults, %d events before the offset, offset detected after %.3f s\n",
         hstmon_circuit_name(), hstmon_circuit_channels(), hstmon_circuit_faults(), events,
         detected_at < 0 ? -1.0 : (double)(detected_at - n) * (double)tick);
  return events == 0 && detected_at >= 0 ? 0 : 1;
}
