// Cost image of a circuit's whole monitor (fw_circuit_monitor.hpp: observer, model bound,
// sensor checks, evaluator, fault matcher) on the circuit's compiled model, at its
// generated tick, measured as main_circuit_footprint.cpp measures the observer:
//  - the usual tick: kTicks monitor steps at the steady state of the generated nominal
//    inputs, every channel measured, alternating by ±50 Pa (pressures, flows) or
//    ±0.05 rad/s (speeds) around the model's outputs; loop overhead (an empty step)
//    subtracted;
//  - an input change: every nonzero input × 0.9 (flows and speeds fall, valves close a
//    little), the machine following the model (each step measures the model's last
//    outputs): the first step after it (it recomputes the model bound: two steady-state
//    solves per uncertain parameter and per channel) and the costliest of the kAfter
//    steps from there, each timed alone (SysTick counts: ±1 count = ±40 instructions);
//  - stack depth below main's frame (painting): configure + reset_steady and the first
//    steps after it (the reset's model bound), the usual steps, the steps after the
//    input change.
// Prints one JSON line {"type":"circuit_monitor_cost",…} (SysTick counts and their
// calibration; scripts/footprint.sh converts them); exit status 0 (10, 11: setup failed).
#include <cstdint>

#include "fw_circuit_monitor.hpp"
#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/report_line.h"
#include "hstmon_mps2/semihosting.h"
#include "hstmon_mps2/stack_paint.h"
#include "timed_ticks.hpp"

namespace {

constexpr int kTicks = 2000;
constexpr int kAfter = 2000;
constexpr std::uint32_t kCalibLoop = 100000;

using hstmon::fw::CircuitFwMonitor;
using Meas = CircuitFwMonitor::Measurement;
using Inputs = CircuitFwMonitor::Inputs;

CircuitFwMonitor mon;  // static: no heap, not on the stack
volatile std::uint32_t sink;
float t_now = 0.0f;

__attribute__((noinline)) std::uint32_t monitor_step(const Inputs& u, const Meas& m) {
  t_now += static_cast<float>(hstmon::fw::kTick);
  (void)mon.step(t_now, u, m);
  return mon.health();
}

__attribute__((noinline)) std::uint32_t empty_step(const Inputs& u, const Meas& m) {
  __asm volatile("" ::"r"(&u), "r"(&m) : "memory");
  return 0u;
}

using StepFn = std::uint32_t (*)(const Inputs&, const Meas&);

// SysTick counts for kTicks calls of f around the measurement `base`.
__attribute__((noinline)) std::uint32_t time_usual(StepFn f, const Inputs& u, const Meas& base) {
  return hstmon::fw::time_alternating(f, u, base, CircuitFwMonitor::kChannels, kTicks, sink);
}

// The model's outputs as a measurement of every channel.
Meas following_the_model() {
  Meas m;
  m.y = mon.observer().estimate();
  m.valid = static_cast<std::uint8_t>((1u << mon.observer().model().n_outputs()) - 1u);
  return m;
}

}  // namespace

int main() {
  cycles_start();
  report_begin("circuit_monitor_cost");
  (void)report_calibration(kCalibLoop);
  std::uintptr_t sp_main;
  __asm volatile("mov %0, sp" : "=r"(sp_main));
  stack_paint();
  const Inputs u = hstmon::fw::circuit_inputs();
  if (hstmon::fw::configure_circuit_monitor(mon, u) != hstmon::Status::kOk) semihost_exit(10);
  if (mon.reset_steady(u) != hstmon::Status::kOk) semihost_exit(11);

  // The usual tick at the steady state.
  const Meas base = following_the_model();
  // The first steps after the reset: the model bound for the reset's inputs, the
  // quasi-steady solve's warm start.
  for (int k = 0; k < 10; ++k) sink = monitor_step(u, base);
  const auto stack_setup = static_cast<std::uint32_t>(sp_main - stack_low_water());
  stack_paint();
  const std::uint32_t counts_usual = time_usual(monitor_step, u, base);
  const auto stack_usual = static_cast<std::uint32_t>(sp_main - stack_low_water());
  const std::uint32_t counts_empty = time_usual(empty_step, u, base);
  const std::uint32_t max_substeps = mon.observer().substeps();

  // An input change, the machine following the model.
  Inputs u2 = u;
  for (int i = 0; i < hstmon::fw::gen::kCircuit.n_inputs; ++i) u2.v[i] = 0.9f * u.v[i];
  stack_paint();
  std::uint32_t first = 0, worst = 0, total = 0;
  std::uint32_t health = 0;
  for (int k = 0; k < kAfter; ++k) {
    const Meas m = following_the_model();
    const std::uint32_t a = cycles_now();
    sink = monitor_step(u2, m);
    const std::uint32_t c = cycles_elapsed(a, cycles_now());
    if (k == 0) first = c;
    if (c > worst) worst = c;
    total += c;
    health |= mon.health();
  }
  const auto stack_change = static_cast<std::uint32_t>(sp_main - stack_low_water());

  report_uint("monitor_bytes", static_cast<std::uint32_t>(sizeof mon));
  report_uint("model_bytes", static_cast<std::uint32_t>(sizeof(hstmon::fw::CircuitFwModel)));
  report_uint("states", static_cast<std::uint32_t>(mon.observer().model().n_states()));
  report_uint("channels", static_cast<std::uint32_t>(CircuitFwMonitor::kChannels));
  report_uint("ticks", kTicks);
  report_uint("counts_usual_loop", counts_usual);
  report_uint("counts_empty_loop", counts_empty);
  report_uint("max_substeps", max_substeps);
  report_uint("after_ticks", kAfter);
  report_uint("counts_change_first", first);
  report_uint("counts_change_worst", worst);
  report_uint("counts_change_total", total);
  report_uint("health_after_change", health);
  std::uint32_t events = 0;
  for (CircuitFwMonitor::Event e; mon.pop_event(e);) ++events;
  report_uint("events", events);
  report_uint("stack_setup_bytes", stack_setup);
  report_uint("stack_usual_bytes", stack_usual);
  report_uint("stack_change_bytes", stack_change);
  report_end();
  return 0;
}
