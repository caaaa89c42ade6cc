// Soak driver (issue 7, scripts/soak.sh, docs/hardening.md): a simulated long run at
// 1 kHz through Monitor<float> and/or Monitor<double>.
//
// The "machine" is a fast generator, NOT the stiff reference simulator: the thesis
// model's steady state for the machine's own parameters (±2 % off the monitor's — the
// mismatch the thresholds are sized for), followed by a first-order lag (τ = 20 ms),
// plus white sensor noise (σ 0.05 bar on pressures, 0.5 rpm on speed). The load changes
// slowly: the PRV setting kp follows a 40-minute sinusoid (±20 %) plus a ramp of +15 %
// over 20 minutes and back in every 3 hours; the controller sends it as a setpoint at 10 Hz,
// and the logged kp is what the monitor gets as its input. The generator's steady state is
// solved at each setpoint change.
//
// Reports: ticks, residual mean per channel and hour (first vs last hour = drift),
// alarm ticks and episodes (must be 0), non-finite residuals/estimates (0), max RK4
// substeps, tick time (max, and ticks over 50 µs) and with --slice the callgrind
// instruction count of one ordinary tick and of the first tick after a load change.
//
//   hstmon_soak [--hours H] [--type float|double|both] [--seed N] [--slice]
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/monitor.hpp"

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
constexpr double kSigmaP = 5e3;             // [Pa]
constexpr double kSigmaW = 0.5 * kPi / 30;  // [rad/s]
constexpr double kTau = 0.02;               // generator lag [s]
constexpr int kSetpointTicks = 100;         // kp setpoint every 100 ms

using ModelD = hstmon::ThesisReducedModel<double>;

hstmon::ThesisParams<double> machine_params() {
  hstmon::ThesisParams<double> p;  // Table 2.2, then ±2 % (alternating signs)
  p.Dm *= 1.02;
  p.Dp *= 0.98;
  p.Rlkg *= 1.02;
  p.Ripl *= 0.98;
  p.Rf *= 1.02;
  p.Rbl *= 0.98;
  p.kf *= 1.02;
  return p;
}

double kp_at(double t) {  // PRV setting [m³/(s·√Pa)]
  const double kp0 = hstmon::ThesisInputs<double>{}.kp;
  double f = 1.0 + 0.2 * std::sin(2 * kPi * t / 2400.0);
  const double tc = std::fmod(t, 10800.0);  // every 3 h: 20 min ramp up 15 %, 20 min down
  if (tc >= 5400.0 && tc < 6600.0) f += 0.15 * (tc - 5400.0) / 1200.0;
  if (tc >= 6600.0 && tc < 7800.0) f += 0.15 * (7800.0 - tc) / 1200.0;
  return kp0 * f;
}

/// The machine: steady state of its own parameters, first-order lag, noise.
struct Generator {
  ModelD model{machine_params()};
  ModelD::Output y_ss, y;
  std::mt19937_64 rng;
  std::normal_distribution<double> n{0.0, 1.0};
  hstmon::ThesisInputs<double> u{};
  bool ok = true;

  explicit Generator(unsigned seed) : rng(seed) {
    set_kp(kp_at(0.0));
    y = y_ss;
  }
  void set_kp(double kp) {
    u.kp = kp;
    model.set_inputs(u);
    ModelD::State x;
    if (model.steady_state(x)) {
      y_ss = model.outputs(x);
    } else {
      ok = false;
    }
  }
  void advance(double meas[4]) {
    const double a = kTick / kTau;
    for (int i = 0; i < 4; ++i) {
      y[i] += (y_ss[i] - y[i]) * a;
      meas[i] = y[i] + (i == 3 ? kSigmaW : kSigmaP) * n(rng);
    }
  }
};

