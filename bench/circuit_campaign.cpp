// Fault campaign for any circuit file (docs/fault_campaign.md, "Any circuit"):
// synthetic logs of the circuit from host_sim's stiff reference (hstmon-sim --circuit's
// simulate_circuit), replayed exactly as `hstmon replay --circuit` does (replay_circuit:
// the circuit's monitor and its generated fault table), scored as the thesis campaign
// scores. A benchmark program, not a test: nothing in CI runs it.
//
//   hstmon_circuit_campaign --circuit F [--params P] [--hours H] [--seeds N] [--jobs N]
//                           [--magnitude M] [--seed-base B] [--adc-bits N] [--lag S] [--json] [--verbose]
//
// Conditions: start at the steady state or from rest (inputs on at the first sample), at
// 1 kHz and 100 Hz. Every run has a machine 2 % off the file's values (each parameter the
// monitor treats as uncertain, uniform ±2 %, new per run) and load steps: every 2 s (6 τ
// where longer: a steady-state signature needs 4 τ to be read) one of
// the logged inputs with a non-zero nominal value moves to nominal × U[0.8, 1.25]
// (fractions kept within ±1). The sensors are the circuit file's (white noise, range
// clipping), the pressures through an ADC and every channel through a lag only when --adc-bits / --lag ask.
//
// Faults (fault at 2.5 s or 3 τ, runs 2.5 s or 6 τ longer, τ the circuit's slowest time
// constant at its nominal inputs): every row of the circuit's fault table —
//   <param>±: the machine's parameter × (1 ± M) from t_f (M = 0.3 by default);
//   <input>±: the true input × (1 ± M) from t_f, the log keeps the setting;
//   sensor_<ch>: a bias of 5 % of the range (or 20 σ without a range) from t_f.
// Nominal: segments of 100 s with the same load steps, hours split over the conditions.
//
// Scored: a `detected` before t_f (fault runs) or anywhere (nominal) is a false alarm;
// a fault run is detected when a `detected` comes at or after t_f; "in set" = the truth
// is among the candidates of the last event (detected / isolated / ambiguous) with candidates after
// t_f — the rule of ../shared/validation/score_monitor.py.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "campaign_score.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/operating_points.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_circuit/machine_spread.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace {

using hstmon::circuit_tools::CircuitLog;
using hstmon::circuit_tools::CircuitReplayOptions;
using hstmon::circuit_tools::CircuitSimOptions;
using hstmon::circuit_tools::InputStep;
using hstmon::circuit_tools::LoadedCircuit;

struct Condition {
  std::string name;
  bool from_rest = false;
  double rate = 1000.0;  // [Hz]
};

const std::vector<Condition> kConditions = {
    {"steady 1 kHz", false, 1000.0}, {"rest 1 kHz", true, 1000.0}, {"steady 100 Hz", false, 100.0},
    {"rest 100 Hz", true, 100.0}};

constexpr double kSegment = 100.0;  // nominal segment [s]
constexpr double kTieMargin = 0.01;  // FaultMatcher's default tie margin [rad]

// Operating-point changes after the fault in a fault run: each movable input once, and at
// least two, so that what a change of operating point splits (operating_points.hpp: a load
// change splits a torque fault from a pressure sensor's offset, a speed change a flow loss
// from a relief setting) a run can show, and the estimator judges a hypothesis at three
// points or more.
int changes_after_fault(const LoadedCircuit& c) {
  int movable = 0;
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) movable += c.values.inputs.v[i] != 0.0 ? 1 : 0;
  return std::max(2, movable);
}

// --fault-at-step: the fault begins at an input step, two steps into the run, so the point the
// machine then moves to is never read healthy (only the record's prediction can judge it).
bool g_fault_at_step = false;

// Fault time and run length [s]: the fault 2.5 s in, or 3 slowest time constants τ where
// longer (a start from rest has settled); the run goes on through changes_after input
// steps after it and ends where the next would come, a load period after the last (the
// matcher's settle of 3 τ and window of τ, as replay_circuit sets them, and the
// estimator's window fit in it).
struct Timing {
  double t_fault = 2.5, run = 5.0, tau = 0.0;
  double load_period = 2.0;  // [s] between input steps: 2 s, or 6 τ where longer (a decision needs 4 τ)
  int changes_after = 2;     // input steps after the fault (changes_after_fault)
};

