/* Footprint image: one monitor through the C API, as C firmware would hold it. Built
 * twice — with HSTMON_FW_WITH_MONITOR=1 and =0 — so that the difference of the two
 * images' sizes is what one monitor costs in flash and RAM (scripts/footprint.sh).
 * With the monitor (observer + sensor checks + evaluator + fault matcher, the C API's
 * hstmon::Monitor<float, 26, 2, 1>) it also measures, under `qemu -icount shift=0`:
 *  - instructions per hstmon_step() at the nominal operating point, 1 ms tick
 *    (SysTick calibrated against a loop of known length; loop overhead measured with a
 *    call to an empty function and subtracted);
 *  - instructions of the first step after the reset, which also recomputes the model
 *    bound of the thresholds (≈ 20 steady-state solves; again on every input change);
 *  - the most instructions of one step during a fault episode (Ppp +10 bar for 300
 *    ticks: detection, alarm onsets, the end of the averaging window — the matcher's
 *    elimination and ranking over the 26 rows);
 *  - the stack depth below main's frame (stack painting): over create + reset_steady
 *    + read, over the bound recomputation, over the timed nominal steps, and over the
 *    episode.
 * Prints one JSON line: {"type":"footprint",…}; exit status 0. */
#include <stdint.h>

#include "hstmon_c.h"
#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/report_line.h"
#include "hstmon_mps2/semihosting.h"
#include "hstmon_mps2/stack_paint.h"

#ifndef HSTMON_FW_WITH_MONITOR
#define HSTMON_FW_WITH_MONITOR 1
#endif

enum { kTicks = 2000, kCalibLoop = 100000 };

static volatile uint32_t sink; /* keeps results observable (in both images: not the monitor's RAM) */



#if HSTMON_FW_WITH_MONITOR
static hstmon_monitor_storage storage; /* the monitor's RAM */

__attribute__((noinline)) static uint32_t empty_step(hstmon_monitor* m, const hstmon_sample* s) {
  __asm volatile("" ::"r"(m), "r"(s) : "memory");
  return 0u;
}

typedef uint32_t (*step_fn)(hstmon_monitor*, const hstmon_sample*);

/* SysTick counts for kTicks calls of f, with ±50 Pa / ±0.05 rad/s alternating noise. */
__attribute__((noinline)) static uint32_t time_ticks(step_fn f, hstmon_monitor* m, hstmon_sample* s) {
  const float base[HSTMON_CHANNELS] = {s->y[0], s->y[1], s->y[2], s->y[3]};
  const uint32_t a = cycles_now();
  for (int k = 0; k < kTicks; ++k) {
    const float d = (k & 1) ? 1.0f : -1.0f;
    s->y[0] = base[0] + 50.0f * d;
    s->y[1] = base[1] - 50.0f * d;
    s->y[2] = base[2] + 50.0f * d;
    s->y[3] = base[3] + 0.05f * d;
    sink = f(m, s);
  }
  const uint32_t b = cycles_now();
  return cycles_elapsed(a, b);
}
#endif

int main(void) {
  cycles_start();
  report_begin("footprint");
  report_uint("with_monitor", HSTMON_FW_WITH_MONITOR);
  sink = report_calibration(kCalibLoop);
#if HSTMON_FW_WITH_MONITOR
  uintptr_t sp_main;
  __asm volatile("mov %0, sp" : "=r"(sp_main));
  stack_paint();
  hstmon_config cfg;
  hstmon_default_config(&cfg);
  cfg.tick_s = 1e-3f;
  hstmon_monitor* m = 0;
  if (hstmon_create(&storage, sizeof storage, &cfg, &m) != HSTMON_OK) semihost_exit(10);
  hstmon_inputs u;
  hstmon_default_inputs(&u);
  if (hstmon_reset_steady(m, &u) != HSTMON_OK) semihost_exit(11);
  hstmon_report r;
  hstmon_read(m, &r);
  hstmon_sample s;
  s.t_s = 0.0f;
  s.u = u;
  for (int i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = r.estimate[i];
  s.valid = 0x0F;
  const uint32_t stack_bytes = (uint32_t)(sp_main - stack_low_water());
  stack_paint(); /* the first step: a tick plus the model bound for the new inputs */
  const uint32_t b0 = cycles_now();
  sink = hstmon_step(m, &s);
  const uint32_t counts_bound = cycles_elapsed(b0, cycles_now());
  const uint32_t stack_bound_bytes = (uint32_t)(sp_main - stack_low_water());
  stack_paint(); /* again: the nominal step path alone */
  const uint32_t counts_step = time_ticks(hstmon_step, m, &s);
  const uint32_t stack_step_bytes = (uint32_t)(sp_main - stack_low_water());
  const uint32_t counts_empty = time_ticks(empty_step, m, &s);
  hstmon_read(m, &r);
  const uint32_t health_nominal = r.health;
  const uint32_t status_nominal = (uint32_t)hstmon_match_status(m);
  /* A fault episode: Ppp 10 bar above the model; the costliest single tick. */
  stack_paint();
  uint32_t counts_episode_max = 0u, events = 0u;
  const float ppp = s.y[HSTMON_CH_PPP];
  for (int k = 0; k < 300; ++k) {
    const float d = (k & 1) ? 1.0f : -1.0f;
    s.y[HSTMON_CH_PPP] = ppp + 10e5f + 50.0f * d;
    const uint32_t a = cycles_now();
    sink = hstmon_step(m, &s);
    const uint32_t c = cycles_elapsed(a, cycles_now());
    if (c > counts_episode_max) counts_episode_max = c;
    hstmon_event e;
    while (hstmon_pop_event(m, &e)) ++events;
  }
  const uint32_t stack_episode_bytes = (uint32_t)(sp_main - stack_low_water());
  const uint32_t status_episode = (uint32_t)hstmon_match_status(m);
  report_uint("monitor_bytes", (uint32_t)hstmon_monitor_size());
  report_uint("storage_bytes", (uint32_t)sizeof storage);
  report_uint("ticks", kTicks);
  report_uint("counts_step_loop", counts_step);
  report_uint("counts_empty_loop", counts_empty);
  report_uint("health", health_nominal);
  report_uint("status_nominal", status_nominal);
  report_uint("counts_bound_step", counts_bound);
  report_uint("stack_bound_bytes", stack_bound_bytes);
  report_uint("counts_episode_max", counts_episode_max);
  report_uint("stack_episode_bytes", stack_episode_bytes);
  report_uint("episode_events", events);
  report_uint("status_episode", status_episode);
  report_uint("max_substeps", r.substeps);
  report_uint("stack_bytes", stack_bytes);
  report_uint("stack_step_bytes", stack_step_bytes);
#endif
  report_end();
  return 0;
}
