/// @file fault_campaign.cpp
/// The fault campaign over rig conditions (issue 12, docs/fault_campaign.md): for each
/// condition — the baseline rig and one factor changed at a time (transducer lag, sample
/// rate, start-up, load shape, ADC, parameter error) — the 50 % PRV blockage, every
/// parameter fault of the thesis table, sensor faults (loop break, stuck, bias) and hours
/// of nominal replay with start-ups, a stop/start and load changes, each log of the thesis
/// reference replayed exactly as `hstmon replay` does (the built-in thesis.json). A
/// benchmark program, not a test.
///
///   hstmon_fault_campaign [--quick] [--json] [--hours H] [--seeds N] [--param-seeds N]
///                         [--sensor-seeds N] [--jobs N] [--condition TEXT] [--t-fault S]
///                         [--after S] [--verbose] [--dump DIR]

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "campaign_runs.hpp"
#include "hstmon/fault_matcher.hpp"
#include "hstmon_sim/machine_error.hpp"
#include "hstmon_sim/measure.hpp"

namespace {

using namespace hstmon_campaign;
namespace sim = hstmon::sim;

struct Options {
  double hours = 10.0;     // nominal replay, total over the conditions
  int seeds = 20;          // blockage runs per condition
  int param_seeds = 3;     // runs per parameter fault and condition
  int sensor_seeds = 2;    // runs per sensor fault and condition
  int jobs = 1;
  double t_fault = 2.0;    // [s] (× the condition's time scale)
  double after = 3.0;      // [s]
  std::string only;        // conditions whose name contains this
  bool json = false;
  bool verbose = false;
  std::string dump;  // --dump DIR: each miss's log, as `hstmon replay` reads it
};

void usage() {
  std::fprintf(stderr,
               "usage: hstmon_fault_campaign [--quick] [--json] [--hours H] [--seeds N] [--param-seeds N]\n"
               "         [--sensor-seeds N] [--jobs N] [--condition TEXT] [--t-fault S] [--after S] [--verbose]\n"
               "         [--dump DIR]\n"
               "  --hours    nominal replay in total, split evenly over the conditions (default 10)\n"
               "  --seeds    50 %% blockage runs per condition (default 20)\n"
               "  --quick    0.5 h, 5 blockage seeds, 1 seed per parameter/sensor fault\n"
               "  --verbose  the events of every miss on stderr\n"
               "  --dump     write each miss's log to DIR (a thesis.json log: hstmon replay reads it)\n");
}

bool parse(int argc, char** argv, Options& o) {
  bool quick = false, hours = false, seeds = false, ps = false, ss = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto num = [&](double lo) {
      if (i + 1 >= argc) return std::nan("");
      char* end = nullptr;
      const double v = std::strtod(argv[++i], &end);
      return (end && *end == '\0' && v >= lo) ? v : std::nan("");
    };
    double v = 0;
    if (a == "--quick") quick = true;
    else if (a == "--json") o.json = true;
    else if (a == "--verbose") o.verbose = true;
    else if (a == "--hours" && !std::isnan(v = num(0))) o.hours = v, hours = true;
    else if (a == "--seeds" && !std::isnan(v = num(1))) o.seeds = static_cast<int>(v), seeds = true;
    else if (a == "--param-seeds" && !std::isnan(v = num(0))) o.param_seeds = static_cast<int>(v), ps = true;
    else if (a == "--sensor-seeds" && !std::isnan(v = num(0))) o.sensor_seeds = static_cast<int>(v), ss = true;
    else if (a == "--jobs" && !std::isnan(v = num(1))) o.jobs = static_cast<int>(v);
    else if (a == "--t-fault" && !std::isnan(v = num(1.0))) o.t_fault = v;
    else if (a == "--after" && !std::isnan(v = num(0.5))) o.after = v;
    else if (a == "--condition" && i + 1 < argc) o.only = argv[++i];
    else if (a == "--dump" && i + 1 < argc)
      o.dump = argv[++i];
    else {
      usage();
      return false;
    }
  }
  if (quick) {
    if (!hours) o.hours = 0.5;
    if (!seeds) o.seeds = 5;
    if (!ps) o.param_seeds = 1;
    if (!ss) o.sensor_seeds = 1;
  }
  return true;
}