Timing timing(const LoadedCircuit& c) {
  Timing tm;
  const hstmon::host::HostCircuitModel m(c.file.circuit, c.values.params, c.values.inputs);
  hstmon::host::HostCircuitModel::State xs;
  const double rate = m.valid() && m.steady_state(xs) ? m.slowest_rate(xs) : 0.0;
  if (rate > 0.0) {
    tm.tau = 1.0 / rate;
    tm.t_fault = std::max(2.5, 3.0 * tm.tau);
    tm.load_period = std::max(2.0, 6.0 * tm.tau);
  }
  if (g_fault_at_step) tm.t_fault = 1.0 + 2.0 * tm.load_period;
  // Steps fall at 1 s + k·period; the changes_after-th after the fault ends the changes.
  tm.changes_after = changes_after_fault(c);
  const double first_after = 1.0 + std::floor((tm.t_fault - 1.0) / tm.load_period + 1.0) * tm.load_period;
  tm.run = first_after + tm.changes_after * tm.load_period;
  return tm;
}
Timing g_timing;
// The circuit's fault table, as hstmon replay --circuit builds it; read-only once the runs start.
hstmon::circuit_tools::CircuitFaultTable g_table;
// --matcher-only: the matcher's verdict alone, as the firmware runs it (no fit, no step at held inputs).
bool g_matcher_only = false;
// --no-record: replay without the healthy record (CircuitReplayOptions::healthy_record), for comparing.
bool g_no_record = false;
// The transducers of every run (--lag, --adc-bits; none by default, as the recorded figures).
hstmon::circuit_tools::TransducerOptions g_transducers;
// The classes of faults no operating point of the runs' span splits (split_by_operating_point
// on the matcher's table; hstmon-fdi isolability --circuit): "isolated on the truth or its class".
std::vector<std::vector<std::string>> g_classes;

// The class of fault f (empty when it is isolable from every other).
std::vector<std::string> class_of(const std::string& f) {
  for (const auto& cls : g_classes) {
    if (std::find(cls.begin(), cls.end(), f) != cls.end()) return cls;
  }
  return {};
}

// What one campaign run injects.
struct Fault {
  std::string name;  // the table row's name ("" = nominal)
  int param = -1, input = -1, channel = -1;
  double factor = 1.0;  // parameter or true-input factor
};

struct RunResult {
  int alarms = 0;  // detected events in a nominal run
  hstmon_campaign::Scored s;  // a fault run (campaign_score.hpp): in set = s.in_last, reported set = s.last_set
  std::string error;
  bool early() const { return s.false_events > 0; }
  bool missed() const { return !s.detected || !s.in_last || early(); }
};

// Input steps every load period from 1 s, each on one input with a non-zero nominal value.
// Before the fault time: a random input to nominal × U[0.8, 1.25], load steps near the
// nominal point. From it on (fault runs and nominal segments alike): the inputs in turn, so
// that a load change and a displacement change both come after a fault, each to nominal ×
// U[0.5, 0.8] or U[1.25, 1.5] — the span of the isolability analysis's operating points
// (operating_points.hpp), so what it says a change of operating point splits, a run can
// show, and the nominal hours cover the same span.
std::vector<InputStep> load_steps(const LoadedCircuit& c, double duration, std::mt19937_64& rng) {
  std::vector<int> movable;
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    if (c.values.inputs.v[i] != 0.0) movable.push_back(static_cast<int>(i));
  }
  std::vector<InputStep> steps;
  if (movable.empty()) return steps;
  std::uniform_int_distribution<std::size_t> pick(0, movable.size() - 1);
  std::uniform_real_distribution<double> level(0.8, 1.25), away(0.0, 0.6);
  std::size_t next = pick(rng);
  for (double t = 1.0; t < duration; t += g_timing.load_period) {
    InputStep s;
    s.t = t;
    double factor = 1.0;
    if (t < g_timing.t_fault - 1e-9) {
      s.input = movable[pick(rng)];
      factor = level(rng);
    } else {
      s.input = movable[next];
      next = (next + 1) % movable.size();
      const double a = away(rng);  // [0, 0.3): below nominal, [0.3, 0.6): above
      factor = a < 0.3 ? 0.5 + a : 1.25 + (a - 0.3) * (0.25 / 0.3);
    }
    s.value = c.values.inputs.v[s.input] * factor;
    if (c.file.inputs[s.input].quantity == hstmon::host::CircuitQuantity::kFraction) s.value = std::clamp(s.value, -1.0, 1.0);
    steps.push_back(s);
  }
  return steps;
}

