// Fault matcher on synthetic residuals (noise at σ plus a fault pattern in units of σ):
// symbols, progressive elimination, order check, tie-break by direction, sensor faults,
// cleared, events, configuration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "hstmon/fault_matcher.hpp"
#include "hstmon/sensor_check.hpp"
#include "test_table.hpp"

namespace {

using hstmon::FaultSignature;
using hstmon::MatchEventKind;
using hstmon::MatchStatus;
using Matcher = hstmon::FaultMatcher<double>;
using Evaluator = hstmon::ResidualEvaluator<double>;
using hstmon_test::kTestTable;
using hstmon_test::kTestTableCount;

constexpr double kTick = 1e-3;

// Drives evaluator + sensor check + matcher at 1 kHz. pattern(t, d) writes the fault's
// deviation d[i] in σ units; raw(t, y) may overwrite the raw measurement (sensor faults).
struct Rig {
  Evaluator ev;
  hstmon::SensorCheck<double> sc;
  Matcher m;
  std::mt19937_64 rng{7};
  std::normal_distribution<double> n01;
  std::vector<Matcher::Event> events;
  double t = 0;
  bool settled = true;  // false: the caller marks an operating point's transient

  explicit Rig(const FaultSignature* table = kTestTable, int count = kTestTableCount, Matcher::Config c = {}) {
    EXPECT_EQ(m.configure(table, count, c), hstmon::Status::kOk);
  }

  /// Configures the sensor checks with every channel's transmitter range [lo, hi] and the
  /// other settings of c.
  hstmon::Status set_ranges(double lo, double hi, hstmon::SensorCheck<double>::Config c = {}) {
    for (int i = 0; i < 4; ++i) {
      c.range_lo[i] = lo;
      c.range_hi[i] = hi;
    }
    return sc.configure(c);
  }

  void run(double t_end, const std::function<void(double, double*)>& pattern,
           const std::function<void(double, double*)>& raw = nullptr) {
    for (; t < t_end - 1e-9; t += kTick) {
      double d[4] = {0, 0, 0, 0};
      if (pattern) pattern(t, d);
      double r[4], y[4];
      for (int i = 0; i < 4; ++i) {
        r[i] = ev.sigma(i) * (n01(rng) + d[i]);
        y[i] = (i == 3 ? 100.0 : 1e6) + r[i];  // a raw value that moves with the noise
      }
      if (raw) raw(t, y);
      std::uint8_t valid = 0xF;
      for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(y[i])) valid = static_cast<std::uint8_t>(valid & ~(1u << i));  // the observer masks NaN
      }
      // As Monitor: the sensor checks first; a saturated channel's residual only while > 0.
      const std::uint8_t flags = sc.update(t, y, 0xF);
      for (int i = 0; i < 4; ++i) {
        if (((sc.saturated() >> i) & 1u) != 0 && !(r[i] > 0)) valid = static_cast<std::uint8_t>(valid & ~(1u << i));
      }
      ev.update(r, valid);
      m.update(t, ev, flags, sc.saturated(), settled);
      Matcher::Event e;
      while (m.pop_event(e)) events.push_back(e);
    }
  }

  std::string names() const {
    std::string s;
    for (int j = 0; j < m.candidate_count(); ++j) s += std::string(j ? "," : "") + m.candidate(j).name;
    return s;
  }
  void print() const {
    for (const auto& e : events) {
      std::printf("  t=%.3f %s:", e.time, hstmon::to_string(e.kind));
      for (int j = 0; j < e.count; ++j) std::printf(" %s(%.4f)", e.candidate[j].name, e.candidate[j].score);
      std::printf("\n");
    }
  }
};

// A first-order step of the given σ-deviation from t_f on, time constant 5 ms.
std::function<void(double, double*)> step(double t_f, std::vector<double> dev, double tau = 5e-3) {
  return [=](double t, double* d) {
    if (t < t_f) return;
    const double g = 1.0 - std::exp(-(t - t_f) / tau);
    for (int i = 0; i < 4; ++i) d[i] = g * dev[static_cast<std::size_t>(i)];
  };
}