template <class Fn>
void parallel_for(int n, int jobs, Fn fn) {
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i; (i = next.fetch_add(1)) < n;) fn(i);
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

enum class Kind { kFault, kNominal };

struct Job {
  int cond = 0;
  Kind kind = Kind::kFault;
  const FaultCase* fault = nullptr;
  int seed = 0;
};

struct Outcome {
  Scored s;
  NominalStats n;
  double cpu_s = 0;
  std::string trace;  // events of a miss (--verbose)
};

// Aggregate of fault runs of one group in one condition.
struct Agg {
  int runs = 0, detected = 0, decided = 0, in_set = 0, in_last = 0, iso_truth = 0, called_sensor = 0, false_events = 0;
  int within_50ms_and_iso = 0;
  long set_sum = 0;
  std::vector<double> delays;
  std::map<std::string, int> best_when_wrong;
  void add(const Scored& s) {
    ++runs;
    false_events += s.false_events;
    called_sensor += s.called_sensor;
    if (!s.detected) return;
    ++detected;
    delays.push_back(s.delay);
    decided += s.decided;
    in_set += s.in_set;
    in_last += s.in_last;
    iso_truth += s.isolated_as_truth;
    within_50ms_and_iso += s.isolated_as_truth && s.delay <= 0.050 + 1e-9;
    set_sum += s.set_size;
    if (!s.in_set) ++best_when_wrong[s.best.empty() ? "(none)" : s.best];
  }
  static double pct(int a, int b) { return b ? 100.0 * a / b : NAN; }
  double median_ms() const {
    if (delays.empty()) return NAN;
    std::vector<double> d = delays;
    std::sort(d.begin(), d.end());
    return 1e3 * (d.size() % 2 ? d[d.size() / 2] : 0.5 * (d[d.size() / 2 - 1] + d[d.size() / 2]));
  }
  double worst_ms() const { return delays.empty() ? NAN : 1e3 * *std::max_element(delays.begin(), delays.end()); }
  double mean_set() const { return detected ? static_cast<double>(set_sum) / detected : NAN; }
  std::string wrong() const {
    std::vector<std::pair<int, std::string>> v;
    for (const auto& [k, n] : best_when_wrong) v.push_back({n, k});
    std::sort(v.rbegin(), v.rend());
    std::string out;
    for (std::size_t i = 0; i < v.size() && i < 4; ++i) out += (i ? " " : "") + v[i].second + "×" + std::to_string(v[i].first);
    return out;
  }
};

struct NomAgg {
  double seconds = 0;
  long rows = 0, detections = 0, nonfinite = 0, segments = 0;
  std::uint32_t health = 0;
  std::map<std::string, int> calls;
  std::vector<std::pair<int, double>> first_times;  // (segment, t)
};

