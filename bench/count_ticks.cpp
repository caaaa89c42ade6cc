// Driver for scripts/count_instructions.sh: runs N ticks of one variant between
// CALLGRIND_START_INSTRUMENTATION and CALLGRIND_STOP_INSTRUMENTATION, so callgrind
// (--instr-atstart=no) counts exactly the ticks. Outside valgrind the client requests are
// no-ops and the program just runs.
//
//   hstmon_count_ticks <variant> [ticks]
//   variants: ours_double ours_float odeint_double odeint_float (naive: 1 RK4 step/tick)
//             odeint_safe_double odeint_safe_float (safe fixed: safe_substeps() RK4 steps/tick)
//             odeint_full
//             ours_{double,float}_10ms odeint_{double,float}_10ms (a 10 ms PLC scan; odeint with
//             ours' nominal substep count, 5)
//   diagnostics (one model call per "tick"): derivative_{double,float},
//   derivative_y_{double,float} (with outputs), outputs_{double,float}
//
// Setup, a warm-up of 64 ticks (lazy binding, first-touch) and the final plausibility
// check run outside the instrumented region. Exit status 2 on bad usage, 3 if the run
// left the operating point (the count would then be of the wrong work).

#include <valgrind/callgrind.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "bench_common.hpp"
#include "count_driver.hpp"

