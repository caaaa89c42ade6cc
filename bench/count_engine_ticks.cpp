// Driver for scripts/count_instructions.sh, the circuit engine's rows: N ticks of one
// variant between CALLGRIND_START_INSTRUMENTATION and CALLGRIND_STOP_INSTRUMENTATION
// (see count_ticks.cpp for the method).
//
//   hstmon_count_engine_ticks <variant> [ticks]
//   variants: engine_double engine_float   Observer<CircuitModel<T>> on thesis.json, 1 ms
//             odeint_engine_double odeint_engine_float   Boost.Odeint runge_kutta4, one step
//                                          per tick, on the same engine model
//             compiled_double compiled_float   Observer<CompiledModel<T>>, the compiled thesis
//                                          model (generated/thesis_circuit_compiled.hpp), 1 ms,
//                                          as hosts run it (the fused usual tick)
//             compiled_general_double compiled_general_float   the same on the general tick
//                                          alone (Observer<…, false>: what firmware runs)
//             odeint_compiled_double odeint_compiled_float   runge_kutta4 on the compiled model
//
// Exit status 2 on bad usage or a circuit that does not load, 3 if the run left the
// operating point.

#include <valgrind/callgrind.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "count_driver.hpp"
#include "engine_workload.hpp"

namespace {

using hstmon_bench::EngineMeasurements;
using hstmon_bench::plausible;
using hstmon_bench::ThesisCircuit;

constexpr int kWarmup = 64;

// One out-of-line call per tick, as in count_ticks.cpp.
template <typename Sim, typename Inputs, typename Measurement>
__attribute__((noinline)) void tick(Sim& sim, const Inputs& u, const Measurement& m) {
  sim.step(u, m);
}

template <typename Sim, typename T, typename Inputs>
__attribute__((noinline)) void run(Sim& sim, const Inputs& u0, const EngineMeasurements<T>& table, std::uint64_t first,
                                   long n) {
  Inputs u = u0;
  for (long k = 0; k < n; ++k) {
    hstmon_bench::escape_engine(&u);  // inputs come from outside each tick
    tick(sim, u, table[first + static_cast<std::uint64_t>(k)]);
    hstmon_bench::escape_engine(&sim.residual());
  }
}

template <typename Sim, typename T, typename Inputs>
void measure(Sim& sim, const Inputs& u, const EngineMeasurements<T>& table, long n) {
  run<Sim, T>(sim, u, table, 0, kWarmup);
  CALLGRIND_START_INSTRUMENTATION;
  run<Sim, T>(sim, u, table, kWarmup, n);
  CALLGRIND_STOP_INSTRUMENTATION;
}

template <typename T>
int engine(const ThesisCircuit& c, long n) {
  auto sim = hstmon_bench::make_engine_observer<T>(c, T(1e-3));
  const EngineMeasurements<T> table(sim.estimate());
  measure<decltype(sim), T>(sim, c.inputs_as<T>(), table, n);
  const double w = static_cast<double>(sim.state()[1]);
  std::printf("ticks=%ld substeps=%d health=0x%x w_m=%.6g\n", n, sim.substeps(), sim.last_health(), w);
  return sim.last_health() == 0 && plausible(w) ? 0 : 3;
}

template <typename T>
int odeint_engine(const ThesisCircuit& c, long n) {
  hstmon_bench::OdeintEngine<T> sim(c, T(1e-3));
  const EngineMeasurements<T> table(hstmon_bench::make_engine_observer<T>(c, T(1e-3)).estimate());
  measure<decltype(sim), T>(sim, c.inputs_as<T>(), table, n);
  const double w = static_cast<double>(sim.state()[1]);
  std::printf("ticks=%ld rk4_steps=1 w_m=%.6g\n", n, w);
  return plausible(w) ? 0 : 3;
}

template <typename T, class Obs = hstmon_bench::CompiledObs<T>>
int compiled(long n) {
  auto sim = hstmon_bench::make_compiled_observer<T, Obs>(T(1e-3));
  const EngineMeasurements<T> table(sim.estimate());
  measure<decltype(sim), T>(sim, hstmon_bench::compiled_inputs<T>(), table, n);
  const double w = static_cast<double>(sim.state()[1]);
  std::printf("ticks=%ld substeps=%d health=0x%x usual=%llu w_m=%.6g\n", n, sim.substeps(), sim.last_health(),
              static_cast<unsigned long long>(sim.usual_ticks()), w);
  return sim.last_health() == 0 && plausible(w) ? 0 : 3;
}

template <typename T>
int odeint_compiled(long n) {
  const auto o = hstmon_bench::make_compiled_observer<T>(T(1e-3));
  hstmon_bench::OdeintEngine<T, hstmon_bench::Compiled<T>> sim(o.model(), o.state(), T(1e-3));
  const EngineMeasurements<T> table(o.estimate());
  measure<decltype(sim), T>(sim, hstmon_bench::compiled_inputs<T>(), table, n);
  const double w = static_cast<double>(sim.state()[1]);
  std::printf("ticks=%ld rk4_steps=1 w_m=%.6g\n", n, w);
  return plausible(w) ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  const long n = hstmon_bench::ticks_argument(argc, argv, "count_engine_ticks.cpp");
  if (n <= 0) return 2;
  try {
    const ThesisCircuit c(HSTMON_SOURCE_DIR);
    const char* v = argv[1];
    if (std::strcmp(v, "engine_double") == 0) return engine<double>(c, n);
    if (std::strcmp(v, "engine_float") == 0) return engine<float>(c, n);
    if (std::strcmp(v, "odeint_engine_double") == 0) return odeint_engine<double>(c, n);
    if (std::strcmp(v, "odeint_engine_float") == 0) return odeint_engine<float>(c, n);
    if (std::strcmp(v, "compiled_double") == 0) return compiled<double>(n);
    if (std::strcmp(v, "compiled_float") == 0) return compiled<float>(n);
    if (std::strcmp(v, "compiled_general_double") == 0) {
      return compiled<double, hstmon_bench::CompiledGeneralObs<double>>(n);
    }
    if (std::strcmp(v, "compiled_general_float") == 0) return compiled<float, hstmon_bench::CompiledGeneralObs<float>>(n);
    if (std::strcmp(v, "odeint_compiled_double") == 0) return odeint_compiled<double>(n);
    if (std::strcmp(v, "odeint_compiled_float") == 0) return odeint_compiled<float>(n);
    std::fprintf(stderr, "unknown variant '%s'\n", v);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
  return 2;
}