std::string f1(double v, const char* fmt = "%.1f") {
  if (std::isnan(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

std::string jnum(double v, const char* fmt = "%.1f") { return std::isnan(v) ? "null" : f1(v, fmt); }

const char* kGroups[] = {"kp- 50%", "param", "loop break", "stuck", "bias 2%FS", "bias 5%FS"};
constexpr double kLevels[] = {1.6, 1.0, 0.65};  // initial PRV setting: light, nominal, heavy

// Nominal segment length in condition c [s]: 100 s, 1000 s at a slow sample rate.
double nominal_segment(const Condition& c) { return 100.0 * (time_scale(c) > 1.0 ? 10.0 : 1.0); }

// Jobs: nominal segments first (the long ones), then the fault runs.
std::vector<Job> make_jobs(const std::vector<Condition>& conds, const std::vector<FaultCase>& pfaults,
                           const std::vector<std::vector<FaultCase>>& sfaults, const Options& o) {
  const double hours_per_cond = o.hours / static_cast<double>(conds.size());
  std::vector<Job> jobs;
  for (int ci = 0; ci < static_cast<int>(conds.size()); ++ci) {
    const double seg = nominal_segment(conds[static_cast<std::size_t>(ci)]);
    const int n_seg = static_cast<int>(std::ceil(hours_per_cond * 3600.0 / seg - 1e-9));
    for (int s = 0; s < n_seg; ++s) jobs.push_back({ci, Kind::kNominal, nullptr, s});
  }
  for (int ci = 0; ci < static_cast<int>(conds.size()); ++ci) {
    for (const FaultCase& f : pfaults) {
      const int n = f.group == std::string("kp- 50%") ? o.seeds : o.param_seeds;
      for (int s = 0; s < n; ++s) jobs.push_back({ci, Kind::kFault, &f, s});
    }
    for (const FaultCase& f : sfaults[static_cast<std::size_t>(ci)]) {
      for (int s = 0; s < o.sensor_seeds; ++s) jobs.push_back({ci, Kind::kFault, &f, s});
    }
  }
  return jobs;
}

// One job in condition c: a nominal segment scored for false alarms, or a fault run scored
// against its row (tie: the matcher's tie margin); with --verbose, a miss's events.
Outcome run_job(const Job& j, const Condition& c, const Options& o, double tie) {
  const auto t0 = std::chrono::steady_clock::now();
  const sim::SensorConfig sensors = sensors_of(c);
  const double k = time_scale(c);
  const auto seed = static_cast<std::uint64_t>(j.seed);
  const double level = kLevels[j.seed % 3];
  Outcome r;
  if (j.kind == Kind::kNominal) {
    const double seg = nominal_segment(c);
    const sim::ThesisScenario sc = sim::thesis_rig_run(run_of(c, seg, level, 50000 + seed, true));
    const Params machine = sim::perturbed_params(90000 + seed, c.spread);
    r.n = score_nominal(replay_log(sim::measure(sc, sensors, 300000 + seed, machine), sensors, c.declare_ranges));
  } else {
    const FaultCase& f = *j.fault;
    const double t_f = o.t_fault * k;
    sim::ThesisScenario sc = sim::thesis_rig_run(run_of(c, t_f + o.after * k, level, 1000 + seed, false));
    const Params machine = sim::perturbed_params(2000 + seed, c.spread);
    const std::uint64_t noise = 7000000 + 1000 * seed + std::hash<std::string>{}(f.label) % 1000;
    sim::ThesisMeasurements log;
    if (f.target == Target::kInput) {
      log = sim::measure(sim::with_input_fault(sc, f.input, f.factor, t_f), sensors, noise, machine);
    } else if (f.target == Target::kParam) {
      Params faulty = machine;
      faulty.*(f.param) *= f.factor;
      log = sim::measure_with_fault(sc, sensors, noise, machine, t_f, faulty);
    } else {
      log = sim::measure(sc, sensors, noise, machine);
      sim::SensorFault sf = f.sensor;
      sf.t_start = t_f;
      sim::inject_sensor_fault(log, sensors, sf);
    }
    const hstmon::circuit_tools::CircuitReplayResult res = replay_log(log, sensors, c.declare_ranges);
    r.s = score(res.events, f.row, t_f, tie);
    if (o.verbose && (!r.s.in_set || r.s.false_events || !r.s.detected)) {
      char b[160];
      std::snprintf(b, sizeof b, "%s | %s seed %d (t_f %.1f s):", c.name.c_str(), f.label.c_str(), j.seed, t_f);
      r.trace = b;
      for (const auto& e : res.events) {
        std::snprintf(b, sizeof b, " %s@%.3f", e.event.c_str(), e.t);
        r.trace += b;
        if (!e.candidates.empty()) r.trace += "[" + e.candidates[0].fault + "]";
      }
    }
    if (!o.dump.empty() && (!r.s.in_set || r.s.false_events || !r.s.detected)) {
      std::string name = c.name + "_" + f.label + "_" + std::to_string(j.seed);
      for (char& ch : name) {
        if (std::isalnum(static_cast<unsigned char>(ch)) == 0 && ch != '+' && ch != '-') ch = '_';
      }
      std::ofstream(o.dump + "/" + name + ".csv") << log_text(
          log, c.name + " | " + f.label + ", fault at " + std::to_string(t_f) + " s, seed " + std::to_string(j.seed));
    }
  }
  r.cpu_s = seconds_since(t0);
  return r;
}

// The outcomes summed per condition: per fault group, all faults, nominal replay, CPU time.
struct Totals {
  std::vector<std::map<std::string, Agg>> agg;
  std::vector<Agg> all_faults;
  std::vector<NomAgg> nom;
  std::vector<double> cpu;
};

Totals aggregate(const std::vector<Job>& jobs, const std::vector<Outcome>& out, std::size_t n_conds, bool verbose) {
  Totals tot{std::vector<std::map<std::string, Agg>>(n_conds), std::vector<Agg>(n_conds), std::vector<NomAgg>(n_conds),
             std::vector<double>(n_conds, 0.0)};
  auto& agg = tot.agg;
  auto& all_faults = tot.all_faults;
  auto& nom = tot.nom;
  auto& cpu = tot.cpu;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const auto ci = static_cast<std::size_t>(jobs[i].cond);
    cpu[ci] += out[i].cpu_s;
    if (jobs[i].kind == Kind::kNominal) {
      const NominalStats& n = out[i].n;
      NomAgg& a = nom[ci];
      a.seconds += n.seconds;
      a.rows += n.rows;
      a.detections += n.detections;
      a.nonfinite += n.nonfinite;
      a.health |= n.health;
      ++a.segments;
      for (const auto& s : n.calls) ++a.calls[s];
      for (double t : n.times) a.first_times.push_back({jobs[i].seed, t});
    } else {
      agg[ci][jobs[i].fault->group].add(out[i].s);
      all_faults[ci].add(out[i].s);
      if (verbose && !out[i].trace.empty()) std::fprintf(stderr, "%s\n", out[i].trace.c_str());
    }
  }
  return tot;
}

void print_json(const Options& o, const std::vector<Condition>& conds, Totals& t, double total_s) {
  auto& agg = t.agg;
  const auto& nom = t.nom;
  const auto& cpu = t.cpu;
  std::printf("{\"type\":\"fault_campaign\",\"hours\":%g,\"seeds\":%d,\"param_seeds\":%d,\"sensor_seeds\":%d,"
              "\"jobs\":%d,\"runtime_s\":%.1f,\"conditions\":[\n",
              o.hours, o.seeds, o.param_seeds, o.sensor_seeds, o.jobs, total_s);
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    const NomAgg& n = nom[ci];
    std::printf("{\"condition\":\"%s\",\"factor\":\"%s\",\"cpu_s\":%.1f,\"nominal\":{\"hours\":%.3f,\"false_alarms\":%ld,"
                "\"nonfinite\":%ld,\"health\":%u},\"groups\":[",
                conds[ci].name.c_str(), conds[ci].factor.c_str(), cpu[ci], n.seconds / 3600.0, n.detections,
                n.nonfinite, n.health);
    bool first = true;
    for (const char* g : kGroups) {
      const Agg& a = agg[ci][g];
      std::printf("%s{\"group\":\"%s\",\"runs\":%d,\"detected\":%d,\"median_delay_ms\":%s,\"worst_delay_ms\":%s,"
                  "\"truth_in_set\":%d,\"truth_in_last_event\":%d,\"isolated_as_truth\":%d,"
                  "\"within_50ms_isolated\":%d,\"called_sensor\":%d,\"mean_set_size\":%s,\"false_before_fault\":%d}",
                  first ? "" : ",", g, a.runs, a.detected, jnum(a.median_ms()).c_str(), jnum(a.worst_ms()).c_str(),
                  a.in_set, a.in_last, a.iso_truth, a.within_50ms_and_iso, a.called_sensor,
                  jnum(a.mean_set(), "%.2f").c_str(), a.false_events);
      first = false;
    }
    std::printf("]}%s\n", ci + 1 == conds.size() ? "" : ",");
  }
  std::printf("]}\n");
}

// A: nominal replay and the 50 % PRV blockage per condition.
void print_nominal_and_blockage(const std::vector<Condition>& conds, Totals& t) {
  auto& agg = t.agg;
  const auto& nom = t.nom;
  std::printf("A. Nominal replay and the 50 %% PRV blockage (kp-) per condition\n");
  std::printf("%-20s %7s %6s %5s | %5s %6s %6s %6s %7s %7s %7s\n", "condition", "nom [h]", "false", "NaN", "runs",
              "det%", "med", "worst", "≤50ms&", "iso kp-", "sensor");
  std::printf("%-20s %7s %6s %5s | %5s %6s %6s %6s %7s %7s %7s\n", "", "", "alarms", "", "", "", "[ms]", "[ms]",
              "iso kp-%", "%", "named%");
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    const NomAgg& n = nom[ci];
    const Agg& b = agg[ci]["kp- 50%"];
    std::printf("%-20s %7.2f %6ld %5ld | %5d %6s %6s %6s %7s %7s %7s\n", conds[ci].name.c_str(), n.seconds / 3600.0,
                n.detections, n.nonfinite, b.runs, f1(Agg::pct(b.detected, b.runs)).c_str(), f1(b.median_ms(), "%.0f").c_str(),
                f1(b.worst_ms(), "%.0f").c_str(), f1(Agg::pct(b.within_50ms_and_iso, b.runs)).c_str(),
                f1(Agg::pct(b.iso_truth, b.runs)).c_str(), f1(Agg::pct(b.called_sensor, b.runs)).c_str());
  }
}

