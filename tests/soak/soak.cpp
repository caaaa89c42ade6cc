// Soak driver (issues 7 and 12, scripts/soak.sh, docs/hardening.md): a simulated long run
// at 1 kHz through Monitor<float> and/or Monitor<double>, both fed the same rows.
//
// The machine is the stiff reference simulator (equations 2.5–2.8, host_sim's measure()),
// so start-ups and load steps are physically right: a ±2 % mismatched machine (the monitor
// keeps Table 2.2) run in 30-minute cycles. Each cycle begins at rest with the logger
// running, the supply steps on after 5 s, and is switched off 60 s before the cycle ends
// (the machine coasts to rest). The load: PRV steps every 4 s in [0.65, 1.6]·kp0 in every
// other cycle, a triangle ramp (300 s legs) or a sinusoid (600 s) in the others. Sensors:
// rig_fast (no lag unless --lag, σ 0.04 bar / 0.5 rpm, ADC 0.01 bar). Each cycle is
// generated and replayed in turn (a day of rows is never held in memory).
//
// Reports: ticks, start-ups, load changes, residual mean per channel and hour, alarm
// ticks and episodes (must be 0), sensor-flag ticks, non-finite residuals/estimates (0),
// max RK4 substeps, generator and monitor time, and with --slice the callgrind
// instruction count of one ordinary tick and of the first tick after a load change.
//
//   hstmon_soak [--hours H] [--type float|double|both] [--seed N] [--lag MS] [--slice]
#include <array>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "../support/thesis_inputs_as.hpp"
#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/monitor.hpp"
#include "hstmon_sim/machine_error.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/rig_run.hpp"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define HSTMON_HAVE_CALLGRIND 1
#endif
#endif
#ifndef HSTMON_HAVE_CALLGRIND
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_TOGGLE_COLLECT
#define CALLGRIND_DUMP_STATS_AT(x)
#endif

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRate = 1000.0;            // [Hz]
constexpr double kTick = 1.0 / kRate;       // [s]
constexpr double kCycle = 1800.0;           // start/stop cycle [s]
constexpr double kSupplyOn = 5.0;           // [s] into a cycle
constexpr double kOffBeforeEnd = 60.0;      // [s]

namespace sim = hstmon::sim;
using ModelD = hstmon::ThesisReducedModel<double>;

/// Cycle i of the day: from rest, supply on at 5 s, off 60 s before the end; load steps
/// in even cycles, ramps and sinusoids in the odd ones.
sim::ThesisScenario cycle_scenario(int i, double duration, unsigned seed) {
  sim::RigRun r;
  r.duration = duration;
  r.from_rest = true;
  r.supply_on = std::fmin(kSupplyOn, 0.5 * duration);
  if (duration > kSupplyOn + kOffBeforeEnd) {
    r.run_time = duration - kOffBeforeEnd - r.supply_on;
    r.stop_time = kOffBeforeEnd + 1.0;
  }
  r.load.seed = 1000u * seed + static_cast<unsigned>(i);
  r.load.level = 1.0;
  r.load.update = 0.1;
  if (i % 2 == 0) {
    r.load.shape = sim::LoadShape::kSteps;
    r.load.period = 4.0;
  } else if (i % 4 == 1) {
    r.load.shape = sim::LoadShape::kRamp;
    r.load.period = 300.0;
  } else {
    r.load.shape = sim::LoadShape::kSine;
    r.load.period = 600.0;
  }
  return sim::thesis_rig_run(r);
}

struct Stats {
  std::uint64_t ticks = 0, alarm_ticks = 0, episodes = 0, nonfinite = 0, sensor_flags = 0;
  std::uint32_t health = 0;
  int max_substeps = 0;
  std::vector<std::array<double, 4>> hour_sum;
  std::vector<std::uint64_t> hour_n;
  std::vector<std::string> first_events;
  double monitor_s = 0;
};

template <typename T>
using Mon = hstmon::Monitor<T>;

template <typename T>
__attribute__((noinline)) void tick(Mon<T>& mon, T t, const hstmon::ThesisInputs<T>& u,
                                    const typename Mon<T>::Measurement& m) {
  mon.step(t, u, m);
}

/// One monitor of the soak, fed row by row.
template <typename T>
struct Soaked {
  Mon<T> mon;
  Stats st;
  bool started = false;
  double t_base = 0;  // the matcher's time, rebased every 1000 s while nominal (float resolves t·6e-8 s)

  explicit Soaked(double hours) {
    typename Mon<T>::Config cfg;
    cfg.observer.tick = static_cast<T>(kTick);
    if (mon.configure(hstmon::ThesisParams<T>{}, cfg, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount) !=
        hstmon::Status::kOk) {
      std::fprintf(stderr, "configure failed\n");
      std::exit(2);
    }
    st.hour_sum.assign(static_cast<std::size_t>(hours) + 1, {0, 0, 0, 0});
    st.hour_n.assign(st.hour_sum.size(), 0);
  }