double sensor_bias(const hstmon::host::CircuitSensor& s) {
  if (std::isfinite(s.lo) && std::isfinite(s.hi) && s.hi > s.lo) return 0.05 * (s.hi - s.lo);
  return 20.0 * hstmon::circuit_tools::sensor_sigma(s);
}

// --dump: the folder where the log of every run that misses or is not isolated on the truth or
// its class, or nominal run that alarms, is written.
std::string g_dump_dir;

RunResult run_one(const LoadedCircuit& c, const Condition& cond, const Fault& f, double duration, std::uint64_t seed) {
  RunResult r;
  std::mt19937_64 rng(seed);
  LoadedCircuit m = hstmon::circuit_tools::spread_machine(c, 0.02, rng);  // the file's values, uncertain ones ±2 %
  CircuitSimOptions so;
  so.duration = duration;
  so.rate = cond.rate;
  so.seed = seed;
  so.from_rest = cond.from_rest;
  so.transducers = g_transducers;
  so.steps = load_steps(c, duration, rng);
  const bool faulted = !f.name.empty();
  if (f.param >= 0) {
    InputStep s;
    s.t = g_timing.t_fault;
    s.param = f.param;
    s.factor = f.factor;
    so.steps.push_back(s);
  }
  if (f.input >= 0) {
    // An input fault: the machine gets the setting × factor from t_f on, the log keeps the setting.
    InputStep s;
    s.t = g_timing.t_fault;
    s.input = f.input;
    s.factor = f.factor;
    s.input_fault = true;
    so.steps.push_back(s);
  }
  hstmon::circuit_tools::sort_steps(so.steps);
  CircuitLog log;
  try {
    log = hstmon::circuit_tools::simulate_circuit(m, so);
  } catch (const std::exception& e) {
    r.error = e.what();
    return r;
  }
  for (std::size_t k = 0; k < log.rows(); ++k) {
    if (log.t[k] < g_timing.t_fault - 1e-12) continue;
    if (f.channel >= 0 && !log.sensors[f.channel].empty()) log.sensors[f.channel][k] += sensor_bias(c.file.sensors[f.channel]);
  }
  CircuitReplayOptions ro;
  ro.table = &g_table;  // hstmon replay --circuit's (fdi::circuit_signature_table), built once
  ro.fit = !g_matcher_only;
  ro.healthy_record = !g_no_record;
  const auto res = hstmon::circuit_tools::replay_circuit(c, log, ro);
  if (faulted) {
    r.s = hstmon_campaign::score(res.events, f.name, g_timing.t_fault, kTieMargin, class_of(f.name), true);
  } else {
    for (const auto& e : res.events) r.alarms += e.event == "detected" ? 1 : 0;
  }
  if (!g_dump_dir.empty() && (faulted ? r.missed() || !r.s.isolated_class : r.alarms > 0)) {
    const std::string what = faulted ? fmt::format("{} at {} s", f.name, g_timing.t_fault) : "nominal";
    std::ofstream(fmt::format("{}/{}_{}.csv", g_dump_dir, faulted ? f.name : "nominal", seed))
        << hstmon::circuit_tools::circuit_log_text(c.file, log, {fmt::format("{}, {}, seed {}", what, cond.name, seed)});
  }
  return r;
}

// True when the circuit has a steady state at its nominal inputs with parameter p (or
// input i) times factor.
bool has_steady_state(const LoadedCircuit& c, int p, int i, double factor) {
  auto params = c.values.params;
  auto inputs = c.values.inputs;
  if (p >= 0)
    hstmon::circuit_tools::apply_param_fault(c.file, params, c.values.params, static_cast<std::size_t>(p), factor);
  if (i >= 0) inputs.v[i] *= factor;
  const hstmon::host::HostCircuitModel m(c.file.circuit, params, inputs);
  hstmon::host::HostCircuitModel::State xs;
  return m.valid() && m.steady_state(xs);
}