// B: every fault group per condition.
void print_groups(const std::vector<Condition>& conds, Totals& t) {
  auto& agg = t.agg;
  const auto& all_faults = t.all_faults;
  std::printf("\nB. Fault groups per condition: detection rate, delay, truth in the reported set (last decision's\n"
              "   candidates within the tie margin), truth among the last event's candidates (score_monitor.py's\n"
              "   rule), mean set size; best candidate when the truth is not in the set\n");
  std::printf("%-20s %-10s %5s %6s %6s %6s %6s %6s %5s %5s  %s\n", "condition", "group", "runs", "det%", "med",
              "worst", "inSet%", "inLast", "set", "early", "best when truth not in set");
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    auto row = [&](const char* g, const Agg& a) {
      std::printf("%-20s %-10s %5d %6s %6s %6s %6s %6s %5s %5d  %s\n", conds[ci].name.c_str(), g, a.runs,
                  f1(Agg::pct(a.detected, a.runs)).c_str(), f1(a.median_ms(), "%.0f").c_str(),
                  f1(a.worst_ms(), "%.0f").c_str(), f1(Agg::pct(a.in_set, a.detected)).c_str(),
                  f1(Agg::pct(a.in_last, a.detected)).c_str(), f1(a.mean_set(), "%.2f").c_str(), a.false_events,
                  a.wrong().c_str());
    };
    for (const char* g : kGroups) row(g, agg[ci][g]);
    row("all", all_faults[ci]);
  }
}