namespace {

using hstmon_bench::MeasurementTable;
using hstmon_bench::plausible;
using hstmon_bench::Reduced;

constexpr int kWarmup = 64;

// One tick is one out-of-line call for every variant, as in firmware (a timer task calls
// the observer once per tick). Without this GCC inlines some variants' step into the loop
// and not others, and their counts moved by up to 8 % with unrelated model edits.
template <typename Sim, typename T>
__attribute__((noinline)) void tick(Sim& sim, const hstmon::ThesisInputs<T>& u,
                                    const typename hstmon_bench::Obs<T>::Measurement& m) {
  sim.step(u, m);
}

// noinline so callgrind_annotate shows each variant's tick loop as its own function.
template <typename Sim, typename T>
__attribute__((noinline)) void run(Sim& sim, const MeasurementTable<T>& table, std::uint64_t first, long n) {
  hstmon::ThesisInputs<T> u{};
  for (long k = 0; k < n; ++k) {
    hstmon_bench::escape(&u);  // inputs come from outside each tick
    tick(sim, u, table[first + static_cast<std::uint64_t>(k)]);
    hstmon_bench::escape(&sim.residual());
  }
}

template <typename Sim, typename T>
void measure(Sim& sim, const MeasurementTable<T>& table, long n) {
  run(sim, table, 0, kWarmup);
  CALLGRIND_START_INSTRUMENTATION;
  run(sim, table, kWarmup, n);
  CALLGRIND_STOP_INSTRUMENTATION;
}

/// tick: 1 ms (one RK4 step at the nominal point) or 10 ms (a PLC scan: nominal_substeps).
template <typename T>
int ours(long n, T tick = T(1e-3)) {
  auto sim = hstmon_bench::make_observer<T>(tick);
  const MeasurementTable<T> table(sim.estimate());
  measure(sim, table, n);
  const bool ok = sim.health() == 0 && sim.substeps() == hstmon_bench::nominal_substeps<T>(tick) &&
                  plausible(static_cast<double>(sim.state()[1]));
  std::printf("ticks=%ld substeps=%d health=0x%x w_m=%.6g\n", n, sim.substeps(), sim.health(),
              static_cast<double>(sim.state()[1]));
  return ok ? 0 : 3;
}

/// n_sub = 0: safe_substeps(tick); −1: nominal_substeps(tick), ours at the nominal point.
template <typename T>
int odeint(long n, int n_sub, T tick = T(1e-3)) {
  if (n_sub == 0) n_sub = hstmon_bench::safe_substeps<T>(tick);
  if (n_sub < 0) n_sub = hstmon_bench::nominal_substeps<T>(tick);
  hstmon_bench::OdeintReduced<T> sim(tick, n_sub);
  const MeasurementTable<T> table(hstmon_bench::make_observer<T>(tick).estimate());
  measure(sim, table, n);
  const double w = static_cast<double>(sim.state()[1]);
  std::printf("ticks=%ld rk4_steps=%d w_m=%.6g\n", n, sim.steps_per_tick(), w);
  return plausible(w) ? 0 : 3;
}

/// Diagnostics: one model evaluation per "tick", to split a tick's count into model
/// evaluations and everything else. kind 0: derivative(x), 1: derivative(x, &y), 2: outputs(x).
template <typename T>
struct ModelCall {
  Reduced<T> model;
  typename Reduced<T>::State x;
  typename Reduced<T>::Output y = Reduced<T>::Output::Zero();
  int kind;
  ModelCall(int k) : model(hstmon_bench::make_observer<T>(T(1e-3)).model()),
                     x(hstmon_bench::make_observer<T>(T(1e-3)).state()), kind(k) {}
  void step(const hstmon::ThesisInputs<T>&, const typename hstmon_bench::Obs<T>::Measurement&) noexcept {
    hstmon_bench::escape(&x);
    if (kind == 0) {
      typename Reduced<T>::State d = model.derivative(x);
      hstmon_bench::escape(&d);
    } else if (kind == 1) {
      typename Reduced<T>::State d = model.derivative(x, &y);
      hstmon_bench::escape(&d);
    } else {
      y = model.outputs(x);
    }
  }
  const typename Reduced<T>::Output& residual() const noexcept { return y; }
};

template <typename T>
int model_call(int kind, long n) {
  ModelCall<T> sim(kind);
  const MeasurementTable<T> table(sim.y);
  measure(sim, table, n);
  return 0;
}

int odeint_full(long n) {
  hstmon_bench::OdeintFull sim(1e-3);
  const MeasurementTable<double> table(hstmon_bench::make_observer<double>(1e-3).estimate());
  measure(sim, table, n);
  const double w = sim.state()[3];
  std::printf("ticks=%ld rk4_steps=%d w_m=%.6g\n", n, sim.steps_per_tick(), w);
  return plausible(w) ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  const long n = hstmon_bench::ticks_argument(argc, argv, "count_ticks.cpp");
  if (n <= 0) return 2;
  const char* v = argv[1];
  if (std::strcmp(v, "ours_double") == 0) return ours<double>(n);
  if (std::strcmp(v, "ours_float") == 0) return ours<float>(n);
  if (std::strcmp(v, "odeint_double") == 0) return odeint<double>(n, 1);
  if (std::strcmp(v, "odeint_safe_double") == 0) return odeint<double>(n, 0);
  if (std::strcmp(v, "odeint_safe_float") == 0) return odeint<float>(n, 0);
  if (std::strcmp(v, "odeint_float") == 0) return odeint<float>(n, 1);
  if (std::strcmp(v, "ours_double_10ms") == 0) return ours<double>(n, 10e-3);
  if (std::strcmp(v, "ours_float_10ms") == 0) return ours<float>(n, 10e-3f);
  if (std::strcmp(v, "odeint_double_10ms") == 0) return odeint<double>(n, -1, 10e-3);
  if (std::strcmp(v, "odeint_float_10ms") == 0) return odeint<float>(n, -1, 10e-3f);
  if (std::strcmp(v, "odeint_full") == 0) return odeint_full(n);
  if (std::strcmp(v, "derivative_double") == 0) return model_call<double>(0, n);
  if (std::strcmp(v, "derivative_y_double") == 0) return model_call<double>(1, n);
  if (std::strcmp(v, "outputs_double") == 0) return model_call<double>(2, n);
  if (std::strcmp(v, "derivative_float") == 0) return model_call<float>(0, n);
  if (std::strcmp(v, "derivative_y_float") == 0) return model_call<float>(1, n);
  if (std::strcmp(v, "outputs_float") == 0) return model_call<float>(2, n);
  std::fprintf(stderr, "unknown variant '%s'\n", v);
  return 2;
}
