// Footprint image of the circuit engine: Observer<CircuitModel<float, Cap>> for the circuit
// generated at build time (fw_circuit.hpp; default thesis.json at 1 ms), measured as
// main_footprint.c measures the C API's monitor. Built twice — HSTMON_FW_WITH_ENGINE=1 and
// =0 — so that the difference of the two images' sizes is what the engine costs in flash
// and RAM (scripts/footprint.sh). With the engine, under `qemu -icount shift=0`:
//  - instructions per observer step at the nominal operating point (steady state for the
//    generated nominal inputs), the generated tick, all channels measured with ±σ-sized
//    alternating noise (SysTick calibrated on a loop of known length, loop overhead
//    measured with an empty function and subtracted);
//  - stack depth below main's frame (painting): configure + reset_steady, and the steps.
// Prints one JSON line {"type":"circuit_footprint",…}; exit status 0 (10, 11: setup failed).
#include <cstdint>

#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/report_line.h"
#include "hstmon_mps2/semihosting.h"
#include "hstmon_mps2/stack_paint.h"

#ifndef HSTMON_FW_WITH_ENGINE
#define HSTMON_FW_WITH_ENGINE 1
#endif

#if HSTMON_FW_WITH_ENGINE
#include "fw_circuit.hpp"
#include "timed_ticks.hpp"
#endif

namespace {

constexpr int kTicks = 2000;
constexpr std::uint32_t kCalibLoop = 100000;

volatile std::uint32_t sink;  // keeps results observable (in both images)



#if HSTMON_FW_WITH_ENGINE
using hstmon::fw::CircuitFwObserver;
using Meas = CircuitFwObserver::Measurement;
using Inputs = CircuitFwObserver::Inputs;

CircuitFwObserver obs;  // the engine's RAM (static: no heap, not on the stack)

__attribute__((noinline)) std::uint32_t engine_step(const Inputs& u, const Meas& m) { return obs.step(u, m); }

__attribute__((noinline)) std::uint32_t empty_step(const Inputs& u, const Meas& m) {
  __asm volatile("" ::"r"(&u), "r"(&m) : "memory");
  return 0u;
}

using StepFn = std::uint32_t (*)(const Inputs&, const Meas&);

// Where a tick goes: kTicks model evaluations, plain (an RK4 stage) and with the
// observer's Jacobian and spectral-radius check (a tick's first evaluation).
__attribute__((noinline)) std::uint32_t time_evaluations(bool with_jacobian) {
  const auto& model = obs.model();
  const auto x = obs.state();
  CircuitFwObserver::Output y;
  float rho = 0.0f;
  bool ok = true;
  const std::uint32_t a = cycles_now();
  for (int k = 0; k < kTicks; ++k) {
    const auto d = with_jacobian ? model.tick_derivative(x, 800.0f, y, rho, ok) : model.derivative(x);
    // Every rate observed (one would let the compiler drop the others' laws).
    float all = 0.0f;
    for (int i = 0; i < d.size(); ++i) all += d[i];
    sink = static_cast<std::uint32_t>(all > 0.0f);
  }
  return cycles_elapsed(a, cycles_now());
}

// SysTick counts for kTicks calls of f around the nominal outputs m.
__attribute__((noinline)) std::uint32_t time_ticks(StepFn f, const Inputs& u, const Meas& m) {
  return hstmon::fw::time_alternating(f, u, m, CircuitFwObserver::kOutputs, kTicks, sink);
}
#endif

}  // namespace

int main() {
  cycles_start();
  report_begin("circuit_footprint");
  report_uint("with_engine", HSTMON_FW_WITH_ENGINE);
  sink = report_calibration(kCalibLoop);
#if HSTMON_FW_WITH_ENGINE
  std::uintptr_t sp_main;
  __asm volatile("mov %0, sp" : "=r"(sp_main));
  stack_paint();
  if (hstmon::fw::configure_circuit_observer(obs) != hstmon::Status::kOk) semihost_exit(10);
  const Inputs u = hstmon::fw::circuit_inputs();
  if (obs.reset_steady(u) != hstmon::Status::kOk) semihost_exit(11);
  const auto stack_setup = static_cast<std::uint32_t>(sp_main - stack_low_water());
  Meas m;
  m.y = obs.estimate();
  m.valid = static_cast<std::uint8_t>((1u << obs.model().n_outputs()) - 1u);
  stack_paint();
  sink = obs.step(u, m);  // the first step (the quasi-steady solve's warm start settles)
  const std::uint32_t counts_step = time_ticks(engine_step, u, m);
  const auto stack_step = static_cast<std::uint32_t>(sp_main - stack_low_water());
  const std::uint32_t counts_empty = time_ticks(empty_step, u, m);
  const std::uint32_t counts_derivative = time_evaluations(false);
  const std::uint32_t counts_tick_derivative = time_evaluations(true);
  report_uint("observer_bytes", static_cast<std::uint32_t>(sizeof obs));
  // What the monitor's model bound (circuit_bound.hpp) copies onto the stack.
  report_uint("model_bytes", static_cast<std::uint32_t>(sizeof(hstmon::fw::CircuitFwModel)));
  report_uint("states", static_cast<std::uint32_t>(obs.model().n_states()));
  report_uint("stiff_nodes", static_cast<std::uint32_t>(obs.model().n_stiff()));
  report_uint("ticks", kTicks);
  report_uint("counts_step_loop", counts_step);
  report_uint("counts_empty_loop", counts_empty);
  report_uint("counts_derivative_loop", counts_derivative);
  report_uint("counts_tick_derivative_loop", counts_tick_derivative);
  report_uint("health", obs.health());
  report_uint("max_substeps", obs.substeps());
  report_uint("stack_setup_bytes", stack_setup);
  report_uint("stack_step_bytes", stack_step);
#endif
  report_end();
  return 0;
}