// C: what the false alarms on nominal replay named.
void print_false_alarms(const std::vector<Condition>& conds, const Totals& t) {
  const auto& nom = t.nom;
  std::printf("\nC. False alarms on nominal replay: what the first decision after each named\n");
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    if (nom[ci].calls.empty()) continue;
    std::printf("  %-20s", conds[ci].name.c_str());
    for (const auto& [k, v] : nom[ci].calls) std::printf(" %s×%d", k.c_str(), v);
    std::printf("  (first at");
    for (std::size_t q = 0; q < nom[ci].first_times.size() && q < 3; ++q)
      std::printf(" seg %d t=%.3f s", nom[ci].first_times[q].first, nom[ci].first_times[q].second);
    std::printf(")\n");
  }
}

// The campaign's targets, met or missed.
void print_targets(const std::vector<Condition>& conds, Totals& t) {
  auto& agg = t.agg;
  const auto& all_faults = t.all_faults;
  const auto& nom = t.nom;
  double nom_h = 0;
  long nom_fa = 0, nom_nan = 0;
  int fault_false = 0, det = 0, in_set = 0;
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    nom_h += nom[ci].seconds / 3600.0;
    nom_fa += nom[ci].detections;
    nom_nan += nom[ci].nonfinite;
    fault_false += all_faults[ci].false_events;
    det += all_faults[ci].detected;
    in_set += all_faults[ci].in_set;
  }
  std::printf("\nTargets\n");
  std::printf("  0 false alarms, %.2f h nominal (start-ups, stop/start, load changes) + before-fault parts: %s "
              "(%ld nominal, %d in fault runs; %ld non-finite)\n",
              nom_h, nom_fa == 0 && fault_false == 0 ? "MET" : "MISSED", nom_fa, fault_false, nom_nan);
  std::printf("  truth in the reported set ≥ 95 %% of detected fault runs: %s (%s %%, %d of %d)\n",
              Agg::pct(in_set, det) >= 95.0 ? "MET" : "MISSED", f1(Agg::pct(in_set, det)).c_str(), in_set, det);
  std::printf("  blockage detected ≤ 50 ms and isolated as kp- in ≥ 95 %% of runs, per transducer setting (1 kHz):\n");
  for (std::size_t ci = 0; ci < conds.size(); ++ci) {
    if (conds[ci].factor != "base" && conds[ci].factor != "lag") continue;
    const Agg& b = agg[ci]["kp- 50%"];
    std::printf("    %-20s %s (%d of %d; named a sensor fault in %d)\n", conds[ci].name.c_str(),
                Agg::pct(b.within_50ms_and_iso, b.runs) >= 95.0 ? "MET" : "MISSED", b.within_50ms_and_iso, b.runs,
                b.called_sensor);
  }
  std::printf("  sensor faults caught (detected, truth in set), all conditions:\n");
  for (const char* g : {"loop break", "stuck", "bias 2%FS", "bias 5%FS"}) {
    int r = 0, d = 0, s = 0;
    for (std::size_t ci = 0; ci < conds.size(); ++ci) {
      r += agg[ci][g].runs;
      d += agg[ci][g].detected;
      s += agg[ci][g].in_set;
    }
    std::printf("    %-10s %s %% detected (%d of %d), truth in set %s %%\n", g, f1(Agg::pct(d, r)).c_str(), d, r,
                f1(Agg::pct(s, d)).c_str());
  }
}

