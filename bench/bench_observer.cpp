// Per-tick cost of hstmon::Observer<ThesisReducedModel<T>>::step at the nominal operating
// point, next to Boost.Odeint observers doing the same job on the same model
// (bench_common.hpp): "naive" (ours' nominal RK4 step count, no stiffness control) and
// "safe fixed" (the one fixed count stable over the whole envelope: 22 at 1 ms). Everything
// runs in one executable so the ratios come from one run.
//
//   <build>/bin/hstmon_bench_observer [--benchmark_repetitions=5 --benchmark_report_aggregates_only=true]
//
// Counters:
//   ns_per_tick      thread CPU time per tick measured inside the benchmark (the ratios use it)
//   ratio_vs_naive   ours / naive odeint at the same tick and precision, from the
//                    Odeint_Reduced run earlier in this process (registered first)
//   ratio_vs_safe    ours / safe fixed-substep odeint, from the Odeint_Safe run
//   Interleaved/*    ours and naive odeint alternate in blocks of 1024 ticks in one benchmark,
//                    so machine noise hits both equally: ours_ns, odeint_ns, ratio
// The machine is shared, so read ratios, not absolute times; count_instructions.sh gives
// the deterministic comparison.

#include <benchmark/benchmark.h>

#include <time.h>

#include <map>
#include <string>

#include "bench_common.hpp"

