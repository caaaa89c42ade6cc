/// @file fault_campaign.cpp
/// Issue 3's fault campaign: every fault of the thesis signature table at two magnitudes ×
/// three operating points × N noise seeds, sensor bias / drift / stuck faults, and hours of
/// nominal replay with ±2 % parameter error, all through hstmon::Monitor<double> as the
/// host replay runs it. Prints a table (or --json). docs/fault_campaign.md explains the set-up
/// and holds the measured figures; scripts/fault_campaign.sh builds and runs it.
///
///   hstmon_fault_campaign [--quick] [--json] [--seeds N] [--hours H] [--jobs N]
///                         [--t-fault S] [--after S] [--spread F] [--verbose]

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "campaign_runs.hpp"
#include "hstmon/generated/thesis_signatures.hpp"

namespace {

using namespace hstmon_campaign;
using hstmon::MatchEventKind;
namespace sim = hstmon::sim;

struct Options {
  int seeds = 5;
  double hours = 10.0;
  int jobs = 1;
  double t_fault = 2.0;   // [s]
  double after = 3.0;     // [s] after the fault
  double spread = 0.02;   // machine parameter error [-]
  bool json = false;
  bool quick = false;
  bool verbose = false;
};

void usage() {
  std::fprintf(stderr,
               "usage: hstmon_fault_campaign [--quick] [--json] [--seeds N] [--hours H] [--jobs N]\n"
               "                             [--t-fault S] [--after S] [--spread F] [--verbose]\n"
               "  --verbose one line per fault run on stderr\n"
               "  --quick   2 seeds, 0.5 h of nominal replay (unless given)\n");
}

bool parse(int argc, char** argv, Options& o) {
  bool seeds_set = false, hours_set = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&](double& v) {
      if (i + 1 >= argc) return false;
      char* end = nullptr;
      v = std::strtod(argv[++i], &end);
      return end && *end == '\0' && std::isfinite(v);
    };
    double v = 0;
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--json") {
      o.json = true;
    } else if (a == "--verbose") {
      o.verbose = true;
    } else if (a == "--seeds" && next(v) && v >= 1) {
      o.seeds = static_cast<int>(v);
      seeds_set = true;
    } else if (a == "--hours" && next(v) && v >= 0) {
      o.hours = v;
      hours_set = true;
    } else if (a == "--jobs" && next(v) && v >= 1) {
      o.jobs = static_cast<int>(v);
    } else if (a == "--t-fault" && next(v) && v >= 1.5) {
      o.t_fault = v;
    } else if (a == "--after" && next(v) && v > 0.5) {
      o.after = v;
    } else if (a == "--spread" && next(v) && v >= 0 && v < 0.5) {
      o.spread = v;
    } else {
      usage();
      return false;
    }
  }
  if (o.quick) {
    if (!seeds_set) o.seeds = 2;
    if (!hours_set) o.hours = 0.5;
  }
  return true;
}

/// Runs fn(i) for i in [0, n) on `jobs` threads.
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

// ---------------------------------------------------------------------------------------
// One fault run and its scoring.

struct Job {
  int fault = 0;  // index into the case list
  int op = 0;
  int seed = 0;
};

struct Scored {
  RunResult r;
  bool in_set = false;      // truth in the reported set
  bool first = false;       // truth ranked first
  bool consistent = false;  // truth among the consistent candidates carried by the event
  bool within_class = false;  // truth in the set and the set inside the truth's class
  int set_size = 0;
  std::string best;         // best candidate of the last decision
  std::string decision;     // kind of the last decision
  double visibility = -1;
};