TEST(Matcher, NominalNoiseStaysNominal) {
  Rig rig;
  rig.run(20.0, nullptr);
  EXPECT_EQ(rig.m.status(), MatchStatus::kNominal);
  EXPECT_TRUE(rig.events.empty());
}

TEST(Matcher, KpMinusDetectedThenIsolated) {
  Rig rig;
  // kp halved in σ units (steady-state change, Table 2.2 point).
  rig.run(3.0, step(2.0, {24.9, -24.9, 1114.0, -1409.0}));
  rig.print();
  ASSERT_GE(rig.events.size(), 2u);
  EXPECT_EQ(rig.events[0].kind, MatchEventKind::kDetected);
  EXPECT_LT(rig.events[0].time - 2.0, 0.01);
  EXPECT_EQ(rig.events.back().kind, MatchEventKind::kIsolated);
  EXPECT_STREQ(rig.events.back().candidate[0].name, "kp-");
  EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated);
  EXPECT_EQ(rig.m.candidate_count(), 1);
  EXPECT_GT(rig.m.candidate(0).score, 0.999);
  // Symbols: Ppp rose, ωm fell; magnitudes after the window.
  EXPECT_EQ(rig.m.symbol(2).slope, hstmon::kQualPlus);
  EXPECT_EQ(rig.m.symbol(3).slope, hstmon::kQualMinus);
  EXPECT_EQ(rig.m.symbol(0).magnitude, hstmon::kQualPlus);
  EXPECT_EQ(rig.m.symbol(1).magnitude, hstmon::kQualMinus);
  EXPECT_EQ(rig.m.symbol(2).rank, 1);
}

// set_windows: the magnitudes wait for the new settle time and average over the new window.
TEST(Matcher, SetWindowsMovesTheMagnitudeWindow) {
  Rig rig;
  ASSERT_EQ(rig.m.set_windows(2.0, 0.5), hstmon::Status::kOk);
  const auto kp_half = step(1.0, {24.9, -24.9, 1114.0, -1409.0});
  rig.run(3.4, kp_half);  // detected at 1.0 s; 2 s settling and 0.5 s averaging: not yet
  EXPECT_EQ(rig.m.status(), MatchStatus::kDetected);
  rig.run(3.6, kp_half);
  EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated);
  EXPECT_STREQ(rig.m.candidate(0).name, "kp-");
  // Invalid windows are refused and change nothing.
  EXPECT_EQ(rig.m.set_windows(-1.0, 0.5), hstmon::Status::kInvalidConfig);
  EXPECT_EQ(rig.m.set_windows(1.0, 0.0), hstmon::Status::kInvalidConfig);
  EXPECT_EQ(rig.m.set_windows(std::nan(""), 0.5), hstmon::Status::kInvalidConfig);
  EXPECT_EQ(rig.m.config().settle_time, 2.0);
  EXPECT_EQ(rig.m.config().average_time, 0.5);
}

TEST(Matcher, DpPlusToldBySlopeAgainstMagnitude) {
  Rig rig;
  // Dp+: Ppp first rises (extra pump flow), then settles below nominal.
  auto f = [](double t, double* d) {
    if (t < 1.0) return;
    const double s = t - 1.0;
    const double g = 1.0 - std::exp(-s / 5e-3);
    d[0] = 7.3 * g;
    d[1] = -7.3 * g;
    d[2] = -33.0 * g + 400.0 * std::exp(-s / 8e-3) * (1.0 - std::exp(-s / 1e-3));
    d[3] = -336.0 * g;
  };
  rig.run(1.5, f);
  rig.print();
  EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated);
  ASSERT_GE(rig.m.candidate_count(), 1);
  EXPECT_STREQ(rig.m.candidate(0).name, "Dp+");
  EXPECT_EQ(rig.m.symbol(2).slope, hstmon::kQualPlus);
  EXPECT_EQ(rig.m.symbol(2).magnitude, hstmon::kQualMinus);
}