// The table's rows as faults to inject (in table order). A fault of the given magnitude
// that leaves the circuit no steady state (the machine stalls, every channel collapses:
// a different question) is injected at 10 %, as the table's own signs are then taken.
std::vector<Fault> table_faults(const LoadedCircuit& c, const hstmon::circuit_tools::CircuitFaultTable& table,
                                double magnitude, std::vector<std::string>& undetectable, std::vector<std::string>& notes) {
  undetectable = table.undetectable;
  std::vector<Fault> out;
  for (const std::string& name : table.names) {
    Fault f;
    f.name = name;
    if (name.rfind("sensor_", 0) == 0) {
      for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
        if (name == "sensor_" + c.file.sensors[ch].name) f.channel = static_cast<int>(ch);
      }
    } else {
      const std::string base = name.substr(0, name.size() - 1);
      const double factor = name.back() == '+' ? 1.0 + magnitude : 1.0 - magnitude;
      f.factor = factor;
      f.param = c.file.param_index(base);
      if (f.param < 0) f.input = c.file.input_index(base);
      if (!has_steady_state(c, f.param, f.input, f.factor)) {
        f.factor = name.back() == '+' ? 1.1 : 0.9;
        notes.push_back(fmt::format("{}: no steady state at {:.0f} %: injected at 10 %", name, 100.0 * magnitude));
        if (!has_steady_state(c, f.param, f.input, f.factor)) {
          notes.back() = fmt::format("{}: no steady state at 10 % either: not injected", name);
          continue;
        }
      }
    }
    if (f.param >= 0 || f.input >= 0 || f.channel >= 0) out.push_back(f);
  }
  return out;
}

struct Job {
  int condition;
  int fault;  // index into the faults, −1 = nominal segment
  std::uint64_t seed;
};

// Tallies of fault runs (per fault, per condition, all) or of nominal segments.
struct Tally {
  int runs = 0, detected = 0, in_set = 0, best = 0, early = 0, errors = 0;
  int cleared = 0;             // detected, and "cleared" at the end while the fault persisted
  int isolated = 0;            // the truth or its class isolated at the end (of detected)
  int sized = 0, size_ok = 0;  // isolated parameter/input faults with a fitted size; within 20 % of the fault's
  double delay_sum = 0.0;
  std::vector<double> isolation_delays;  // [s]
  double median_isolation() const {
    if (isolation_delays.empty()) return NAN;
    std::vector<double> d = isolation_delays;
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    return d[d.size() / 2];
  }
};

struct Tallies {
  std::map<std::string, Tally> by_fault;
  // Per truth: how often each other fault shared the reported set (detected runs).
  std::map<std::string, std::map<std::string, int>> confused;
  std::vector<Tally> by_cond = std::vector<Tally>(kConditions.size());
  Tally all, nominal;
  double nominal_s = 0.0;  ///< nominal replay without a simulation error [s]
};

struct Settings {
  std::string circuit, params;
  double hours = 1.0, magnitude = 0.3;
  int seeds = 2;
  std::uint64_t seed_base = 0;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  bool json = false, verbose = false;
};

void add_options(CLI::App& app, Settings& o) {
  app.add_option("--circuit", o.circuit, "circuit file")->required();
  app.add_option("--params", o.params, "its parameter file (default: <stem>.params.json beside it)");
  app.add_option("--hours", o.hours, "nominal replay in all [h]")->check(CLI::NonNegativeNumber);
  app.add_option("--seeds", o.seeds, "fault runs per fault and condition")->check(CLI::PositiveNumber);
  app.add_option("--magnitude", o.magnitude, "parameter / input fault size M: factor 1 ± M")->check(CLI::Range(0.01, 0.9));
  app.add_option("--jobs", o.jobs, "threads")->check(CLI::PositiveNumber);
  app.add_option("--seed-base", o.seed_base,
                 "added to every run's seed (machine, load steps, noise): 0 = the recorded figures' runs; "
                 "another value draws other runs, to check a figure is not these seeds'");
  app.add_flag("--json", o.json, "one JSON object with the figures");
  app.add_option("--dump", g_dump_dir,
                 "write the log of every run that misses or is not isolated on the truth or its class (or nominal run "
                 "that alarms) into this existing folder");
  app.add_flag("--verbose", o.verbose,
               "print every fault run whose truth is not in the reported set, or that is detected and not isolated on "
               "the truth or its class");
  app.add_option("--adc-bits", g_transducers.pressure_adc_bits,
                 "every pressure channel through an ADC of N bits over its range")
      ->check(CLI::Range(4, 24));
  app.add_option("--lag", g_transducers.lag, "every channel through a first-order lag of this time constant [s]")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--no-record", g_no_record,
               "replay without the healthy record (replay_circuit's healthy_record), for comparing");
  app.add_flag(
      "--fault-at-step", g_fault_at_step,
      "the fault begins at an input step (two steps in), so no healthy reading of the point it moves to exists");
  app.add_flag("--matcher-only", g_matcher_only,
               "the matcher's verdict alone, as the firmware runs it (replay --circuit --matcher-only)");
}