namespace {

using hstmon_bench::MeasurementTable;
using hstmon_bench::Obs;
using hstmon_bench::OdeintFull;
using hstmon_bench::OdeintReduced;

/// CPU time of this thread [s]: other processes on the shared machine preempting the
/// benchmark do not count (wall time would charge them to whichever side was running).
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// ns/tick of the odeint baselines measured earlier in this run, keyed "T/tick_us".
std::map<std::string, double>& baseline() {
  static std::map<std::string, double> m;
  return m;
}

template <typename T>
const char* type_name() {
  return sizeof(T) == sizeof(double) ? "double" : "float";
}

template <typename T>
std::string key(int tick_us) {
  return std::string(type_name<T>()) + "/" + std::to_string(tick_us);
}

template <typename T>
T tick_of(const benchmark::State& state) {
  return static_cast<T>(state.range(0)) * T(1e-6);
}

/// One tick as one out-of-line call for every variant, as in firmware (and count_ticks.cpp).
template <typename Sim, typename T>
__attribute__((noinline)) void one_tick(Sim& sim, const hstmon::ThesisInputs<T>& u,
                                    const typename Obs<T>::Measurement& m) {
  sim.step(u, m);
}

template <typename Sim, typename T>
void run_ticks(benchmark::State& state, Sim& sim, const MeasurementTable<T>& table, double* ns_per_tick) {
  hstmon::ThesisInputs<T> u{};
  std::uint64_t i = 0;
  const double t0 = thread_seconds();
  for (auto _ : state) {
    benchmark::DoNotOptimize(u);  // inputs come from outside each tick
    one_tick(sim, u, table[i++]);
    benchmark::DoNotOptimize(sim.residual());
    benchmark::ClobberMemory();
  }
  const double t1 = thread_seconds();
  *ns_per_tick = (t1 - t0) * 1e9 / static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["ns_per_tick"] = *ns_per_tick;
}

template <typename T>
void BM_Odeint_Reduced(benchmark::State& state) {
  const T tick = tick_of<T>(state);
  const int n_sub = hstmon_bench::nominal_substeps<T>(tick);  // same RK4 step count as ours
  OdeintReduced<T> sim(tick, n_sub);
  const MeasurementTable<T> table(hstmon_bench::make_observer<T>(tick).estimate());
  double ns = 0;
  run_ticks(state, sim, table, &ns);
  baseline()[key<T>(static_cast<int>(state.range(0)))] = ns;
  state.counters["rk4_steps"] = n_sub;
}

template <typename T>
void BM_Odeint_Safe(benchmark::State& state) {
  const T tick = tick_of<T>(state);
  const int n_sub = hstmon_bench::safe_substeps<T>(tick);
  OdeintReduced<T> sim(tick, n_sub);
  const MeasurementTable<T> table(hstmon_bench::make_observer<T>(tick).estimate());
  double ns = 0;
  run_ticks(state, sim, table, &ns);
  baseline()["safe/" + key<T>(static_cast<int>(state.range(0)))] = ns;
  state.counters["rk4_steps"] = n_sub;
}

template <typename T>
void BM_Ours(benchmark::State& state) {
  const T tick = tick_of<T>(state);
  Obs<T> sim = hstmon_bench::make_observer<T>(tick);
  const MeasurementTable<T> table(sim.estimate());
  double ns = 0;
  run_ticks(state, sim, table, &ns);
  if (sim.health() != 0) state.SkipWithError("observer raised health flags at the nominal point");
  state.counters["rk4_steps"] = sim.substeps();
  baseline()["ours/" + key<T>(static_cast<int>(state.range(0)))] = ns;
  const auto naive = baseline().find(key<T>(static_cast<int>(state.range(0))));
  if (naive != baseline().end() && naive->second > 0) state.counters["ratio_vs_naive"] = ns / naive->second;
  const auto safe = baseline().find("safe/" + key<T>(static_cast<int>(state.range(0))));
  if (safe != baseline().end() && safe->second > 0) state.counters["ratio_vs_safe"] = ns / safe->second;
}

void BM_Odeint_Full_Stiff(benchmark::State& state) {
  const double tick = tick_of<double>(state);
  OdeintFull sim(tick);
  const MeasurementTable<double> table(hstmon_bench::make_observer<double>(tick).estimate());
  double ns = 0;
  run_ticks(state, sim, table, &ns);
  state.counters["rk4_steps"] = sim.steps_per_tick();
  const auto it = baseline().find("ours/" + key<double>(static_cast<int>(state.range(0))));
  if (it != baseline().end() && it->second > 0) state.counters["ratio_vs_ours"] = ns / it->second;
  const double w = sim.state()[3];
  if (!(w > 100.0 && w < 250.0)) state.SkipWithError("full model left the operating point");
}

/// Ours and odeint alternating in blocks within one benchmark: the ratio is immune to
/// slow drifts in machine load.
template <typename T>
void BM_Interleaved(benchmark::State& state) {
  constexpr int kBlock = 1024;
  const T tick = tick_of<T>(state);
  Obs<T> ours = hstmon_bench::make_observer<T>(tick);
  OdeintReduced<T> theirs(tick, hstmon_bench::nominal_substeps<T>(tick));
  const MeasurementTable<T> table(ours.estimate());
  hstmon::ThesisInputs<T> u{};
  std::uint64_t i = 0, j = 0;
  // kBlock ticks of obs, reading the table from row `at` on.
  const auto block = [&](auto& obs, std::uint64_t& at) {
    for (int k = 0; k < kBlock; ++k) {
      benchmark::DoNotOptimize(u);
      one_tick(obs, u, table[at++]);
      benchmark::DoNotOptimize(obs.residual());
      benchmark::ClobberMemory();
    }
  };
  double t_ours = 0, t_theirs = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    block(ours, i);
    const double t1 = thread_seconds();
    block(theirs, j);
    const double t2 = thread_seconds();
    const double a = t1 - t0;
    const double b = t2 - t1;
    t_ours += a;
    t_theirs += b;
    state.SetIterationTime(a + b);
  }
  const double n = static_cast<double>(state.iterations()) * kBlock;
  state.counters["ours_ns"] = t_ours * 1e9 / n;
  state.counters["odeint_ns"] = t_theirs * 1e9 / n;
  state.counters["ratio"] = t_ours / t_theirs;
  state.SetItemsProcessed(static_cast<std::int64_t>(n) * 2);
}

}  // namespace

// Registration order matters: baselines first, so the ratio counters find them.
// Argument: tick in µs.
BENCHMARK_TEMPLATE(BM_Odeint_Reduced, double)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(BM_Odeint_Reduced, float)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(BM_Odeint_Safe, double)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(BM_Odeint_Safe, float)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(BM_Ours, double)->Arg(1000)->Arg(10000);
BENCHMARK_TEMPLATE(BM_Ours, float)->Arg(1000)->Arg(10000);
BENCHMARK(BM_Odeint_Full_Stiff)->Arg(1000);
BENCHMARK_TEMPLATE(BM_Interleaved, double)->Arg(1000)->UseManualTime();
BENCHMARK_TEMPLATE(BM_Interleaved, float)->Arg(1000)->UseManualTime();

BENCHMARK_MAIN();