Scored score_run(const RunResult& r, const std::string& truth, const std::vector<std::vector<int>>& classes,
                 double tie_margin) {
  Scored s;
  s.r = r;
  if (!r.detected || !r.decided) return s;
  const auto& e = r.last_decision;
  s.decision = hstmon::to_string(e.kind);
  if (e.count > 0) s.best = e.candidate[0].name;
  for (int j = 0; j < e.count; ++j) s.consistent = s.consistent || truth == e.candidate[j].name;
  if (e.kind == MatchEventKind::kUnexplained || e.count == 0) return s;
  auto ang = [](double c) { return std::acos(std::fmin(1.0, std::fmax(-1.0, c))); };
  const double a0 = ang(e.candidate[0].score);
  std::vector<int> set;
  for (int j = 0; j < e.count; ++j) {
    if (j == 0 || ang(e.candidate[j].score) - a0 < tie_margin) set.push_back(e.candidate[j].index);
  }
  s.set_size = static_cast<int>(set.size());
  const int t = row_index(truth);
  s.first = e.candidate[0].index == t;
  s.in_set = std::find(set.begin(), set.end(), t) != set.end();
  if (s.in_set && t >= 0) {
    const auto& cls = classes[static_cast<std::size_t>(t)];
    s.within_class = std::all_of(set.begin(), set.end(),
                                 [&](int k) { return std::find(cls.begin(), cls.end(), k) != cls.end(); });
  }
  return s;
}

// Aggregate over a set of scored runs.
struct Agg {
  int runs = 0, detected = 0, decided = 0, in_set = 0, first = 0, consistent = 0, within_class = 0, unexplained = 0;
  int false_events = 0;
  long set_size_sum = 0;
  long class_size_sum = 0;
  std::vector<double> delays;  // [s]
  std::vector<double> iso_delays;
  double vis_min = 1e300, vis_max = -1e300;
  std::map<std::string, int> confused;  // best candidate when truth is not first

  void add(const Scored& s, const std::string& /*truth*/, int class_size, double t_fault) {
    ++runs;
    false_events += s.r.false_events;
    if (s.visibility >= 0) {
      vis_min = std::min(vis_min, s.visibility);
      vis_max = std::max(vis_max, s.visibility);
    }
    if (!s.r.detected) return;
    ++detected;
    delays.push_back(s.r.t_detect - t_fault);
    if (s.r.decided) {
      ++decided;
      iso_delays.push_back(s.r.t_decide - t_fault);
    }
    in_set += s.in_set;
    first += s.first;
    consistent += s.consistent;
    within_class += s.within_class;
    unexplained += s.decision == "unexplained";
    set_size_sum += s.set_size;
    class_size_sum += class_size;
    if (!s.first) ++confused[s.best.empty() ? (s.decision.empty() ? "(undecided)" : "(" + s.decision + ")") : s.best];
  }
  static double pct(int a, int b) { return b ? 100.0 * a / b : 0.0; }
  double det_rate() const { return pct(detected, runs); }
  static double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
  double med_ms() const { return median(delays) * 1e3; }
  double worst_ms() const { return delays.empty() ? NAN : *std::max_element(delays.begin(), delays.end()) * 1e3; }
  double med_iso_ms() const { return median(iso_delays) * 1e3; }
  double mean_set() const { return detected ? static_cast<double>(set_size_sum) / detected : NAN; }
  double mean_class() const { return detected ? static_cast<double>(class_size_sum) / detected : NAN; }
  std::string confusions() const {
    std::vector<std::pair<int, std::string>> v;
    for (const auto& [k, n] : confused) v.push_back({n, k});
    std::sort(v.rbegin(), v.rend());
    std::string out;
    for (const auto& [n, k] : v) out += (out.empty() ? "" : " ") + k + "×" + std::to_string(n);
    return out;
  }
};