struct Stats {
  std::uint64_t ticks = 0, alarm_ticks = 0, episodes = 0, nonfinite = 0, sensor_flags = 0;
  std::uint64_t slow_ticks = 0;  // over 50 µs
  std::uint32_t health = 0;
  int max_substeps = 0;
  double max_tick_us = 0;
  std::vector<std::array<double, 4>> hour_sum;
  std::vector<std::uint64_t> hour_n;
  std::vector<std::string> first_events;
  double wall_s = 0;
};

template <typename T>
using Mon = hstmon::Monitor<T>;

template <typename T>
__attribute__((noinline)) void tick(Mon<T>& mon, T t, const hstmon::ThesisInputs<T>& u,
                                    const typename Mon<T>::Measurement& m) {
  mon.step(t, u, m);
}

template <typename T>
Stats soak(double hours, unsigned seed) {
  Stats st;
  Generator gen(seed);
  Mon<T> mon;
  typename Mon<T>::Config cfg;
  cfg.observer.tick = static_cast<T>(kTick);
  if (mon.configure(hstmon::ThesisParams<T>{}, cfg, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount) !=
      hstmon::Status::kOk) {
    std::fprintf(stderr, "configure failed\n");
    std::exit(2);
  }
  auto to_t = [](const hstmon::ThesisInputs<double>& d) {
    hstmon::ThesisInputs<T> u;
    u.Psupl = static_cast<T>(d.Psupl);
    u.Ps = static_cast<T>(d.Ps);
    u.Pbp = static_cast<T>(d.Pbp);
    u.kp = static_cast<T>(d.kp);
    return u;
  };
  hstmon::ThesisInputs<T> u = to_t(gen.u);
  if (mon.reset_steady(u) != hstmon::Status::kOk) {
    std::fprintf(stderr, "reset_steady failed\n");
    std::exit(2);
  }
  const auto n_ticks = static_cast<std::uint64_t>(std::llround(hours * 3600.0 * kRate));
  const std::uint64_t per_hour = static_cast<std::uint64_t>(3600.0 * kRate);
  st.hour_sum.assign(static_cast<std::size_t>(n_ticks / per_hour + 1), {0, 0, 0, 0});
  st.hour_n.assign(st.hour_sum.size(), 0);
  // The matcher's time: rebased every 1000 s while nominal (float resolves t·6e-8 s).
  double t_base = 0;
  typename Mon<T>::Measurement m;
  m.valid = 0x0F;
  typename Mon<T>::Event ev;
  const auto wall0 = std::chrono::steady_clock::now();
  for (std::uint64_t k = 0; k < n_ticks; ++k) {
    const double t = static_cast<double>(k) * kTick;
    if (k % kSetpointTicks == 0 && k > 0) {
      gen.set_kp(kp_at(t));
      u = to_t(gen.u);
    }
    double y[4];
    gen.advance(y);
    for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(y[i]);
    if (t - t_base >= 1000.0 && mon.matcher().status() == hstmon::MatchStatus::kNominal) t_base = t;
    const auto c0 = std::chrono::steady_clock::now();
    tick<T>(mon, static_cast<T>(t - t_base), u, m);
    const auto c1 = std::chrono::steady_clock::now();
    const double us = std::chrono::duration<double, std::micro>(c1 - c0).count();
    if (us > st.max_tick_us) st.max_tick_us = us;
    if (us > 50.0) ++st.slow_ticks;

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
    const std::size_t h = static_cast<std::size_t>(k / per_hour);
    for (int i = 0; i < 4; ++i) st.hour_sum[h][static_cast<std::size_t>(i)] += static_cast<double>(r[i]);
    ++st.hour_n[h];
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
  st.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (!gen.ok) std::fprintf(stderr, "warning: the generator lost its steady state once\n");
  return st;
}

void print(const char* type, double hours, const Stats& st) {
  std::printf("== Monitor<%s>: %.3g h simulated at 1 kHz\n", type, hours);
  std::printf("ticks             %" PRIu64 "\n", st.ticks);
  std::printf("wall time         %.1f s (%.3f us/tick incl. generator)\n", st.wall_s, st.wall_s * 1e6 / static_cast<double>(st.ticks));
  std::printf("alarm ticks       %" PRIu64 "\n", st.alarm_ticks);
  std::printf("episodes          %" PRIu64 "\n", st.episodes);
  std::printf("sensor-flag ticks %" PRIu64 "\n", st.sensor_flags);
  std::printf("non-finite ticks  %" PRIu64 "\n", st.nonfinite);
  std::printf("health (OR)       0x%x\n", st.health);
  std::printf("max substeps      %d\n", st.max_substeps);
  std::printf("max tick time     %.1f us (ticks over 50 us: %" PRIu64 ")\n", st.max_tick_us, st.slow_ticks);
  for (const auto& e : st.first_events) std::printf("event             %s\n", e.c_str());
  std::printf("mean residual per hour [bar, bar, bar, rpm]:\n");
  for (std::size_t h = 0; h < st.hour_n.size(); ++h) {
    if (st.hour_n[h] == 0) continue;
    const double n = static_cast<double>(st.hour_n[h]);
    std::printf("  hour %3zu  %9.5f %9.5f %9.5f %9.4f%s\n", h + 1, st.hour_sum[h][0] / n / 1e5, st.hour_sum[h][1] / n / 1e5,
                st.hour_sum[h][2] / n / 1e5, st.hour_sum[h][3] / n * 30 / kPi,
                st.hour_n[h] < 3600000 ? "  (partial)" : "");
  }
}

/// Callgrind slice: warm up, then collect one ordinary tick, then the first tick after
/// a load change (kp setpoint step: the model bound is recomputed).
template <typename T>
void slice() {
  Generator gen(1);
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
  for (int k = 0; k < 2000; ++k) {
    gen.advance(y);
    for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(y[i]);
    tick<T>(mon, static_cast<T>(k * kTick), u, m);
  }
  gen.advance(y);
  for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(y[i]);
  CALLGRIND_TOGGLE_COLLECT;
  tick<T>(mon, static_cast<T>(2000 * kTick), u, m);
  CALLGRIND_TOGGLE_COLLECT;
  CALLGRIND_DUMP_STATS_AT("ordinary tick");
  u.kp = static_cast<T>(u.kp * T(1.001));  // a 0.1 % setpoint change: bound recomputed
  gen.advance(y);
  for (int i = 0; i < 4; ++i) m.y[i] = static_cast<T>(y[i]);
  CALLGRIND_TOGGLE_COLLECT;
  tick<T>(mon, static_cast<T>(2001 * kTick), u, m);
  CALLGRIND_TOGGLE_COLLECT;
  CALLGRIND_DUMP_STATS_AT("load-change tick");
  std::printf("slice done (Monitor<%s>)\n", sizeof(T) == 4 ? "float" : "double");
}

}  // namespace

int main(int argc, char** argv) {
  double hours = 24;
  std::string type = "both";
  unsigned seed = 1;
  bool do_slice = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--hours" && i + 1 < argc) hours = std::atof(argv[++i]);
    else if (a == "--type" && i + 1 < argc) type = argv[++i];
    else if (a == "--seed" && i + 1 < argc) seed = static_cast<unsigned>(std::atoi(argv[++i]));
    else if (a == "--slice") do_slice = true;
    else {
      std::fprintf(stderr, "usage: hstmon_soak [--hours H] [--type float|double|both] [--seed N] [--slice]\n");
      return 1;
    }
  }
  if (do_slice) {
    if (type != "double") slice<float>();
    if (type != "float") slice<double>();
    return 0;
  }
  int bad = 0;
  if (type != "double") {
    const Stats s = soak<float>(hours, seed);
    print("float", hours, s);
    bad += s.episodes != 0 || s.alarm_ticks != 0 || s.nonfinite != 0;
  }
  if (type != "float") {
    const Stats s = soak<double>(hours, seed);
    print("double", hours, s);
    bad += s.episodes != 0 || s.alarm_ticks != 0 || s.nonfinite != 0;
  }
  return bad ? 3 : 0;
}
