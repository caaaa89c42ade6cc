/* Circuit C API image: the paper's HST monitor through hstmon_circuit_c.h, from C, as C
 * firmware would hold it (ports/c_api: hstmon_add_circuit_c_api, paper_circuit +
 * paper_signatures, one monitor in a static buffer of the program's). Under
 * `qemu -icount shift=0` it measures (scripts/footprint.sh reports them, not gated):
 *  - instructions per hstmon_circuit_step() at the steady state of the nominal inputs, the
 *    generated 5 ms tick, every channel measured with ±σ-sized alternating noise (SysTick
 *    calibrated on a loop of known length, loop overhead subtracted);
 *  - the stack below main's frame (painting) over create + reset_steady (the setup's
 *    steady-state solves and model bound), over the timed steps, and over a fault episode;
 *  - that episode: p_mi 15 bar above the model for 2 s must be detected (events > 0).
 * Prints one JSON line {"type":"circuit_c_api",…}; exit status 0 (10–12: setup failed,
 * 13: the episode raised no event). */
#include <stdint.h>
#include <string.h>

#include "hstmon_circuit_c.h"
#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/report_line.h"
#include "hstmon_mps2/semihosting.h"
#include "hstmon_mps2/stack_paint.h"

enum { kTicks = 1000, kCalibLoop = 100000 };

static volatile uint32_t sink;
/* The monitor's buffer (static RAM; the library's MONITOR_BYTES sizes it). */
static hstmon_circuit_monitor_storage g_monitor;

__attribute__((noinline)) static uint32_t empty_step(hstmon_circuit_monitor* m, const hstmon_circuit_sample* s) {
  __asm volatile("" ::"r"(m), "r"(s) : "memory");
  return 0u;
}

typedef uint32_t (*step_fn)(hstmon_circuit_monitor*, const hstmon_circuit_sample*);

/* Measurements around base: ±noise alternating (a constant reading is a stuck sensor). */
static void dither(hstmon_circuit_sample* s, const float* base, const float* noise, int k) {
  const float d = (k & 1) ? 1.0f : -1.0f;
  for (int i = 0; i < hstmon_circuit_channels(); ++i) s->y[i] = base[i] + d * noise[i];
}

__attribute__((noinline)) static uint32_t time_ticks(step_fn f, hstmon_circuit_monitor* m, hstmon_circuit_sample* s,
                                                     const float* base, const float* noise) {
  const uint32_t a = cycles_now();
  for (int k = 0; k < kTicks; ++k) {
    dither(s, base, noise, k);
    s->t_s += 0.005f;
    sink = f(m, s);
  }
  return cycles_elapsed(a, cycles_now());
}

int main(void) {
  cycles_start();
  report_begin("circuit_c_api");
  report_uint("channels", (uint32_t)hstmon_circuit_channels());
  report_uint("faults", (uint32_t)hstmon_circuit_faults());
  report_uint("monitor_bytes", (uint32_t)hstmon_circuit_monitor_size());
  (void)report_calibration(kCalibLoop);

  uintptr_t sp_main;
  __asm volatile("mov %0, sp" : "=r"(sp_main));
  stack_paint();
  hstmon_circuit_sample s;
  memset(&s, 0, sizeof s);
  hstmon_circuit_nominal_inputs(s.u);
  hstmon_circuit_monitor* m = 0;
  if (hstmon_circuit_create(&g_monitor, sizeof g_monitor, &s, &m, 0) != HSTMON_OK) semihost_exit(10);
  if (hstmon_circuit_reset_steady(m, s.u) != HSTMON_OK) semihost_exit(11);
  hstmon_circuit_report r;
  hstmon_circuit_read(m, &r);
  const uint32_t stack_setup = (uint32_t)(sp_main - stack_low_water());

  float base[HSTMON_CIRCUIT_MAX_CHANNELS], noise[HSTMON_CIRCUIT_MAX_CHANNELS];
  for (int i = 0; i < hstmon_circuit_channels(); ++i) {
    base[i] = r.estimate[i];
    /* ±0.05 bar on pressures, ±0.5 rpm on speeds: about the paper's sensor σ */
    noise[i] = base[i] > 1000.0f ? 5000.0f : 0.05f;
  }
  s.valid = (uint8_t)((1u << hstmon_circuit_channels()) - 1u);
  dither(&s, base, noise, 0);
  sink = hstmon_circuit_step(m, &s); /* the first step: the model bound for the inputs */
  stack_paint();
  const uint32_t counts_step = time_ticks(hstmon_circuit_step, m, &s, base, noise);
  const uint32_t stack_step = (uint32_t)(sp_main - stack_low_water());
  const uint32_t counts_empty = time_ticks(empty_step, m, &s, base, noise);
  const uint32_t status_nominal = (uint32_t)hstmon_circuit_match_status(m);

  /* A fault episode: p_mi (channel 1 of paper.json) 15 bar above the model for 2 s. */
  stack_paint();
  uint32_t events = 0u;
  base[1] += 15e5f;
  for (int k = 0; k < 400; ++k) {
    dither(&s, base, noise, k);
    s.t_s += 0.005f;
    sink = hstmon_circuit_step(m, &s);
    hstmon_event e;
    while (hstmon_circuit_pop_event(m, &e)) ++events;
  }
  const uint32_t stack_episode = (uint32_t)(sp_main - stack_low_water());
  hstmon_circuit_read(m, &r);
  report_uint("ticks", kTicks);
  report_uint("counts_step_loop", counts_step);
  report_uint("counts_empty_loop", counts_empty);
  report_uint("stack_setup_bytes", stack_setup);
  report_uint("stack_step_bytes", stack_step);
  report_uint("stack_episode_bytes", stack_episode);
  report_uint("status_nominal", status_nominal);
  report_uint("episode_events", events);
  report_uint("health", r.health);
  report_end();
  return events > 0u ? 0 : 13;
}
