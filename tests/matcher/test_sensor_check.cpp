// Raw-measurement checks: NaN, out of range (at or below the live zero, beyond the
// saturation band), saturated at the top of the range (masked, not a fault), stuck over a
// time window with a floor in samples; ordinary quantised noise is not flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "hstmon/sensor_check.hpp"

namespace {

using hstmon::SensorCheck;
using hstmon::kSensorNonFinite;
using hstmon::kSensorOutOfRange;
using hstmon::kSensorSaturated;
using hstmon::kSensorStuck;

constexpr double kLo = 0.0, kHi = 250e5;          // a 0–250 bar transmitter [Pa]
constexpr double kBand = (kHi - kLo) / 32.0;      // NE 43: up to 20.5 mA = 1/32 of the span

SensorCheck<double>::Config ranged() {
  SensorCheck<double>::Config c;
  for (int i = 0; i < 4; ++i) {
    c.range_lo[i] = kLo;
    c.range_hi[i] = kHi;
    c.noise[i] = 5e3;  // Noisy's σ on every channel: its 305 Pa ADC step is finer
  }
  return c;
}

/// Four channels of 100 bar + σ 0.05 bar on a 16-bit ADC (305 Pa steps).
struct Noisy {
  std::mt19937 rng{3};
  std::normal_distribution<double> n01;
  double y[4];
  double* next() {
    for (double& v : y) v = std::round((100e5 + 5e3 * n01(rng)) / 305.0) * 305.0;
    return y;
  }
};

TEST(SensorCheck, NonFiniteOutOfRangeSaturatedStuck) {
  SensorCheck<double> sc;
  ASSERT_EQ(sc.configure(ranged()), hstmon::Status::kOk);
  Noisy n;
  double t = 0;
  const double dt = 1e-3;
  for (int k = 0; k < 100000; ++k, t += dt) ASSERT_EQ(sc.update(t, n.next(), 0xF), 0) << k;
  double* y = n.next();
  y[1] = NAN;
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0b0010);
  EXPECT_EQ(sc.flags(1), kSensorNonFinite);
  y = n.next();
  y[2] = kHi;  // saturated at the range end: masked, not a fault
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0);
  EXPECT_EQ(sc.flags(2), kSensorSaturated);
  EXPECT_EQ(sc.saturated(), 0b0100);
  y = n.next();
  y[2] = kHi + kBand;  // 20.5 mA: still saturated
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0);
  EXPECT_EQ(sc.saturated(), 0b0100);
  y = n.next();
  y[2] = kHi + 1.01 * kBand;  // beyond 20.5 mA: a failure signal
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0b0100);
  EXPECT_EQ(sc.flags(2), kSensorOutOfRange);
  EXPECT_EQ(sc.saturated(), 0);
  y = n.next();
  y[0] = kLo;  // pinned at the live zero (4 mA): a loop break on a clamping input card
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0b0001);
  EXPECT_EQ(sc.flags(0), kSensorOutOfRange);
  y = n.next();
  y[0] = kLo - 25e5;  // 0 mA on a card that does not clamp: −25 % of the span
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0b0001);
  // Stuck: 100 equal samples at 1 kHz = stuck_time 0.1 s (the floor, 50, is below).
  for (int k = 0; k < 99; ++k) {
    y = n.next();
    y[3] = 42e5;
    ASSERT_EQ(sc.update(t += dt, y, 0xF), 0) << k;
  }
  y = n.next();
  y[3] = 42e5;  // the 100th equal sample
  EXPECT_EQ(sc.update(t += dt, y, 0xF), 0b1000);
  EXPECT_EQ(sc.flags(3), kSensorStuck);
  EXPECT_EQ(sc.mask(), 0b1000);
  EXPECT_EQ(sc.latched(), 0b1111);
  EXPECT_EQ(sc.update(t += dt, n.next(), 0xF), 0);  // moving again
  EXPECT_EQ(sc.mask(), 0);
  EXPECT_EQ(sc.saturated(), 0);
}

// The window is a time, with a floor in samples: stuck_time at fast rates, the floor at
// slow ones (n equal samples at interval Δt count as n·Δt).
int samples_until_stuck(double dt, double stuck_time, unsigned floor) {
  SensorCheck<float> sc;
  SensorCheck<float>::Config c;
  c.stuck_time = static_cast<float>(stuck_time);
  c.stuck_min_samples = static_cast<std::uint8_t>(floor);
  EXPECT_EQ(sc.configure(c), hstmon::Status::kOk);
  const float y[1] = {1.5e7f};
  for (int k = 0; k < 100000; ++k) {
    // float time, as the C API passes it, 10 s into the run
    if (sc.update(static_cast<float>(10.0 + k * dt), y, 1) != 0) return k + 1;
  }
  return -1;
}

TEST(SensorCheck, StuckWindowIsTimeWithASampleFloor) {
  EXPECT_EQ(samples_until_stuck(1e-3, 0.1, 50), 100);    // 0.1 s at 1 kHz
  EXPECT_EQ(samples_until_stuck(1e-4, 0.1, 50), 1000);   // 0.1 s at 10 kHz (was 100 samples = 10 ms)
  EXPECT_EQ(samples_until_stuck(1e-2, 0.1, 50), 50);     // the floor: 0.5 s at 100 Hz
  EXPECT_EQ(samples_until_stuck(4.0, 0.1, 50), 50);      // 200 s at the thesis DAS's 4 s
  EXPECT_EQ(samples_until_stuck(1e-2, 1.0, 50), 100);    // 1 s at 100 Hz
  EXPECT_EQ(samples_until_stuck(1e-2, 0.0, 2), 2);       // floor alone: the second equal sample
  EXPECT_EQ(samples_until_stuck(1e-3, 0.1, 0), -1);      // 0: disabled
}

