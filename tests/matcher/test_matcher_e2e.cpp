// End to end: host_sim log → Observer → SensorCheck + ResidualEvaluator (±2 % parameter
// bound) → FaultMatcher on the hand-made table.
//  - Nominal logs (fast sensors: σ = 0.05 bar / 0.5 rpm, 1 ms / 10 ms lags, 16-bit ADC)
//    from machines whose parameters are off by ±2 %: no alarm, no event.
//  - The thesis PRV blockage (kp halved at t = 80 s, the log records nominal kp): detected
//    within 50 ms at 1 kHz and isolated to a set containing kp−.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../support/thesis_inputs_as.hpp"
#include "hstmon/hstmon.hpp"
#include "hstmon_sim/measure.hpp"
#include "test_table.hpp"

namespace {

using hstmon::MatchEventKind;

struct RunResult {
  std::vector<hstmon::MatchEvent<double>> events;
  long alarm_ticks = 0;
  double first_alarm = -1;
};

template <typename T>
RunResult run(const hstmon::sim::ThesisMeasurements& log, const hstmon::sim::SensorConfig& sensors) {
  using Model = hstmon::ThesisReducedModel<T>;
  const T tick = static_cast<T>(sensors.sample_period);
  hstmon::Observer<Model> obs;
  typename hstmon::Observer<Model>::Config oc;
  oc.tick = tick;
  EXPECT_EQ(obs.configure(Model{}, oc), hstmon::Status::kOk);
  EXPECT_EQ(obs.reset_steady(hstmon_test::thesis_inputs_as<T>(log.front().u)), hstmon::Status::kOk);

  hstmon::ResidualEvaluator<T> ev;
  typename hstmon::ResidualEvaluator<T>::Config ec;
  for (int i = 0; i < 4; ++i) ec.noise_sigma[i] = static_cast<T>(sensors.channels[static_cast<std::size_t>(i)].noise_std);
  EXPECT_EQ(ev.configure(ec), hstmon::Status::kOk);
  T bound[4];
  EXPECT_EQ(hstmon::thesis_model_bound(obs.model(), hstmon::ThesisUncertainty<T>{}, bound), hstmon::Status::kOk);
  EXPECT_EQ(ev.set_model_bound(bound), hstmon::Status::kOk);

  hstmon::SensorCheck<T> sc;
  typename hstmon::SensorCheck<T>::Config scc;
  for (int i = 0; i < 4; ++i) {
    scc.range_lo[i] = static_cast<T>(sensors.channels[static_cast<std::size_t>(i)].range_lo);
    scc.range_hi[i] = static_cast<T>(sensors.channels[static_cast<std::size_t>(i)].range_hi);
  }
  EXPECT_EQ(sc.configure(scc), hstmon::Status::kOk);

  hstmon::FaultMatcher<T> m;
  EXPECT_EQ(m.configure(hstmon_test::kTestTable, hstmon_test::kTestTableCount, {}), hstmon::Status::kOk);

  RunResult res;
  typename hstmon::Observer<Model>::Measurement meas;
  meas.valid = 0xF;
  T y[4];
  for (const auto& s : log) {
    for (int i = 0; i < 4; ++i) y[i] = meas.y[i] = static_cast<T>(s.y[static_cast<std::size_t>(i)]);
    obs.step(hstmon_test::thesis_inputs_as<T>(s.u), meas);
    ev.update(obs.residual().data(), obs.residual_valid());
    if (ev.alarm() != 0) {
      ++res.alarm_ticks;
      if (res.first_alarm < 0) res.first_alarm = s.t;
    }
    m.update(static_cast<T>(s.t), ev, sc.update(static_cast<T>(s.t), y, 0xF));
    typename hstmon::FaultMatcher<T>::Event e;
    while (m.pop_event(e)) {
      hstmon::MatchEvent<double> d;
      d.kind = e.kind;
      d.time = static_cast<double>(e.time);
      d.count = e.count;
      d.consistent = e.consistent;
      for (int j = 0; j < e.count; ++j) {
        d.candidate[j].index = e.candidate[j].index;
        d.candidate[j].name = e.candidate[j].name;
        d.candidate[j].score = static_cast<double>(e.candidate[j].score);
      }
      res.events.push_back(d);
    }
  }
  return res;
}

void print_events(const RunResult& r) {
  for (const auto& e : r.events) {
    std::printf("  {\"t\":%.3f, \"event\":\"%s\", \"candidates\":[", e.time, hstmon::to_string(e.kind));
    for (int j = 0; j < e.count; ++j)
      std::printf("%s{\"fault\":\"%s\",\"score\":%.4f}", j ? "," : "", e.candidate[j].name, e.candidate[j].score);
    std::printf("]}\n");
  }
}

hstmon::sim::ThesisScenario steady_nominal(double duration) {
  hstmon::sim::ThesisScenario sc;
  sc.name = "steady";
  sc.schedule = {{0.0, hstmon::ThesisInputs<double>{}}};
  sc.duration = duration;
  sc.initial = hstmon::sim::InitialCondition::kSteady;
  return sc;
}

// Machines off by up to ±2 % on every parameter (corners and random points), 30 s each.
TEST(MatcherE2E, NoFalseAlarmOnNominalLogsWithTwoPercentParameterError) {
  const auto sensors = hstmon::sim::thesis_fast_sensors(1000.0);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> sign(0, 1);
  std::uniform_real_distribution<double> uni(-0.02, 0.02);
  long ticks = 0, alarms = 0, events = 0;
  for (int run_i = 0; run_i < 6; ++run_i) {
    hstmon::ThesisParams<double> p;
    double* fields[] = {&p.Dm, &p.Dp, &p.Rlkg, &p.Ripl, &p.Rf, &p.Rbl, &p.kf, &p.J, &p.K};
    for (double* f : fields) *f *= 1.0 + (run_i < 4 ? (sign(rng) ? 0.02 : -0.02) : uni(rng));
    const auto log = hstmon::sim::measure(steady_nominal(30.0), sensors, 100 + static_cast<std::uint64_t>(run_i), p);
    const RunResult r = run_i % 2 ? run<float>(log, sensors) : run<double>(log, sensors);
    ticks += static_cast<long>(log.size());
    alarms += r.alarm_ticks;
    events += static_cast<long>(r.events.size());
    print_events(r);
  }
  std::printf("nominal, ±2 %% parameter error: %ld ticks at 1 kHz (6 machines, float and double), %ld alarm ticks, %ld events\n",
              ticks, alarms, events);
  EXPECT_EQ(alarms, 0);
  EXPECT_EQ(events, 0);
}

template <typename T>
void prv_blockage(double rate_hz, double max_delay) {
  const auto sensors = hstmon::sim::thesis_fast_sensors(rate_hz);
  const auto sc = hstmon::sim::thesis_prv_blockage();
  const auto log = hstmon::sim::measure(sc, sensors, 42);
  const RunResult r = run<T>(log, sensors);
  print_events(r);
  ASSERT_FALSE(r.events.empty());
  const auto& det = r.events.front();
  EXPECT_EQ(det.kind, MatchEventKind::kDetected);
  const double delay = det.time - 80.0;
  std::printf("PRV blockage at %.0f Hz (%s): detected %.1f ms after the fault\n", rate_hz,
              sizeof(T) == 4 ? "float" : "double", delay * 1e3);
  EXPECT_GE(delay, 0.0);  // nothing before the fault
  EXPECT_LT(delay, max_delay);
  bool isolated = false, has_kp = false;
  for (const auto& e : r.events) {
    if (e.kind != MatchEventKind::kIsolated) continue;
    isolated = true;
    for (int j = 0; j < e.count; ++j) has_kp = has_kp || std::string(e.candidate[j].name) == "kp-";
    std::printf("  isolated %.1f ms after the fault\n", (e.time - 80.0) * 1e3);
    break;
  }
  EXPECT_TRUE(isolated);
  EXPECT_TRUE(has_kp);
  EXPECT_EQ(r.events.back().kind, MatchEventKind::kIsolated);  // the fault persists: no clear
}

TEST(MatcherE2E, PrvBlockageAt1kHzDouble) { prv_blockage<double>(1000.0, 0.05); }
TEST(MatcherE2E, PrvBlockageAt1kHzFloat) { prv_blockage<float>(1000.0, 0.05); }
// At 100 Hz three samples are 30 ms; the observer runs at the 10 ms sample period.
TEST(MatcherE2E, PrvBlockageAt100Hz) { prv_blockage<double>(100.0, 0.05); }

}  // namespace
