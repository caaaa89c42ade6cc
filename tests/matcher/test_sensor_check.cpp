// Raw-measurement checks: NaN, out of range, stuck; saturation at a range end and
// ordinary quantised noise are not flagged.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hstmon/sensor_check.hpp"

namespace {

using hstmon::SensorCheck;

TEST(SensorCheck, NonFiniteOutOfRangeStuck) {
  SensorCheck<double> sc;
  SensorCheck<double>::Config c;
  for (int i = 0; i < 4; ++i) {
    c.range_lo[i] = -1e5;
    c.range_hi[i] = 250e5;
  }
  c.stuck_samples = 50;
  ASSERT_EQ(sc.configure(c), hstmon::Status::kOk);
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  double y[4];
  auto noisy = [&] {
    for (int i = 0; i < 4; ++i) y[i] = std::round((100e5 + 5e3 * n01(rng)) / 305.0) * 305.0;  // 16-bit ADC
  };
  for (int k = 0; k < 100000; ++k) {
    noisy();
    ASSERT_EQ(sc.update(y, 0xF), 0) << k;
  }
  noisy();
  y[1] = NAN;
  EXPECT_EQ(sc.update(y, 0xF), 0b0010);
  EXPECT_EQ(sc.flags(1), hstmon::kSensorNonFinite);
  noisy();
  y[2] = 250e5;  // saturated at the range end: plausible
  EXPECT_EQ(sc.update(y, 0xF), 0);
  noisy();
  y[2] = 251e5;
  EXPECT_EQ(sc.update(y, 0xF), 0b0100);
  EXPECT_EQ(sc.flags(2), hstmon::kSensorOutOfRange);
  for (int k = 0; k < 49; ++k) {
    noisy();
    y[3] = 42.0;
    EXPECT_EQ(sc.update(y, 0xF), 0) << k;
  }
  noisy();
  y[3] = 42.0;  // the 50th equal sample
  EXPECT_EQ(sc.update(y, 0xF), 0b1000);
  EXPECT_EQ(sc.flags(3), hstmon::kSensorStuck);
  EXPECT_EQ(sc.latched(), 0b1110);
  noisy();
  EXPECT_EQ(sc.update(y, 0xF), 0);  // moving again
}

TEST(SensorCheck, RejectsInvalidConfig) {
  SensorCheck<float> sc;
  SensorCheck<float>::Config c;
  c.range_lo[0] = 1.0f;
  c.range_hi[0] = 1.0f;
  EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig);
  c = {};
  c.stuck_samples = 1;
  EXPECT_EQ(sc.configure(c), hstmon::Status::kInvalidConfig);
}

}  // namespace