  void feed(double t, const sim::Measurement<hstmon::ThesisInputs<double>>& row) {
    typename Mon<T>::Measurement m;
    m.valid = 0x0F;
    for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(row.y[static_cast<std::size_t>(i)]);
    const hstmon::ThesisInputs<T> u = hstmon_test::thesis_inputs_as<T>(row.u);
    const auto c0 = std::chrono::steady_clock::now();
    if (!started) {  // the monitor starts from the first sample, as replay does
      if (mon.reset_measured(u, m) != hstmon::Status::kOk) {
        std::fprintf(stderr, "reset_measured failed\n");
        std::exit(2);
      }
      started = true;
    }
    if (t - t_base >= 1000.0 && mon.matcher().status() == hstmon::MatchStatus::kNominal) t_base = t;
    tick<T>(mon, static_cast<T>(t - t_base), u, m);
    st.monitor_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    const auto& obs = mon.observer();
    st.health |= mon.health();
    if (obs.substeps() > st.max_substeps) st.max_substeps = obs.substeps();
    if (mon.evaluator().alarm() != 0) ++st.alarm_ticks;
    if (mon.sensors().mask() != 0) ++st.sensor_flags;
    const auto& r = obs.residual();
    const auto& e = obs.estimate();
    bool fin = true;
    for (int i = 0; i < 4; ++i) fin = fin && std::isfinite(r[i]) && std::isfinite(e[i]);
    if (!fin) ++st.nonfinite;
    const auto h = std::min(static_cast<std::size_t>(t / 3600.0), st.hour_n.size() - 1);
    for (int i = 0; i < 4; ++i) st.hour_sum[h][static_cast<std::size_t>(i)] += static_cast<double>(r[i]);
    ++st.hour_n[h];
    typename Mon<T>::Event ev;
    while (mon.pop_event(ev)) {
      if (ev.kind == hstmon::MatchEventKind::kDetected) ++st.episodes;
      if (st.first_events.size() < 10) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "t=%.3f s %s %s", t, hstmon::to_string(ev.kind),
                      ev.count > 0 ? ev.candidate[0].name : "");
        st.first_events.emplace_back(buf);
      }
    }
    ++st.ticks;
  }
};

void print(const char* type, double hours, const Stats& st) {
  std::printf("== Monitor<%s>: %.3g h simulated at 1 kHz\n", type, hours);
  std::printf("ticks             %" PRIu64 "\n", st.ticks);
  std::printf("monitor time      %.1f s (%.3f us/tick)\n", st.monitor_s, st.monitor_s * 1e6 / static_cast<double>(st.ticks));
  std::printf("alarm ticks       %" PRIu64 "\n", st.alarm_ticks);
  std::printf("episodes          %" PRIu64 "\n", st.episodes);
  std::printf("sensor-flag ticks %" PRIu64 "\n", st.sensor_flags);
  std::printf("non-finite ticks  %" PRIu64 "\n", st.nonfinite);
  std::printf("health (OR)       0x%x\n", st.health);
  std::printf("max substeps      %d\n", st.max_substeps);
  for (const auto& e : st.first_events) std::printf("event             %s\n", e.c_str());
  std::printf("mean residual per hour [bar, bar, bar, rpm] (start-ups and load changes included):\n");
  for (std::size_t h = 0; h < st.hour_n.size(); ++h) {
    if (st.hour_n[h] == 0) continue;
    const double n = static_cast<double>(st.hour_n[h]);
    std::printf("  hour %3zu  %9.5f %9.5f %9.5f %9.4f%s\n", h + 1, st.hour_sum[h][0] / n / 1e5, st.hour_sum[h][1] / n / 1e5,
                st.hour_sum[h][2] / n / 1e5, st.hour_sum[h][3] / n * 30 / kPi,
                st.hour_n[h] < 3600000 ? "  (partial)" : "");
  }
}

