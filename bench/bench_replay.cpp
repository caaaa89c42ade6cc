// Replay throughput of `hstmon replay`'s path (the built-in thesis.json): a one-hour 1 kHz
// log (3.6 M rows) generated in memory, then
//   Parse        circuit_tools::parse_circuit_log alone
//   Step         circuit_tools::replay_circuit over the parsed rows (observer at 1 ms,
//                model bound, matcher, fit after a detection, statistics)
//   ParseAndStep both, i.e. what replaying a log from memory costs
//   ParseAndStepResidualsOnly  the same without the fault matcher (--no-diagnosis)
//   ParseSimFormat  Parse on the same rows written as hstmon-sim writes them
// Target: ≥ 3.6 M rows/s (an hour of 1 kHz data in a second). Counters rows_per_s and
// x_target (rows/s over the target; ≥ 1 meets it). Rates use process CPU time, which on
// an idle machine equals wall time for this single-threaded work and on the shared
// build machine is not inflated by other jobs.
//
//   <build>/bin/hstmon_bench_replay [--benchmark_repetitions=3]   (3.6 M rows)
//   HSTMON_REPLAY_ROWS=100000 <build>/bin/hstmon_bench_replay   (quick check)

#include <benchmark/benchmark.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "bench_common.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
using LogData = ct::CircuitLog;

constexpr double kTargetRowsPerSecond = 3.6e6;

std::size_t row_count() {
  if (const char* s = std::getenv("HSTMON_REPLAY_ROWS")) {
    const long n = std::strtol(s, nullptr, 10);
    if (n > 0) return static_cast<std::size_t>(n);
  }
  return 3'600'000;  // one hour at 1 kHz
}

void append(std::string& out, double v, int precision, std::chars_format fmt = std::chars_format::fixed) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, fmt, precision);
  out.append(buf, res.ptr);
}

/// The log: nominal operating point (steady outputs of the reduced model) with a few
/// hundred Pa / a few rpm of deterministic noise. Columns as the rig writes them; with
/// `sim_format` numbers as hstmon-sim writes them instead (10 significant digits, "%.10g").
std::string make_log(bool sim_format) {
  const std::size_t n = row_count();
  const auto y0 = hstmon_bench::make_observer<double>(1e-3).estimate();
  const hstmon::ThesisInputs<double> u{};
  constexpr double kBar = 1e5;
  constexpr double kRpm = 60.0 / (2.0 * 3.14159265358979323846);
  std::string s;
  s.reserve(n * (sim_format ? 80 : 72) + 64);
  s += "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  std::uint32_t lcg = 1u;
  auto noise = [&lcg] {
    lcg = lcg * 1664525u + 1013904223u;
    return static_cast<double>(lcg >> 8) / 16777216.0 - 0.5;
  };
  const auto put = [&s, sim_format](double v, int precision, std::chars_format fmt = std::chars_format::fixed) {
    if (sim_format) {
      append(s, v, 10, std::chars_format::general);
    } else {
      append(s, v, precision, fmt);
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    put(static_cast<double>(i) * 1e-3, 3);
    s += ',';
    put(u.Psupl / kBar, 3);
    s += ',';
    put(u.kp, 4, std::chars_format::scientific);
    s += ',';
    put((y0[0] + 400.0 * noise()) / kBar, 5);
    s += ',';
    put((y0[1] + 400.0 * noise()) / kBar, 5);
    s += ',';
    put((y0[2] + 400.0 * noise()) / kBar, 4);
    s += ',';
    put((y0[3] + 0.05 * noise()) * kRpm, 2);
    s += '\n';
  }
  return s;
}

const std::string& log_text() {
  static const std::string text = make_log(false);
  return text;
}

// The built-in thesis.json and its fault table, as `hstmon replay` loads them.
const ct::LoadedCircuit& circuit() {
  static const ct::LoadedCircuit c = [] {
    ct::LoadedCircuit l;
    (void)ct::load_circuit("", "", l);  // built in: cannot fail
    return l;
  }();
  return c;
}
const ct::CircuitFaultTable& table() {
  static const ct::CircuitFaultTable t = hstmon::fdi::circuit_signature_table(circuit());
  return t;
}

LogData parse() { return ct::parse_circuit_log(log_text(), "bench_1h_1kHz.csv", circuit().file); }

const LogData& parsed_log() {
  static const LogData log = parse();
  return log;
}

/// Replays the parsed rows as `hstmon replay` does (inputs per row, observer tick per row,
/// residual statistics; the matcher unless residuals only); returns the health.
std::uint32_t step_all(const LogData& log, bool diagnose = true) {
  ct::CircuitReplayOptions opt;
  opt.tick = 1e-3;
  opt.diagnose = diagnose;
  opt.table = &table();
  const ct::CircuitReplayResult r = ct::replay_circuit(circuit(), log, opt);
  benchmark::DoNotOptimize(r.channels);
  return r.health;
}

bool check(benchmark::State& state, const LogData& log) {
  if (log.error || log.rows() != row_count()) {
    static std::string why;
    why = log.error ? log.error->to_string() : "wrong row count";
    state.SkipWithError(why.c_str());
    return false;
  }
  return true;
}

void report(benchmark::State& state) {
  const double rows = static_cast<double>(row_count());
  state.counters["rows_per_s"] = benchmark::Counter(rows, benchmark::Counter::kIsIterationInvariantRate);
  // rows/s divided by the target: ≥ 1 meets it.
  state.counters["x_target"] =
      benchmark::Counter(rows / kTargetRowsPerSecond, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["rows"] = rows;
}

void BM_Parse(benchmark::State& state) {
  const std::string& text = log_text();
  for (auto _ : state) {
    LogData log = parse();
    if (!check(state, log)) return;
    benchmark::DoNotOptimize(log.t.data());
  }
  report(state);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void BM_Step(benchmark::State& state) {
  const LogData& log = parsed_log();
  if (!check(state, log)) return;
  for (auto _ : state) {
    const std::uint32_t h = step_all(log);
    if (h != 0) {
      state.SkipWithError("observer raised health flags on the generated log");
      return;
    }
  }
  report(state);
}

void BM_ParseAndStep(benchmark::State& state) {
  for (auto _ : state) {
    LogData log = parse();
    if (!check(state, log)) return;
    benchmark::DoNotOptimize(step_all(log));
  }
  report(state);
}

}  // namespace

BENCHMARK(BM_Parse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseAndStep)->Unit(benchmark::kMillisecond);

/// As ParseAndStep, residuals only (`hstmon replay --no-diagnosis`: no fault matcher).
void BM_ParseAndStepResidualsOnly(benchmark::State& state) {
  for (auto _ : state) {
    LogData log = parse();
    if (!check(state, log)) return;
    benchmark::DoNotOptimize(step_all(log, false));
  }
  report(state);
}
BENCHMARK(BM_ParseAndStepResidualsOnly)->Unit(benchmark::kMillisecond);

/// As Parse, on the same rows written as hstmon-sim writes them ("33.18532082",
/// "4.41e-08": longer significands than the rig format above).
void BM_ParseSimFormat(benchmark::State& state) {
  static const std::string text = make_log(true);  // made before the timed loop
  for (auto _ : state) {
    LogData log = ct::parse_circuit_log(text, "bench_sim_1h_1kHz.csv", circuit().file);
    if (!check(state, log)) return;
    benchmark::DoNotOptimize(log.t.data());
  }
  report(state);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseSimFormat)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  (void)log_text();  // generate, load and build outside any timed region
  (void)table();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