// Finite faults (5–10 %) at Table 2.2 in σ units, from the steady states; the rows'
// directions are for 0.1 % faults, so the match is not exact.
TEST(Matcher, TieBreakByDirection) {
  struct Case {
    const char* truth;
    std::vector<double> dev;
  };
  const Case cases[] = {{"Dp+", {3.67, -3.67, -16.44, -167.94}},
                        {"Rbl+", {1.31, -1.31, -112.23, -58.96}},
                        {"Dm-", {5.08, -5.08, -134.42, -70.75}}};
  for (const auto& c : cases) {
    Rig rig(hstmon_test::kTieTable, 3);
    rig.run(1.5, step(1.0, c.dev));
    std::printf("%s:\n", c.truth);
    rig.print();
    EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated) << c.truth;
    ASSERT_EQ(rig.m.candidate_count(), 3) << c.truth;  // qualitatively all consistent
    EXPECT_STREQ(rig.m.candidate(0).name, c.truth);
  }
}

TEST(Matcher, BiasOnOneChannelIsASensorFault) {
  for (int ch = 0; ch < 4; ++ch) {
    Rig rig;
    std::vector<double> dev(4, 0.0);
    dev[static_cast<std::size_t>(ch)] = (ch % 2 ? -20.0 : 20.0);
    rig.run(1.5, step(1.0, dev, 1e-4));
    // A row whose direction is almost one channel (Dp+ is 99.7 % ωm) stays consistent
    // with a deviation on that channel alone; the sensor row ranks first and isolates.
    EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated) << ch << " " << rig.names();
    ASSERT_GE(rig.m.candidate_count(), 1) << ch;
    if (ch != 3) {
      EXPECT_EQ(rig.m.candidate_count(), 1) << ch << " " << rig.names();
    }
    EXPECT_TRUE(kTestTable[rig.m.candidate(0).index].sensor);
    EXPECT_EQ(rig.m.symbol(ch).magnitude, ch % 2 ? hstmon::kQualMinus : hstmon::kQualPlus);
    const char* want[] = {"sensor_p_mi", "sensor_p_mo", "sensor_p_pp", "sensor_w_m"};
    EXPECT_STREQ(rig.m.candidate(0).name, want[ch]);
  }
}

TEST(Matcher, StuckOutOfRangeNaNAreSensorFaultsNeverParameterFaults) {
  const char* want[] = {"sensor_p_mi", "sensor_p_mo", "sensor_p_pp", "sensor_w_m"};
  for (int kind = 0; kind < 3; ++kind) {
    for (int ch = 0; ch < 4; ++ch) {
      Rig rig;
      hstmon::SensorCheck<double>::Config sc;
      sc.stuck_time = 0.1;  // 100 samples at 1 kHz
      ASSERT_EQ(rig.set_ranges(0, 2e6, sc), hstmon::Status::kOk);
      auto raw = [&](double t, double* y) {
        if (t < 1.0) return;
        if (kind == 0) y[ch] = 123.0;   // stuck
        if (kind == 1) y[ch] = 3e6;     // out of range
        if (kind == 2) y[ch] = NAN;     // not a number
      };
      // A residual that a stuck or out-of-range sensor produces on its channel.
      std::vector<double> dev(4, 0.0);
      if (kind != 2) dev[static_cast<std::size_t>(ch)] = -40.0;
      rig.run(1.5, step(1.0, dev, 1e-4), raw);
      EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated) << kind << " " << ch;
      ASSERT_EQ(rig.m.candidate_count(), 1) << kind << " " << ch << " " << rig.names();
      EXPECT_STREQ(rig.m.candidate(0).name, want[ch]);
      EXPECT_EQ(rig.m.sensor_masked(), 1u << ch);
      // A stuck sensor is only recognised after stuck_time; until then its residual
      // is an ordinary deviation, so only the isolation needs to be sensor-only. NaN and
      // out of range are flagged on the first sample: every event is sensor-only.
      for (const auto& e : rig.events) {
        if (kind == 0 && e.kind == MatchEventKind::kDetected) continue;
        for (int j = 0; j < e.count; ++j) EXPECT_TRUE(kTestTable[e.candidate[j].index].sensor) << kind << ch;
      }
    }
  }
}

