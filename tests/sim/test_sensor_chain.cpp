// Sensor chain: noise level, quantisation, clipping, lag time constant, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hstmon_sensors/gaussian.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sensors/sensor_presets.hpp"

namespace hstmon::sim {
namespace {

ChannelSpec plain(double tau = 0.0, double sigma = 0.0, double step = 0.0) {
  ChannelSpec c;
  c.name = "x";
  c.tau = tau;
  c.noise_std = sigma;
  c.quant_step = step;
  return c;
}

TEST(Gaussian, MomentsOfStandardNormal) {
  GaussianSource g(42);
  const int n = 200000;
  double s = 0.0, s2 = 0.0, s4 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = g.next();
    s += v;
    s2 += v * v;
    s4 += v * v * v * v;
  }
  EXPECT_NEAR(s / n, 0.0, 4.0 / std::sqrt(n));
  EXPECT_NEAR(s2 / n, 1.0, 0.015);
  EXPECT_NEAR(s4 / n, 3.0, 0.1);  // Gaussian kurtosis
}

TEST(SensorChain, NoiseStdOnConstantSignal) {
  const double sigma = 0.05 * kPaPerBar;
  SensorChain chain({plain(0.0, sigma)}, 7);
  const double truth = 33.12e5;
  chain.reset(&truth);
  const int n = 100000;
  double s = 0.0, s2 = 0.0;
  for (int i = 0; i < n; ++i) {
    double y;
    chain.measure(&y);
    s += y - truth;
    s2 += (y - truth) * (y - truth);
  }
  const double mean = s / n;
  const double sd = std::sqrt(s2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4.0 * sigma / std::sqrt(n));
  EXPECT_NEAR(sd / sigma, 1.0, 0.01);  // standard error of the s.d. ≈ 0.22 %
}

TEST(SensorChain, QuantisationStepAndGrid) {
  // 12-bit over 0–200 bar: 2e7 Pa / 4095 = 4884 Pa ≈ 0.0488 bar.
  const double step = adc_step(0.0, 200.0 * kPaPerBar, 12);
  EXPECT_NEAR(step, 2e7 / 4095.0, 1e-9);
  ChannelSpec c = plain(0.0, 0.0, step);
  c.range_lo = 0.0;
  c.range_hi = 200.0 * kPaPerBar;
  for (double v : {0.0, 1.0, 2442.0, 2443.0, 3.312079e6, 1.999e7, 2e7}) {
    const double q = clip_and_quantise(v, c);
    EXPECT_LE(std::fabs(q - v), 0.5 * step + 1e-9) << v;
    const double k = q / step;
    EXPECT_NEAR(k, std::round(k), 1e-9) << v;  // on the grid
  }
  // A ramp through the range visits consecutive codes only.
  double last = clip_and_quantise(0.0, c);
  for (double v = 0.0; v <= 1e5; v += 100.0) {
    const double q = clip_and_quantise(v, c);
    EXPECT_TRUE(q == last || std::fabs(q - last - step) < 1e-6);
    last = q;
  }
  // 1 rpm speed counting.
  ChannelSpec w = plain(0.0, 0.0, kRadPerSecPerRpm);
  EXPECT_NEAR(clip_and_quantise(175.6867, w) / kRadPerSecPerRpm, 1678.0, 1e-9);
}

TEST(SensorChain, ClipsAtRangeEnds) {
  ChannelSpec c = plain(0.0, 0.0, adc_step(0.0, 200.0 * kPaPerBar, 12));
  c.range_lo = 0.0;
  c.range_hi = 200.0 * kPaPerBar;
  EXPECT_EQ(clip_and_quantise(226.8e5, c), 200.0 * kPaPerBar);  // Ppp at kp/2 on a 200 bar part
  EXPECT_EQ(clip_and_quantise(-3e4, c), 0.0);
  // The thesis presets give p_pp 250 bar so the blockage level is not clipped.
  const SensorConfig das = thesis_das_sensors();
  EXPECT_EQ(das.channels[2].name, "p_pp");
  EXPECT_EQ(das.channels[2].range_hi, 250.0 * kPaPerBar);
  EXPECT_NEAR(clip_and_quantise(226.8005e5, das.channels[2]), 226.8005e5, 0.5 * das.channels[2].quant_step);
}

TEST(SensorChain, LagTimeConstantFromStepResponse) {
  const double tau = 1e-3;
  SensorChain chain({plain(tau)}, 1);
  const double zero = 0.0, one = 1.0;
  chain.reset(&zero);
  const double h0 = 1e-12;  // the step: a ramp over 1 ps
  chain.advance(&one, h0);
  const double h = 1e-4;
  double t = h0;
  for (int k = 1; k <= 50; ++k) {
    chain.advance(&one, h);
    t += h;
    const double y = chain.lagged()[0];
    EXPECT_NEAR(y, 1.0 - std::exp(-t / tau), 1e-9) << t;
    if (k == 10) {  // t ≈ τ: 63.2 %
      const double tau_est = -t / std::log(1.0 - y);
      EXPECT_NEAR(tau_est / tau, 1.0, 1e-6);
    }
  }
}

TEST(SensorChain, LagIsExactForARamp) {
  // y for x = r·t from y(0) = 0: r·(t − τ + τ·e^{−t/τ}); any internal step gives it.
  const double tau = 0.01, r = 3.0;
  for (double h : {1e-4, 3e-3, 0.05}) {
    SensorChain chain({plain(tau)}, 1);
    double x = 0.0;
    chain.reset(&x);
    double t = 0.0;
    for (int k = 0; k < 20; ++k) {
      t += h;
      x = r * t;
      chain.advance(&x, h);
    }
    EXPECT_NEAR(chain.lagged()[0], r * (t - tau + tau * std::exp(-t / tau)), 1e-12 * r * t) << h;
  }
}

TEST(SensorChain, DeterministicBySeed) {
  auto run = [](std::uint64_t seed) {
    SensorChain chain({plain(1e-3, 1e4), plain(0.0, 0.1)}, seed);
    const double x[2] = {1e6, 100.0};
    chain.reset(x);
    std::vector<double> out;
    for (int i = 0; i < 100; ++i) {
      chain.advance(x, 1e-3);
      double y[2];
      chain.measure(y);
      out.insert(out.end(), y, y + 2);
    }
    return out;
  };
  EXPECT_EQ(run(1), run(1));
  EXPECT_NE(run(1), run(2));
}

TEST(SensorChain, RejectsInvalidSpecs) {
  EXPECT_THROW(SensorChain({plain(-1.0)}, 1), std::invalid_argument);
  EXPECT_THROW(SensorChain({plain(0.0, -1.0)}, 1), std::invalid_argument);
  ChannelSpec c = plain();
  c.range_lo = 1.0;
  c.range_hi = 0.0;
  EXPECT_THROW(SensorChain({c}, 1), std::invalid_argument);
  EXPECT_THROW(adc_step(0.0, 1.0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace hstmon::sim