// Fault runs (seeds per fault and condition), then nominal segments over the conditions in turn.
std::vector<Job> make_jobs(std::size_t n_faults, const Settings& o) {
  std::vector<Job> work;
  const int n_cond = static_cast<int>(kConditions.size());
  for (int ci = 0; ci < n_cond; ++ci) {
    for (int fi = 0; fi < static_cast<int>(n_faults); ++fi) {
      for (int s = 0; s < o.seeds; ++s) work.push_back({ci, fi, 1000003ull * static_cast<std::uint64_t>(ci * 7919 + fi) + static_cast<std::uint64_t>(s) + 1 + o.seed_base});
    }
  }
  const int segments = static_cast<int>(std::ceil(o.hours * 3600.0 / kSegment));
  for (int k = 0; k < segments; ++k) work.push_back({k % n_cond, -1, 900000001ull + static_cast<std::uint64_t>(k) + o.seed_base});
  return work;
}

std::vector<RunResult> run_all(const LoadedCircuit& c, const std::vector<Job>& work, const std::vector<Fault>& faults,
                               unsigned jobs) {
  std::vector<RunResult> results(work.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> pool;
  for (unsigned j = 0; j < jobs; ++j) {
    pool.emplace_back([&] {
      for (std::size_t i = next++; i < work.size(); i = next++) {
        const Job& w = work[i];
        const Fault nominal;
        const Fault& f = w.fault >= 0 ? faults[static_cast<std::size_t>(w.fault)] : nominal;
        results[i] = run_one(c, kConditions[static_cast<std::size_t>(w.condition)], f, w.fault >= 0 ? g_timing.run : kSegment, w.seed);
      }
    });
  }
  for (auto& t : pool) t.join();
  return results;
}

// Per fault and per condition tallies; with verbose, the runs that failed or missed on stderr.
Tallies tally(const std::vector<Job>& work, const std::vector<RunResult>& results, const std::vector<Fault>& faults,
              bool verbose) {
  Tallies t;
  for (std::size_t i = 0; i < work.size(); ++i) {
    const Job& w = work[i];
    const RunResult& r = results[i];
    if (w.fault < 0) {
      ++t.nominal.runs;
      t.nominal.early += r.alarms;
      t.nominal.errors += r.error.empty() ? 0 : 1;
      if (r.error.empty()) t.nominal_s += kSegment;
      if (verbose && (r.alarms > 0 || !r.error.empty()))
        fmt::print(stderr, "nominal seed {} ({}): {} alarms {}\n", w.seed, kConditions[static_cast<std::size_t>(w.condition)].name, r.alarms, r.error);
      continue;
    }
    const Fault& f = faults[static_cast<std::size_t>(w.fault)];
    for (Tally* ta : {&t.by_fault[f.name], &t.by_cond[static_cast<std::size_t>(w.condition)], &t.all}) {
      ++ta->runs;
      ta->errors += r.error.empty() ? 0 : 1;
      ta->early += r.early() ? 1 : 0;
      ta->detected += r.s.detected ? 1 : 0;
      ta->in_set += r.s.detected && r.s.in_last ? 1 : 0;
      ta->best += r.s.detected && r.s.best_in_last ? 1 : 0;
      ta->cleared += r.s.detected && r.s.cleared_at_end ? 1 : 0;
      if (r.s.detected) ta->delay_sum += r.s.delay;
      if (r.s.detected && r.s.isolated_class) {
        ++ta->isolated;
        ta->isolation_delays.push_back(r.s.isolation_delay);
        // The size as the fault's relative change: −30 % fitted within −24 … −36 %.
        if (f.channel < 0 && std::isfinite(r.s.size)) {
          ++ta->sized;
          ta->size_ok += std::fabs((r.s.size - 1.0) - (f.factor - 1.0)) <= 0.2 * std::fabs(f.factor - 1.0) ? 1 : 0;
        }
      }
    }
    if (r.s.detected) {
      for (const std::string& other : r.s.last_set) {
        if (other != f.name) ++t.confused[f.name][other];
      }
    }
    if (verbose && !r.error.empty()) fmt::print(stderr, "{} seed {}: simulation failed: {}\n", f.name, w.seed, r.error);
    if (verbose && r.error.empty() && (r.missed() || (r.s.detected && !r.s.isolated_class)))
      fmt::print(stderr, "{} seed {} ({}): detected {} early {}{} — {}\n", f.name, w.seed,
                 kConditions[static_cast<std::size_t>(w.condition)].name, r.s.detected, r.early(),
                 r.missed() ? "" : ", not isolated", r.s.last.empty() ? "no decision" : r.s.last);
  }
  return t;
}

double percent(int a, int b) { return b > 0 ? 100.0 * a / b : 0.0; }

void print_json(const LoadedCircuit& c, std::size_t n_faults, const Tallies& t) {
  fmt::print(
      "{{\"circuit\":\"{}\",\"faults\":{},\"fault_runs\":{},\"detected_pct\":{:.2f},\"in_set_pct\":{:.2f},"
      "\"best_pct\":{:.2f},\"isolated_pct\":{:.2f},\"median_isolation_s\":{:.3f},\"size_within_20pct\":{:.2f},"
      "\"early_detections\":{},\"cleared_at_end\":{},\"nominal_hours\":{:.3f},\"nominal_false_alarms\":{},"
      "\"errors\":{}}}\n",
      c.file.name, n_faults, t.all.runs, percent(t.all.detected, t.all.runs), percent(t.all.in_set, t.all.detected),
      percent(t.all.best, t.all.detected), percent(t.all.isolated, t.all.detected), t.all.median_isolation(),
      percent(t.all.size_ok, t.all.sized), t.all.early, t.all.cleared, t.nominal_s / 3600.0, t.nominal.early,
      t.all.errors + t.nominal.errors);
}

// Which faults shared another's reported set, against what the matcher's table predicts.
void print_confusions(Tallies& t) {
  // The predicted relation is read off the table the matcher ran, slopes and orders too
  // (hstmon-fdi isolability --circuit, docs/isolability.md).
  const hstmon::circuit_tools::Isolability predicted = hstmon::circuit_tools::circuit_isolability(g_table);
  const auto mark = [&](const std::string& a, const std::string& b) {
    const auto at = [&](const std::string& f) {
      return static_cast<std::size_t>(std::find(predicted.faults.begin(), predicted.faults.end(), f) - predicted.faults.begin());
    };
    const std::size_t i = at(a), j = at(b);
    if (i >= predicted.faults.size() || j >= predicted.faults.size()) return "?";
    for (const auto& cls : predicted.classes) {  // one class: not isolable, even if this pair is directly
      if (std::count(cls.begin(), cls.end(), a) > 0 && std::count(cls.begin(), cls.end(), b) > 0) return "x";
    }
    return predicted.isolable[i][j] == 2 ? "~" : "!";
  };
  fmt::print("\nconfusions (a fault in the reported set of another's detected runs, in ≥ 25 % of them; predicted from the\n"
             "matcher's table: x in one class, ~ weakly isolable, ! isolable — not predicted):\n");
  for (const auto& [truth, others] : t.confused) {
    std::vector<std::string> shown;
    const int n = t.by_fault[truth].detected;
    for (const auto& [other, k] : others) {
      if (4 * k >= n) shown.push_back(fmt::format("{} {:.0f} % {}", other, percent(k, n), mark(truth, other)));
    }
    if (!shown.empty()) fmt::print("  {:<20} with {}\n", truth, fmt::join(shown, ", "));
  }
}

void print_report(const Settings& o, const LoadedCircuit& c, std::size_t n_faults, const std::vector<std::string>& undetectable,
                  const std::vector<std::string>& fault_notes, Tallies& t) {
  fmt::print("circuit {} ({}): {} faults in the table, magnitude {:.0f} %, {} seeds × {} conditions\n", c.file.name, o.circuit,
             n_faults, 100.0 * o.magnitude, o.seeds, kConditions.size());
  fmt::print(
      "slowest time constant {:.3g} s: faults at {:.3g} s in runs of {:.3g} s, input steps every {:.3g} s ({} after "
      "the fault)\n",
      g_timing.tau, g_timing.t_fault, g_timing.run, g_timing.load_period, g_timing.changes_after);
  if (!undetectable.empty()) fmt::print("not detectable at the nominal inputs (no row): {}\n", fmt::join(undetectable, ", "));
  std::vector<std::string> classes;
  for (const auto& cls : g_classes) classes.push_back("{" + fmt::format("{}", fmt::join(cls, ", ")) + "}");
  fmt::print("classes no operating point splits (isolated on one counts for its members): {}\n",
             classes.empty() ? "none" : fmt::format("{}", fmt::join(classes, " ")));
  for (const std::string& n : fault_notes) fmt::print("{}\n", n);
  fmt::print("\n{:<22} {:>5} {:>9} {:>8} {:>7} {:>9} {:>9} {:>9} {:>6}\n", "fault", "runs", "detected", "in set", "best",
             "isolated", "delay ms", "to iso s", "early");
  for (const auto& [name, ft] : t.by_fault) {
    fmt::print("{:<22} {:>5} {:>8.0f}% {:>7.0f}% {:>6.0f}% {:>8.0f}% {:>9.0f} {:>9.2f} {:>6}\n", name, ft.runs, percent(ft.detected, ft.runs),
               percent(ft.in_set, ft.detected), percent(ft.best, ft.detected), percent(ft.isolated, ft.detected),
               ft.detected > 0 ? 1e3 * ft.delay_sum / ft.detected : NAN, ft.median_isolation(), ft.early);
  }
  print_confusions(t);
  fmt::print("\n{:<22} {:>5} {:>9} {:>8} {:>9} {:>7}\n", "condition", "runs", "detected", "in set", "isolated", "early");
  for (std::size_t i = 0; i < kConditions.size(); ++i) {
    const Tally& ct = t.by_cond[i];
    fmt::print("{:<22} {:>5} {:>8.1f}% {:>7.1f}% {:>8.1f}% {:>6}\n", kConditions[i].name, ct.runs, percent(ct.detected, ct.runs),
               percent(ct.in_set, ct.detected), percent(ct.isolated, ct.detected), ct.early);
  }
  fmt::print(
      "\nall fault runs: {} — detected {:.1f} %, truth in set {:.1f} % of detected, best {:.1f} %, "
      "early detections {}, cleared at the end while the fault persisted {}\n",
      t.all.runs, percent(t.all.detected, t.all.runs), percent(t.all.in_set, t.all.detected),
      percent(t.all.best, t.all.detected), t.all.early, t.all.cleared);
  fmt::print("isolated on the truth or its class: {:.1f} % of detected, median {:.2f} s after the fault; size within 20 % "
             "in {:.1f} % of {} isolated parameter and input faults\n",
             percent(t.all.isolated, t.all.detected), t.all.median_isolation(), percent(t.all.size_ok, t.all.sized), t.all.sized);
  fmt::print("nominal: {:.2f} h in {} segments of {:.0f} s: {} false alarms\n", t.nominal_s / 3600.0, t.nominal.runs, kSegment, t.nominal.early);
  if (t.all.errors + t.nominal.errors > 0) fmt::print("simulation errors: {} (runs not scored)\n", t.all.errors + t.nominal.errors);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fault campaign for a circuit file: simulated faults and nominal hours through hstmon replay --circuit's monitor"};
  Settings o;
  add_options(app, o);
  CLI11_PARSE(app, argc, argv);

  LoadedCircuit c;
  if (const auto err = hstmon::circuit_tools::load_circuit(o.circuit, o.params, c)) {
    fmt::print(stderr, "{}\n", err->to_string());
    return 2;
  }
  std::vector<std::string> undetectable, fault_notes;
  std::vector<Fault> faults;
  try {
    g_table = hstmon::fdi::circuit_signature_table(c);
    faults = table_faults(c, g_table, o.magnitude, undetectable, fault_notes);
    g_classes = hstmon::circuit_tools::split_by_operating_point(c, hstmon::fdi::signature_fault_tables(),
                                                                hstmon::circuit_tools::SignatureParts::kFull, {},
                                                                &g_table)
                    .classes;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: {}\n", o.circuit, e.what());
    return 2;
  }

  g_timing = timing(c);
  const std::vector<Job> work = make_jobs(faults.size(), o);
  const std::vector<RunResult> results = run_all(c, work, faults, o.jobs);
  Tallies t = tally(work, results, faults, o.verbose);
  if (o.json) {
    print_json(c, faults.size(), t);
  } else {
    print_report(o, c, faults.size(), undetectable, fault_notes, t);
  }
  return 0;
}