void print_report(const Options& o, const std::vector<Condition>& conds, Totals& t, double total_s) {
  const double hours_per_cond = o.hours / static_cast<double>(conds.size());
  std::printf(
      "hstmon fault campaign over rig conditions (each log replayed as `hstmon replay` does, default\n"
      "options: the built-in thesis.json, init auto, its transmitter ranges). Baseline: rig_fast sensors at 1 kHz (no "
      "lag, σ 0.04 bar / 0.5 rpm,\n"
      "ADC 0.01 bar, Ppp 0–400 bar), machine ±2 %%, start from rest (supply on at the first sample), PRV steps every 2 "
      "s\n"
      "in [0.65, 1.6]·kp0. Each other condition changes one factor. Fault at t = %.0f s (×20 at 0.25 Hz),\n"
      "%.0f s after; nominal: %.2f h per condition in 100 s segments (1000 s at 0.25 Hz), each a start-up\n"
      "from rest, a stop at 60 %% and a restart at 70 %% of the segment, a new machine and seeds.\n\n",
      o.t_fault, o.after, hours_per_cond);
  print_nominal_and_blockage(conds, t);
  print_groups(conds, t);
  print_false_alarms(conds, t);
  print_targets(conds, t);
  const auto& cpu = t.cpu;
  std::printf("\nRuntime: %.1f s wall on %d thread(s); per condition (CPU s):", total_s, o.jobs);
  for (std::size_t ci = 0; ci < conds.size(); ++ci) std::printf(" %s %.1f;", conds[ci].name.c_str(), cpu[ci]);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) return 1;
  const auto t_start = std::chrono::steady_clock::now();
  std::vector<Condition> conds;
  for (const Condition& c : campaign_conditions()) {
    if (o.only.empty() || c.name.find(o.only) != std::string::npos) conds.push_back(c);
  }
  if (conds.empty()) {
    std::fprintf(stderr, "no condition matches %s\n", o.only.c_str());
    return 1;
  }
  const double tie = hstmon::FaultMatcher<double>::Config{}.tie_margin;
  const std::vector<FaultCase> pfaults = parameter_faults();
  std::vector<std::vector<FaultCase>> sfaults;
  for (const Condition& c : conds) sfaults.push_back(sensor_faults(sensors_of(c)));
  const std::vector<Job> jobs = make_jobs(conds, pfaults, sfaults, o);

  std::vector<Outcome> out(jobs.size());
  parallel_for(static_cast<int>(jobs.size()), o.jobs, [&](int i) {
    const Job& j = jobs[static_cast<std::size_t>(i)];
    out[static_cast<std::size_t>(i)] = run_job(j, conds[static_cast<std::size_t>(j.cond)], o, tie);
  });
  const double total_s = seconds_since(t_start);

  Totals t = aggregate(jobs, out, conds.size(), o.verbose);
  if (o.json) {
    print_json(o, conds, t, total_s);
  } else {
    print_report(o, conds, t, total_s);
  }
  return 0;
}