// A transmitter driven to the top of its range by a real pressure rise reads exactly its
// range end from then on: saturated, not a sensor fault. Its deviation is a lower bound —
// the Rig, like Monitor, gives the evaluator its residual only while positive — so its
// '+' slope and magnitude still count and kp− is isolated as without saturation. The same
// channel pinned at the bottom of its range (a 4–20 mA loop break) is a sensor fault.
TEST(Matcher, SaturatedChannelIsMaskedButSystemHypothesesStay) {
  for (const bool high : {true, false}) {
    Rig rig;
    ASSERT_EQ(rig.set_ranges(0, 5.5e6), hstmon::Status::kOk);
    // Ppp (raw 1e6 + residual) rises by 1114 σ = 5.6e6 with τ = 5 ms: a clamping input
    // card reads the range end from ≈ 8 ms after the fault on. Or the loop breaks at 2.02 s.
    auto raw = [high](double t, double* y) {
      if (high) y[2] = std::min(y[2], 5.5e6);
      if (!high && t >= 2.02) y[2] = 0.0;
    };
    rig.run(3.0, step(2.0, {24.9, -24.9, 1114.0, -1409.0}), raw);
    rig.print();
    EXPECT_EQ(rig.m.sensor_masked(), 0b0100) << high;
    EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated) << high;
    ASSERT_GE(rig.m.candidate_count(), 1) << high;
    if (high) {
      EXPECT_EQ(rig.sc.saturated(), 0b0100);
      EXPECT_EQ(rig.sc.latched(), 0) << "saturation is not a sensor problem";
      EXPECT_EQ(rig.m.sensor_faults(), 0);
      EXPECT_STREQ(rig.m.candidate(0).name, "kp-");
      EXPECT_EQ(rig.m.symbol(2).slope, hstmon::kQualPlus);
      EXPECT_EQ(rig.m.symbol(2).magnitude, hstmon::kQualPlus);
      for (const auto& e : rig.events) {
        for (int j = 0; j < e.count; ++j) EXPECT_FALSE(kTestTable[e.candidate[j].index].sensor) << e.candidate[j].name;
      }
    } else {
      EXPECT_STREQ(rig.m.candidate(0).name, "sensor_p_pp");
      EXPECT_EQ(rig.m.sensor_faults(), 0b0100);
    }
  }
}

// A saturated channel whose reading is below the model (the model itself is over range)
// says nothing: no alarm, no episode, however long it lasts.
TEST(Matcher, SaturatedBelowTheModelRaisesNothing) {
  Rig rig;
  ASSERT_EQ(rig.set_ranges(0, 5.5e6), hstmon::Status::kOk);
  // Ppp reads its range end while the residual (measured − model) is −20 σ.
  auto raw = [](double, double* y) { y[2] = 5.5e6; };
  rig.run(5.0, step(0.0, {0.0, 0.0, -20.0, 0.0}, 1e-4), raw);
  EXPECT_EQ(rig.sc.saturated(), 0b0100);
  EXPECT_EQ(rig.m.status(), MatchStatus::kNominal);
  EXPECT_TRUE(rig.events.empty());
}

TEST(Matcher, ClearedAfterHoldAndDetectsAgain) {
  Rig rig;
  auto f = [](double t, double* d) {
    if ((t >= 1.0 && t < 1.3) || t >= 3.0) d[2] = 30.0;
  };
  rig.run(2.5, f);
  rig.print();
  ASSERT_GE(rig.events.size(), 3u);
  EXPECT_EQ(rig.events.back().kind, MatchEventKind::kCleared);
  EXPECT_NEAR(rig.events.back().time, 1.3 + 0.5, 0.02);
  EXPECT_EQ(rig.m.status(), MatchStatus::kNominal);
  rig.run(3.5, f);
  EXPECT_EQ(rig.m.status(), MatchStatus::kIsolated);
  EXPECT_STREQ(rig.m.candidate(0).name, "sensor_p_pp");
}