// The window runs in the channel's own samples: a channel sampled every 10th tick is
// judged on its 100 Hz samples, not on the ticks in between.
TEST(SensorCheck, StuckWindowFollowsTheChannelsOwnSampleInterval) {
  SensorCheck<double> sc;
  Noisy n;
  int stuck_at = -1;
  for (int k = 0; k < 5000 && stuck_at < 0; ++k) {
    double* y = n.next();
    y[2] = 171e5;
    const std::uint8_t valid = (k % 10 == 0) ? 0xF : 0xB;  // p_pp every 10 ms, others every ms
    if (sc.update(k * 1e-3, y, valid) & 0b0100) stuck_at = k;
  }
  EXPECT_EQ(stuck_at, 490) << "50 samples of p_pp at 100 Hz";
  EXPECT_EQ(sc.mask(), 0b0100);
}

// A clamped reading repeats by nature: a transmitter held at its range end for minutes
// is saturated the whole time, never stuck.
TEST(SensorCheck, SaturatedIsNeverStuck) {
  SensorCheck<double> sc;
  ASSERT_EQ(sc.configure(ranged()), hstmon::Status::kOk);
  Noisy n;
  for (int k = 0; k < 200000; ++k) {
    double* y = n.next();
    y[2] = kHi;
    ASSERT_EQ(sc.update(k * 1e-3, y, 0xF), 0) << k;
    ASSERT_EQ(sc.saturated(), 0b0100) << k;
  }
  EXPECT_EQ(sc.latched(), 0);
  double* y = n.next();
  y[2] = 0.5 * kHi;
  EXPECT_EQ(sc.update(200.0, y, 0xF), 0);
  EXPECT_EQ(sc.saturated(), 0);
}

// 1 rpm counting with 0.5 rpm noise (the shipped logs' speed channel): runs of 20–30
// equal samples are ordinary; 10 minutes at 100 Hz raise no stuck flag.
TEST(SensorCheck, QuantisedSpeedAt100HzIsNotStuck) {
  SensorCheck<double> sc;
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  int longest = 0, run = 0;
  double prev = NAN;
  for (int k = 0; k < 60000; ++k) {
    double y[4] = {33e5 + k, 2e5 + k, 171e5 + k, std::round(1678.0 + 0.5 * n01(rng))};
    run = y[3] == prev ? run + 1 : 0;
    longest = std::max(longest, run + 1);
    prev = y[3];
    ASSERT_EQ(sc.update(k * 1e-2, y, 0xF), 0) << k;
  }
  EXPECT_GE(longest, 15) << "the test should see long runs";
  std::printf("longest run of equal speed samples: %d\n", longest);
}

TEST(SensorCheck, RejectsInvalidConfig) {
  SensorCheck<float> sc;
  SensorCheck<float>::Config c;
  c.range_lo[0] = 1.0f;
  c.range_hi[0] = 1.0f;
  EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig);
  c = {};
  c.range_hi[1] = NAN;
  EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig);
  c = {};
  c.stuck_min_samples = 1;
  EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig);
  for (float bad : {-1e-3f, NAN, std::numeric_limits<float>::infinity()}) {
    c = {};
    c.stuck_time = bad;
    EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig) << bad;
  }
  c = {};
  c.stuck_time = 0.25f;
  c.stuck_min_samples = 2;
  c.range_lo[3] = -10.0f;
  ASSERT_EQ(sc.configure(c), hstmon::Status::kOk);
  EXPECT_EQ(sc.config().stuck_time, 0.25f);
  EXPECT_EQ(sc.config().stuck_min_samples, 2);
  EXPECT_EQ(sc.config().range_lo[3], -10.0f);
  EXPECT_EQ(sc.config().range_hi[3], std::numeric_limits<float>::infinity());
}

}  // namespace

// A coarse ADC (step ≥ σ) repeats its code on a steady signal: a long run is not stuck
// unless the model moved by more than two steps (and its allowance) meanwhile.
TEST(SensorCheck, CoarseAdcIsStuckOnlyWhenTheModelMoved) {
  SensorCheck<double> sc;
  ASSERT_EQ(sc.configure(ranged()), hstmon::Status::kOk);
  double y[4] = {100e5, 100e5, 100e5, 100e5};
  double e[4] = {100e5, 100e5, 100e5, 100e5};
  const auto model = [&e](int c, double& est, double& allowance) {
    est = e[c];
    allowance = 0.5e5;
  };
  double t = 0;
  ASSERT_EQ(sc.update(t, y, 0x1, model), 0);
  for (int run = 0; run < 2; ++run) {  // two runs teach the 1 bar step (20 σ)
    y[0] += 1e5;
    ASSERT_EQ(sc.update(t += 1e-3, y, 0x1, model), 0);
    ASSERT_EQ(sc.update(t += 1e-3, y, 0x1, model), 0);
  }
  EXPECT_EQ(sc.step(0), 1e5);
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(sc.update(t += 1e-3, y, 0x1, model), 0) << "steady, k = " << k;
  for (int k = 0; k < 200; ++k) {
    e[0] += 0.05e5;  // the model rises by 10 bar while the reading stands still
    sc.update(t += 1e-3, y, 0x1, model);
  }
  EXPECT_EQ(sc.mask(), 0b0001);
  EXPECT_EQ(sc.flags(0), kSensorStuck);
}