/// The day: cycles generated by the stiff reference and fed to the monitors in turn.
void soak(double hours, unsigned seed, double lag, bool run_float, bool run_double, int& bad) {
  const hstmon::ThesisParams<double> machine = sim::perturbed_params(seed, 0.02);
  const sim::SensorConfig sensors = sim::with_lag(sim::rig_fast_sensors(kRate), lag);
  std::unique_ptr<Soaked<float>> f = run_float ? std::make_unique<Soaked<float>>(hours) : nullptr;
  std::unique_ptr<Soaked<double>> d = run_double ? std::make_unique<Soaked<double>>(hours) : nullptr;
  const double total = hours * 3600.0;
  double gen_s = 0, t0 = 0;
  long startups = 0, load_changes = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  for (int i = 0; t0 < total - 1e-9; ++i) {
    const double len = std::fmin(kCycle, total - t0);
    const auto g0 = std::chrono::steady_clock::now();
    const sim::ThesisScenario sc = cycle_scenario(i, len, seed);
    const sim::ThesisMeasurements rows = sim::measure(sc, sensors, 100000u * seed + static_cast<unsigned>(i), machine);
    gen_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - g0).count();
    for (std::size_t k = 1; k < sc.schedule.size(); ++k) {
      const auto& a = sc.schedule[k - 1].u;
      const auto& b = sc.schedule[k].u;
      startups += a.Psupl == 0.0 && b.Psupl > 0.0;
      load_changes += a.kp != b.kp;
    }
    startups += sc.schedule.front().u.Psupl > 0.0;
    // The last row of a cycle is the first of the next (both at rest): skip it.
    const std::size_t n = (t0 + len < total - 1e-9) ? rows.size() - 1 : rows.size();
    for (std::size_t k = 0; k < n; ++k) {
      const double t = t0 + rows[k].t;
      if (f) f->feed(t, rows[k]);
      if (d) d->feed(t, rows[k]);
    }
    t0 += len;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::printf("== soak: %.3g h, seed %u, machine ±2 %%, rig_fast sensors, lag %.3g ms: %ld start-ups (from rest, "
              "logger running), %ld load changes\n",
              hours, seed, lag * 1e3, startups, load_changes);
  std::printf("wall time         %.1f s (generator, stiff reference + sensor chain: %.1f s)\n", wall, gen_s);
  if (f) {
    print("float", hours, f->st);
    bad += f->st.episodes != 0 || f->st.alarm_ticks != 0 || f->st.nonfinite != 0;
  }
  if (d) {
    print("double", hours, d->st);
    bad += d->st.episodes != 0 || d->st.alarm_ticks != 0 || d->st.nonfinite != 0;
  }
}

/// Fast steady-state generator, only for the callgrind slice (an ordinary tick and a
/// load-change tick at the operating point; its physics is not what is measured there).
struct Generator {
  ModelD model{sim::perturbed_params(1, 0.02)};
  ModelD::Output y_ss;
  hstmon::ThesisInputs<double> u{};
  Generator() {
    model.set_inputs(u);
    ModelD::State x;
    if (model.steady_state(x)) y_ss = model.outputs(x);
  }
  void advance(double meas[4]) {
    for (int i = 0; i < 4; ++i) meas[i] = y_ss[i];
  }
};

/// Callgrind slice: warm up, then collect one ordinary tick, then the first tick after
/// a load change (kp setpoint step: the model bound is recomputed).
template <typename T>
void slice() {
  Generator gen;
  Mon<T> mon;
  typename Mon<T>::Config cfg;
  cfg.observer.tick = static_cast<T>(kTick);
  (void)mon.configure(hstmon::ThesisParams<T>{}, cfg, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount);
  hstmon::ThesisInputs<T> u;
  u.kp = static_cast<T>(gen.u.kp);
  (void)mon.reset_steady(u);
  typename Mon<T>::Measurement m;
  m.valid = 0x0F;
  double y[4];
  // The generator's next sample into m.
  const auto sample = [&] {
    gen.advance(y);
    for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(y[i]);
  };
  // Tick k with only the tick itself collected (not the sample's generation).
  const auto collected_tick = [&](int k) {
    CALLGRIND_TOGGLE_COLLECT;
    tick<T>(mon, static_cast<T>(k * kTick), u, m);
    CALLGRIND_TOGGLE_COLLECT;
  };
  for (int k = 0; k < 2000; ++k) {
    sample();
    tick<T>(mon, static_cast<T>(k * kTick), u, m);
  }
  sample();
  collected_tick(2000);
  CALLGRIND_DUMP_STATS_AT("ordinary tick");
  u.kp = static_cast<T>(u.kp * T(1.001));  // a 0.1 % setpoint change: bound recomputed
  sample();
  collected_tick(2001);
  CALLGRIND_DUMP_STATS_AT("load-change tick");
  std::printf("slice done (Monitor<%s>)\n", sizeof(T) == 4 ? "float" : "double");
}

}  // namespace

int main(int argc, char** argv) {
  double hours = 24;
  std::string type = "both";
  unsigned seed = 1;
  double lag_ms = 0;
  bool do_slice = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--hours" && i + 1 < argc) hours = std::atof(argv[++i]);
    else if (a == "--type" && i + 1 < argc) type = argv[++i];
    else if (a == "--seed" && i + 1 < argc) seed = static_cast<unsigned>(std::atoi(argv[++i]));
    else if (a == "--lag" && i + 1 < argc) lag_ms = std::atof(argv[++i]);
    else if (a == "--slice") do_slice = true;
    else {
      std::fprintf(stderr, "usage: hstmon_soak [--hours H] [--type float|double|both] [--seed N] [--lag MS] [--slice]\n");
      return 1;
    }
  }
  if (do_slice) {
    if (type != "double") slice<float>();
    if (type != "float") slice<double>();
    return 0;
  }
  if (!(hours > 0)) return 1;
  int bad = 0;
  soak(hours, seed, lag_ms * 1e-3, type != "double", type != "float", bad);
  return bad ? 3 : 0;
}