// While the caller marks an operating point's transient (settled = false) an episode does
// not end: a persisting fault its allowance hides is not cleared by an input change. The
// quiet time counts from when the transient has gone.
TEST(Matcher, NoClearDuringAnOperatingPointTransient) {
  Rig rig;
  auto f = [](double t, double* d) {
    if (t >= 1.0 && t < 1.3) d[2] = 30.0;
  };
  rig.run(1.2, f);
  ASSERT_NE(rig.m.status(), MatchStatus::kNominal);
  rig.settled = false;
  rig.run(2.5, f);
  EXPECT_NE(rig.m.status(), MatchStatus::kNominal) << "quiet since 1.3 s, in a transient";
  rig.settled = true;
  rig.run(2.9, f);
  EXPECT_NE(rig.m.status(), MatchStatus::kNominal);
  rig.run(3.1, f);
  EXPECT_EQ(rig.m.status(), MatchStatus::kNominal);
  ASSERT_FALSE(rig.events.empty());
  EXPECT_EQ(rig.events.back().kind, MatchEventKind::kCleared);
  EXPECT_NEAR(rig.events.back().time, 2.5 + 0.5, 0.01);
}

// Ppp deviates 30 ms before the other channels: rows whose fastest channel is not Ppp
// (order 0 or 1 elsewhere, 2 on Ppp) are dropped by the order check.
TEST(Matcher, FirstDeviatingChannelAgainstOrders) {
  auto delayed = [](double t, double* d) {
    const std::vector<double> dev = {1.3, -1.3, -112.0, -59.0};
    if (t >= 1.0) d[2] = dev[2] * (1.0 - std::exp(-(t - 1.0) / 5e-3));
    if (t >= 1.03) {
      const double g = 1.0 - std::exp(-(t - 1.03) / 5e-3);
      d[0] = 10 * dev[0] * g;
      d[1] = 10 * dev[1] * g;
      d[3] = dev[3] * g;
    }
  };
  {
    Rig rig;
    rig.run(1.5, delayed);
    rig.print();
    EXPECT_EQ(rig.m.first_channels(), 0b0100);
    EXPECT_EQ(rig.m.status(), MatchStatus::kUnexplained);
    EXPECT_EQ(rig.m.candidate_count(), 0);
  }
  {
    Matcher::Config c;
    c.order_slack = 1;
    Rig rig(kTestTable, kTestTableCount, c);
    rig.run(1.5, delayed);
    rig.print();
    // Rbl+ (fastest order 1, Ppp 2) is within the slack; Dm−, kf−, Psupl− (order 0 on Pmi/Pmo) are not.
    ASSERT_GE(rig.m.candidate_count(), 1) << rig.names();
    EXPECT_STREQ(rig.m.candidate(0).name, "Rbl+");
    for (int j = 0; j < rig.m.candidate_count(); ++j) {
      EXPECT_STRNE(rig.m.candidate(j).name, "Dm-");
      EXPECT_STRNE(rig.m.candidate(j).name, "kf-");
    }
  }
}

TEST(Matcher, EventQueueAndLatest) {
  Rig rig;
  EXPECT_EQ(rig.m.latest_event(), nullptr);
  rig.run(1.5, step(1.0, {24.9, -24.9, 1114.0, -1409.0}));
  ASSERT_NE(rig.m.latest_event(), nullptr);
  EXPECT_EQ(rig.m.latest_event()->kind, MatchEventKind::kIsolated);
  EXPECT_EQ(rig.m.events_dropped(), 0u);
  EXPECT_STREQ(hstmon::to_string(MatchEventKind::kCleared), "cleared");
  EXPECT_STREQ(hstmon::to_string(MatchStatus::kAmbiguous), "ambiguous");
}

TEST(Matcher, RejectsInvalidConfig) {
  hstmon::FaultMatcher<float, 4> small;
  EXPECT_EQ(small.configure(kTestTable, kTestTableCount, {}), hstmon::Status::kInvalidConfig);  // 11 > 4
  EXPECT_EQ(small.configure(nullptr, 2, {}), hstmon::Status::kInvalidConfig);
  EXPECT_EQ(small.configure(nullptr, 0, {}), hstmon::Status::kOk);
  hstmon::FaultMatcher<float, 4>::Config c;
  c.average_time = 0;
  EXPECT_EQ(small.configure(kTestTable, 4, c), hstmon::Status::kInvalidConfig);
}

}  // namespace