std::string fmt_ms(double v) {
  if (std::isnan(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", v);
  return b;
}

std::string class_name(const std::vector<int>& cls) {
  std::string s;
  for (int k : cls) s += (s.empty() ? "" : ",") + std::string(hstmon::kThesisSignatures[k].name);
  return "{" + s + "}";
}

void print_row(const char* label, const Agg& a, bool with_vis) {
  char vis[32] = "";
  if (with_vis) std::snprintf(vis, sizeof vis, "%.2f–%.2f", a.vis_min, a.vis_max);
  std::printf("%-20s %-11s %4d %6.1f %6s %6s %6s %6.1f %6.1f %6.1f %5.2f/%-4.2f %4d  %s\n", label, vis, a.runs,
              a.det_rate(), fmt_ms(a.med_ms()).c_str(), fmt_ms(a.worst_ms()).c_str(), fmt_ms(a.med_iso_ms()).c_str(),
              Agg::pct(a.in_set, a.detected), Agg::pct(a.first, a.detected), Agg::pct(a.within_class, a.detected),
              a.mean_set(), a.mean_class(), a.unexplained, a.confusions().c_str());
}

void print_header(const char* first) {
  std::printf("%-20s %-11s %4s %6s %6s %6s %6s %6s %6s %6s %-10s %4s  %s\n", first, "visibility", "runs", "det%",
              "med", "worst", "iso", "inSet%", "first%", "class%", "set/class", "unex", "best when truth not first");
  std::printf("%-20s %-11s %4s %6s %6s %6s %6s %6s %6s %6s %-10s %4s\n", "", "(ss/thr)", "", "", "[ms]", "[ms]",
              "[ms]", "", "", "", "", "");
}

void json_agg(const char* key, const std::string& name, const Agg& a, bool last) {
  auto num = [](double v) {
    char b[40];
    if (std::isnan(v)) return std::string("null");
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::string(b);
  };
  std::printf(
      "{\"%s\":\"%s\",\"runs\":%d,\"detected\":%d,\"detection_rate\":%s,\"median_delay_ms\":%s,"
      "\"worst_delay_ms\":%s,\"median_decision_delay_ms\":%s,\"truth_in_set\":%d,\"truth_first\":%d,"
      "\"set_within_class\":%d,\"mean_set_size\":%s,\"mean_class_size\":%s,\"unexplained\":%d,"
      "\"false_events_before_fault\":%d,\"visibility_min\":%s,\"visibility_max\":%s,\"confusions\":\"%s\"}%s\n",
      key, name.c_str(), a.runs, a.detected, num(a.det_rate() / 100).c_str(), num(a.med_ms()).c_str(),
      num(a.worst_ms()).c_str(), num(a.med_iso_ms()).c_str(), a.in_set, a.first, a.within_class,
      num(a.mean_set()).c_str(), num(a.mean_class()).c_str(), a.unexplained, a.false_events,
      num(a.runs && a.vis_max >= 0 ? a.vis_min : NAN).c_str(), num(a.runs && a.vis_max >= 0 ? a.vis_max : NAN).c_str(),
      a.confusions().c_str(), last ? "" : ",");
}

std::string event_text(const hstmon::MatchEvent<double>& e, double t_fault) {
  char b[64];
  std::snprintf(b, sizeof b, "%s@%.0fms[", hstmon::to_string(e.kind), (e.time - t_fault) * 1e3);
  std::string s = b;
  for (int j = 0; j < e.count; ++j) {
    std::snprintf(b, sizeof b, "%s%s:%.4f", j ? " " : "", e.candidate[j].name, e.candidate[j].score);
    s += b;
  }
  return s + "]";
}

void print_verbose(const std::string& label, const char* op, int seed, const Scored& s, double t_fault) {
  std::fprintf(stderr, "%-18s %-7s seed %d vis %6.2f  %s", label.c_str(), op, seed, s.visibility,
               s.r.detected ? "" : "not detected");
  if (s.r.detected) std::fprintf(stderr, "det %+.0fms", (s.r.t_detect - t_fault) * 1e3);
  if (s.r.false_events) std::fprintf(stderr, " FALSE x%d", s.r.false_events);
  if (s.r.decided) {
    std::fprintf(stderr, "  first %s", event_text(s.r.first_decision, t_fault).c_str());
    std::fprintf(stderr, "  last %s", event_text(s.r.last_decision, t_fault).c_str());
    auto q = [](int v) { return v == 1 ? '+' : v == -1 ? '-' : v == 0 ? '0' : '?'; };
    char sym[40];
    std::snprintf(sym, sizeof sym, " mag %c%c%c%c slope %c%c%c%c first %c%c%c%c", q(s.r.magnitude[0]), q(s.r.magnitude[1]),
                  q(s.r.magnitude[2]), q(s.r.magnitude[3]), q(s.r.slope[0]), q(s.r.slope[1]), q(s.r.slope[2]),
                  q(s.r.slope[3]), (s.r.first_channels & 1) ? 'i' : '.', (s.r.first_channels & 2) ? 'o' : '.',
                  (s.r.first_channels & 4) ? 'p' : '.', (s.r.first_channels & 8) ? 'w' : '.');
    std::fprintf(stderr, "%s", sym);
  }
  std::fprintf(stderr, "  final %s%s\n", hstmon::to_string(s.r.final_status), (s.in_set || !s.r.detected) ? "" : "  <-- truth not in set");
}

bool by_design(const std::string& row) { return row == "J-" || row == "J+" || row == "K-" || row == "K+"; }

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) return 1;
  const auto t_start = std::chrono::steady_clock::now();
  const sim::SensorConfig sensors = sim::thesis_fast_sensors(1000.0);
  const Mon::Config cfg = monitor_config(sensors);
  const double tie = cfg.matcher.tie_margin;
  const auto classes = isolable_classes(hstmon::kThesisSignatures, hstmon::kThesisSignatureCount, tie);
  const double duration = o.t_fault + o.after;

  const std::vector<FaultCase> pfaults = parameter_faults();
  const std::vector<FaultCase> sfaults = sensor_faults(sensors);
  constexpr int kOps = 3;

  auto op_inputs = [](int op) {
    Inputs u;
    u.kp = sim::kThesisKpNominal * kOperatingPoints[op].kp_factor;
    return u;
  };
  auto machine_seed = [](int op, int seed) { return static_cast<std::uint64_t>(1000 + 10 * seed + op); };
  auto noise_seed = [](int op, int seed, int fault) {
    return static_cast<std::uint64_t>(7000000 + 100000 * seed + 1000 * op + fault);
  };

  // --- Parameter faults ---------------------------------------------------------------
  std::vector<Job> pjobs;
  for (int f = 0; f < static_cast<int>(pfaults.size()); ++f)
    for (int op = 0; op < kOps; ++op)
      for (int s = 0; s < o.seeds; ++s) pjobs.push_back({f, op, s});
  std::vector<Scored> pres(pjobs.size());
  const auto t_param = std::chrono::steady_clock::now();
  parallel_for(static_cast<int>(pjobs.size()), o.jobs, [&](int i) {
    const Job& j = pjobs[static_cast<std::size_t>(i)];
    const FaultCase& f = pfaults[static_cast<std::size_t>(j.fault)];
    const Params machine = perturbed_machine(machine_seed(j.op, j.seed), o.spread);
    const Inputs u = op_inputs(j.op);
    sim::ThesisScenario sc;
    sc.name = f.label;
    sc.duration = duration;
    sc.initial = sim::InitialCondition::kSteady;
    sc.schedule = {{0.0, u}};
    Params faulty = machine;
    double t_param_fault = 1e300;
    if (f.target == Target::kInput) {
      Inputs uf = u;
      uf.*(f.input) *= f.factor;
      sc.schedule.push_back({o.t_fault, uf});
      sc.logged = {{0.0, u}};
    } else {
      faulty.*(f.param) *= f.factor;
      t_param_fault = o.t_fault;
    }
    const auto log = sim::measure_with_fault(sc, sensors, noise_seed(j.op, j.seed, j.fault), machine, t_param_fault,
                                             faulty);
    Scored s = score_run(monitor_log(log, cfg, o.t_fault), f.row, classes, tie);
    s.visibility = predicted_visibility(f, u, cfg);
    pres[static_cast<std::size_t>(i)] = s;
  });
  const double param_seconds = seconds_since(t_param);

  // --- Sensor faults (on the nominal log of each operating point and seed) -----------
  std::vector<Job> sjobs;
  for (int f = 0; f < static_cast<int>(sfaults.size()); ++f)
    for (int op = 0; op < kOps; ++op)
      for (int s = 0; s < o.seeds; ++s) sjobs.push_back({f, op, s});
  std::vector<sim::ThesisMeasurements> base(static_cast<std::size_t>(kOps * o.seeds));
  const auto t_sensor = std::chrono::steady_clock::now();
  parallel_for(kOps * o.seeds, o.jobs, [&](int i) {
    const int op = i / o.seeds, s = i % o.seeds;
    sim::ThesisScenario sc;
    sc.name = "nominal";
    sc.duration = duration;
    sc.initial = sim::InitialCondition::kSteady;
    sc.schedule = {{0.0, op_inputs(op)}};
    const Params machine = perturbed_machine(machine_seed(op, s), o.spread);
    base[static_cast<std::size_t>(i)] = sim::measure(sc, sensors, noise_seed(op, s, 999), machine);
  });
  std::vector<Scored> sres(sjobs.size());
  parallel_for(static_cast<int>(sjobs.size()), o.jobs, [&](int i) {
    const Job& j = sjobs[static_cast<std::size_t>(i)];
    const FaultCase& f = sfaults[static_cast<std::size_t>(j.fault)];
    auto log = base[static_cast<std::size_t>(j.op * o.seeds + j.seed)];
    sim::SensorFault sf = f.sensor;
    sf.t_start = o.t_fault;
    sim::inject_sensor_fault(log, sensors, sf);
    sres[static_cast<std::size_t>(i)] = score_run(monitor_log(log, cfg, o.t_fault), f.row, classes, tie);
  });
  const double sensor_seconds = seconds_since(t_sensor);

  // --- Nominal long replay -------------------------------------------------------------
  constexpr double kSegment = 100.0;  // [s]
  const int n_seg = static_cast<int>(std::ceil(o.hours * 3600.0 / kSegment - 1e-9));
  std::vector<NominalStats> nres(static_cast<std::size_t>(n_seg));
  const auto t_nominal = std::chrono::steady_clock::now();
  parallel_for(n_seg, o.jobs, [&](int i) {
    const bool ramps = i % 2 == 1;  // every other segment with slow load changes
    const auto sc = nominal_segment(static_cast<std::uint64_t>(50000 + i), kSegment, ramps);
    const Params machine = perturbed_machine(static_cast<std::uint64_t>(90000 + i), o.spread);
    const auto log = sim::measure(sc, sensors, static_cast<std::uint64_t>(300000 + i), machine);
    nres[static_cast<std::size_t>(i)] = monitor_nominal(log, cfg);
  });
  const double nominal_seconds = seconds_since(t_nominal);
  if (const char* dbg = std::getenv("HSTMON_CAMPAIGN_TRACE_SEGMENT")) {  // diagnostic: residual trace of one segment
    const int i = std::atoi(dbg);
    const auto sc = nominal_segment(static_cast<std::uint64_t>(50000 + i), kSegment, i % 2 == 1);
    const Params machine = perturbed_machine(static_cast<std::uint64_t>(90000 + i), o.spread);
    const auto log = sim::measure(sc, sensors, static_cast<std::uint64_t>(300000 + i), machine);
    Mon mon;
    (void)mon.configure(Params{}, cfg, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount);
    (void)mon.reset_steady(log.front().u);
    Mon::Measurement m;
    m.valid = 0xF;
    const double t0 = std::atof(std::getenv("HSTMON_CAMPAIGN_TRACE_T") ? std::getenv("HSTMON_CAMPAIGN_TRACE_T") : "0");
    for (const auto& r : log) {
      for (int c = 0; c < 4; ++c) m.y[c] = r.y[static_cast<std::size_t>(c)];
      mon.step(r.t, r.u, m);
      if (r.t >= t0 - 0.02 && r.t <= t0 + 0.05) {
        const auto& res = mon.observer().residual();
        std::fprintf(stderr, "t %.3f kp/kp0 %.4f  r_w %.2f rpm bound_w %.2f  r_pp %.3f bar bound_pp %.3f alarm 0x%x\n", r.t,
                     r.u.kp / sim::kThesisKpNominal, res[3] * 30 / M_PI, mon.evaluator().bound(3) * 30 / M_PI,
                     res[2] / 1e5, mon.evaluator().bound(2) / 1e5, mon.evaluator().alarm());
      }
    }
  }
  NominalStats nom;
  long nom_ramp_ticks = 0, nom_ramp_det = 0;
  std::map<std::string, int> nom_cands;
  for (int i = 0; i < n_seg; ++i) {
    const auto& s = nres[static_cast<std::size_t>(i)];
    nom.ticks += s.ticks;
    nom.alarm_ticks += s.alarm_ticks;
    nom.detections += s.detections;
    nom.health |= s.health;
    if (i % 2 == 1) {
      nom_ramp_ticks += s.ticks;
      nom_ramp_det += s.detections;
    }
    for (const auto& c : s.first_candidates) ++nom_cands[c];
    for (std::size_t k = 0; k < s.detection_times.size(); ++k) {
      std::fprintf(o.json ? stderr : stdout, "  false alarm: nominal segment %d (%s), t = %.3f s, alarm channels 0x%x\n", i,
                  i % 2 ? "load changes" : "constant", s.detection_times[k], s.alarm_channels[k]);
    }
  }

  if (o.verbose) {
    for (std::size_t i = 0; i < pjobs.size(); ++i)
      print_verbose(pfaults[static_cast<std::size_t>(pjobs[i].fault)].label, kOperatingPoints[pjobs[i].op].name,
                    pjobs[i].seed, pres[i], o.t_fault);
    for (std::size_t i = 0; i < sjobs.size(); ++i)
      print_verbose(sfaults[static_cast<std::size_t>(sjobs[i].fault)].label, kOperatingPoints[sjobs[i].op].name,
                    sjobs[i].seed, sres[i], o.t_fault);
  }

  // --- Aggregation ----------------------------------------------------------------------
  std::map<std::string, Agg> by_label;       // parameter faults per label (fault × magnitude)
  std::vector<std::string> label_order;
  std::map<std::string, Agg> by_class;       // per isolable class of the truth
  std::vector<std::string> class_order;
  Agg vis_hi, vis_lo, design, all_param, kp_blockage;
  for (std::size_t i = 0; i < pjobs.size(); ++i) {
    const FaultCase& f = pfaults[static_cast<std::size_t>(pjobs[i].fault)];
    const Scored& s = pres[i];
    const int t = row_index(f.row);
    const auto& cls = classes[static_cast<std::size_t>(t)];
    const int csize = static_cast<int>(cls.size());
    if (!by_label.count(f.label)) label_order.push_back(f.label);
    by_label[f.label].add(s, f.row, csize, o.t_fault);
    const std::string cn = class_name(cls);
    if (!by_class.count(cn)) class_order.push_back(cn);
    by_class[cn].add(s, f.row, csize, o.t_fault);
    if (by_design(f.row)) {
      design.add(s, f.row, csize, o.t_fault);
    } else {
      all_param.add(s, f.row, csize, o.t_fault);
      (s.visibility >= 1.0 ? vis_hi : vis_lo).add(s, f.row, csize, o.t_fault);
    }
    if (f.row == "kp-" && std::fabs(f.magnitude - 0.5) < 1e-12) kp_blockage.add(s, f.row, csize, o.t_fault);
  }
  std::map<std::string, Agg> by_slabel;
  std::vector<std::string> slabel_order;
  std::map<std::string, Agg> by_skind;
  std::vector<std::string> skind_order;
  Agg sensor_all;
  for (std::size_t i = 0; i < sjobs.size(); ++i) {
    const FaultCase& f = sfaults[static_cast<std::size_t>(sjobs[i].fault)];
    const Scored& s = sres[i];
    const int csize = static_cast<int>(classes[static_cast<std::size_t>(row_index(f.row))].size());
    if (!by_slabel.count(f.label)) slabel_order.push_back(f.label);
    by_slabel[f.label].add(s, f.row, csize, o.t_fault);
    const std::string kind = f.sensor.kind == sim::SensorFaultKind::kStuck
                                 ? "stuck"
                                 : (f.sensor.kind == sim::SensorFaultKind::kBias ? "bias" : "drift");
    if (!by_skind.count(kind)) skind_order.push_back(kind);
    by_skind[kind].add(s, f.row, csize, o.t_fault);
    sensor_all.add(s, f.row, csize, o.t_fault);
  }
  // Isolation over every detected fault run (parameter incl. J/K, and sensor).
  Agg overall;
  for (std::size_t i = 0; i < pjobs.size(); ++i) {
    const FaultCase& f = pfaults[static_cast<std::size_t>(pjobs[i].fault)];
    overall.add(pres[i], f.row, static_cast<int>(classes[static_cast<std::size_t>(row_index(f.row))].size()), o.t_fault);
  }
  for (std::size_t i = 0; i < sjobs.size(); ++i) {
    const FaultCase& f = sfaults[static_cast<std::size_t>(sjobs[i].fault)];
    overall.add(sres[i], f.row, static_cast<int>(classes[static_cast<std::size_t>(row_index(f.row))].size()), o.t_fault);
  }
  int false_in_fault_runs = overall.false_events;

  const bool t_false = nom.detections == 0 && false_in_fault_runs == 0;
  const double in_set_pct = Agg::pct(overall.in_set, overall.detected);
  const bool t_iso = in_set_pct >= 95.0;
  const double kp_worst = kp_blockage.worst_ms();
  const bool t_kp = kp_blockage.detected == kp_blockage.runs && kp_worst <= 50.0;
  const double total_seconds = seconds_since(t_start);

  if (o.json) {
    std::printf("{\"type\":\"fault_campaign\",\"seeds\":%d,\"operating_points\":3,\"t_fault\":%g,\"after\":%g,"
                "\"spread\":%g,\"jobs\":%d,\n",
                o.seeds, o.t_fault, o.after, o.spread, o.jobs);
    std::printf("\"parameter_faults\":[\n");
    for (std::size_t k = 0; k < label_order.size(); ++k)
      json_agg("fault", label_order[k], by_label[label_order[k]], k + 1 == label_order.size());
    std::printf("],\n\"classes\":[\n");
    for (std::size_t k = 0; k < class_order.size(); ++k)
      json_agg("class", class_order[k], by_class[class_order[k]], k + 1 == class_order.size());
    std::printf("],\n\"sensor_faults\":[\n");
    for (std::size_t k = 0; k < slabel_order.size(); ++k)
      json_agg("fault", slabel_order[k], by_slabel[slabel_order[k]], k + 1 == slabel_order.size());
    std::printf("],\n\"summary\":[\n");
    json_agg("group", "parameter faults, steady effect above threshold", vis_hi, false);
    json_agg("group", "parameter faults, steady effect below threshold", vis_lo, false);
    json_agg("group", "J/K: not observable by design", design, false);
    json_agg("group", "sensor faults", sensor_all, false);
    json_agg("group", "kp- 50% (PRV blockage)", kp_blockage, false);
    json_agg("group", "all fault runs", overall, true);
    std::printf("],\n\"nominal\":{\"hours\":%g,\"segments\":%d,\"ticks\":%ld,\"load_change_ticks\":%ld,"
                "\"alarm_ticks\":%ld,\"false_alarms\":%ld,\"false_alarms_load_changes\":%ld,\"health\":%u},\n",
                static_cast<double>(nom.ticks) / 3.6e6, n_seg, nom.ticks, nom_ramp_ticks, nom.alarm_ticks,
                nom.detections, nom_ramp_det, nom.health);
    std::printf("\"targets\":{\"zero_false_alarms\":%s,\"false_events_in_fault_runs\":%d,\"truth_in_set_pct\":%.2f,"
                "\"truth_in_set_met\":%s,\"blockage_worst_delay_ms\":%s,\"blockage_met\":%s},\n",
                t_false ? "true" : "false", false_in_fault_runs, in_set_pct, t_iso ? "true" : "false",
                fmt_ms(kp_worst).c_str(), t_kp ? "true" : "false");
    std::printf("\"runtime_s\":{\"parameter\":%.1f,\"sensor\":%.1f,\"nominal\":%.1f,\"total\":%.1f}}\n", param_seconds,
                sensor_seconds, nominal_seconds, total_seconds);
    return 0;
  }

  std::printf("hstmon fault campaign: Monitor<double>, generated thesis table (%d rows), thesis_fast_sensors(1 kHz)\n",
              hstmon::kThesisSignatureCount);
  std::printf("  %d seeds × 3 operating points (light kp×1.6, nominal, heavy kp×0.65); fault at t = %.1f s, "
              "%.1f s after;\n  machine parameters off by uniform ±%.0f %% per run (monitor: Table 2.2); tie margin "
              "%.3f rad\n\n",
              o.seeds, o.t_fault, o.after, o.spread * 100, tie);
  std::printf("visibility = largest steady-state change / detection threshold (model bound + 2σ), nominal machine;\n"
              "det%% over runs; delays from the fault; iso = first isolated/ambiguous/unexplained decision;\n"
              "inSet/first/class%% over detected runs (class%%: truth in the set and the set inside the truth's "
              "isolable class);\nset/class = mean reported set size / mean isolable class size; unex = unexplained\n\n");
  std::printf("Parameter faults (each row: 3 operating points × %d seeds)\n", o.seeds);
  print_header("fault");
  for (const auto& l : label_order) print_row(l.c_str(), by_label[l], true);
  std::printf("\nPer isolable class of the table (truth's class; classes with identical signature and direction "
              "within the tie margin)\n");
  print_header("class");
  for (const auto& c : class_order) print_row(c.c_str(), by_class[c], true);
  std::printf("\nSensor faults (bias/drift in %% of the transmitter's full scale)\n");
  print_header("fault");
  for (const auto& l : slabel_order) print_row(l.c_str(), by_slabel[l], false);
  for (const auto& k : skind_order) print_row(("all " + k).c_str(), by_skind[k], false);
  std::printf("\nSummary\n");
  print_header("group");
  print_row("param, ss ≥ thr", vis_hi, true);
  print_row("param, ss < thr", vis_lo, true);
  print_row("param, all (no J/K)", all_param, true);
  print_row("J±, K± (by design)", design, true);
  print_row("sensor faults", sensor_all, false);
  print_row("kp- 50% blockage", kp_blockage, true);
  print_row("all fault runs", overall, false);
  std::printf("\nNominal replay: %.2f h at 1 kHz (%d segments of %.0f s, each a machine off by ±%.0f %%; half at a "
              "constant operating point,\n  half with slow load changes: kp ramps in [0.65, 1.6]·kp0 every 10 s): "
              "%ld ticks, %ld alarm ticks, %ld false alarms (%ld in load-change segments), health 0x%x\n",
              static_cast<double>(nom.ticks) / 3.6e6, n_seg, kSegment, o.spread * 100, nom.ticks, nom.alarm_ticks,
              nom.detections, nom_ramp_det, nom.health);
  if (!nom_cands.empty()) {
    std::printf("  false alarms decided as:");
    for (const auto& [k, n] : nom_cands) std::printf(" %s×%d", k.c_str(), n);
    std::printf("\n");
  }
  std::printf("\nTargets\n");
  std::printf("  0 false alarms (10 h nominal + before-fault parts of fault runs): %s (%ld nominal, %d in fault runs)\n",
              t_false ? "MET" : "MISSED", nom.detections, false_in_fault_runs);
  std::printf("  truth in the reported set ≥ 95 %% of detected fault runs: %s (%.1f %%, %d of %d)\n",
              t_iso ? "MET" : "MISSED", in_set_pct, overall.in_set, overall.detected);
  std::printf("  50 %% PRV blockage detected within 50 ms: %s (%d of %d detected, worst %s ms, median %s ms)\n",
              t_kp ? "MET" : "MISSED", kp_blockage.detected, kp_blockage.runs, fmt_ms(kp_worst).c_str(),
              fmt_ms(kp_blockage.med_ms()).c_str());
  std::printf("\nRuntime: parameter faults %.1f s (%zu runs), sensor faults %.1f s (%zu runs), nominal %.1f s; "
              "total %.1f s on %d thread(s)\n",
              param_seconds, pjobs.size(), sensor_seconds, sjobs.size(), nominal_seconds, total_seconds, o.jobs);
  return 0;
}
