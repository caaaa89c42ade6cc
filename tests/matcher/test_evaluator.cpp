// Residual evaluation: CUSUM timing, no alarm on long pure-noise runs with the default
// configuration, the model bound from ±2 % parameter intervals, configuration checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "hstmon/residual_bounds.hpp"
#include "hstmon/residual_evaluator.hpp"

namespace {

using hstmon::ResidualEvaluator;
using hstmon::Status;

TEST(Cusum, ClipAndCapBoundTheStatistic) {
  hstmon::TwoSidedCusum<double> c;
  c.update(100.0, 2.0, 2.0, 10.0);
  EXPECT_DOUBLE_EQ(c.upper(), 2.0);  // one outlier adds at most the clip
  EXPECT_DOUBLE_EQ(c.lower(), 0.0);
  for (int i = 0; i < 20; ++i) c.update(100.0, 2.0, 2.0, 10.0);
  EXPECT_DOUBLE_EQ(c.upper(), 10.0);  // capped
  for (int i = 0; i < 5; ++i) c.update(0.0, 2.0, 2.0, 10.0);
  EXPECT_DOUBLE_EQ(c.upper(), 0.0);  // drained in cap / drift samples
}

template <typename T>
int ticks_to_alarm(ResidualEvaluator<T>& ev, const T* r, int max_ticks) {
  for (int k = 1; k <= max_ticks; ++k) {
    if (ev.update(r, 0xF) != 0) return k;
  }
  return -1;
}

TEST(Evaluator, OneOutlierNeverFiresAStepFiresOnItsThirdSample) {
  ResidualEvaluator<double> ev;
  const double s = ev.sigma(2);
  double r[4] = {0, 0, 1000 * s, 0};
  EXPECT_EQ(ev.update(r, 0xF), 0);  // 1000 σ once: no alarm
  r[2] = 0;
  for (int i = 0; i < 10; ++i) EXPECT_EQ(ev.update(r, 0xF), 0);
  ev.reset();
  r[2] = -10 * s;
  EXPECT_EQ(ticks_to_alarm(ev, r, 100), 3);
  EXPECT_EQ(ev.alarm(), 0b0100);
  EXPECT_EQ(ev.alarm_sign(2), -1);
  // 5 σ step: excess 3 σ clipped to 2 σ per sample → still 3 samples.
  ev.reset();
  r[2] = 5 * s;
  EXPECT_EQ(ticks_to_alarm(ev, r, 100), 3);
  // 3 σ step: excess 1 σ per sample → 5 samples.
  ev.reset();
  r[2] = 3 * s;
  EXPECT_EQ(ticks_to_alarm(ev, r, 100), 5);
  // Back to zero: released within cap / drift = 5 samples.
  r[2] = 0;
  int k = 0;
  while (ev.update(r, 0xF) != 0 && k < 100) ++k;
  EXPECT_LE(k, 5);
}

TEST(Evaluator, ModelBoundAbsorbsABiasUpToIt) {
  ResidualEvaluator<double>::Config c;
  c.model_bound[3] = 6.0;  // rad/s
  ResidualEvaluator<double> ev;
  ASSERT_EQ(ev.configure(c), Status::kOk);
  EXPECT_DOUBLE_EQ(ev.bound(3), 6.0 + 2.0 * ev.sigma(3));
  double r[4] = {0, 0, 0, -6.0};
  for (int i = 0; i < 10000; ++i) ASSERT_EQ(ev.update(r, 0xF), 0);
  r[3] = -6.0 - 4.0 * ev.sigma(3);
  EXPECT_GT(ticks_to_alarm(ev, r, 100), 0);
  EXPECT_EQ(ev.alarm_sign(3), -1);
}

TEST(Evaluator, InvalidChannelsKeepTheirState) {
  ResidualEvaluator<float> ev;
  float r[4] = {1e6f, 0, 0, NAN};
  for (int i = 0; i < 5; ++i) ev.update(r, 0b1110);  // Pmi masked, ωm NaN
  EXPECT_EQ(ev.alarm(), 0);
  EXPECT_EQ(ev.valid(), 0b0110);
}

TEST(Evaluator, RejectsInvalidConfig) {
  ResidualEvaluator<double> ev;
  ResidualEvaluator<double>::Config c;
  c.noise_sigma[1] = 0;
  EXPECT_EQ(ev.configure(c), Status::kInvalidConfig);
  c = {};
  c.k_threshold = 1.0;  // ≤ k_clip: one sample could fire
  EXPECT_EQ(ev.configure(c), Status::kInvalidConfig);
  c = {};
  c.model_bound[0] = NAN;
  EXPECT_EQ(ev.configure(c), Status::kInvalidConfig);
  const double bad[4] = {0, -1, 0, 0};
  EXPECT_EQ(ev.set_model_bound(bad), Status::kInvalidConfig);
}

// 1e6 ticks of white Gaussian noise at the configured σ on all 4 channels, each with a
// constant bias anywhere within ±m: not one alarm with the defaults.
template <typename T>
void no_alarm_on_noise(std::uint32_t seed) {
  ResidualEvaluator<T> ev;
  typename ResidualEvaluator<T>::Config c;
  const T m[4] = {T(2.67e4), T(2.67e4), T(4.92e5), T(6.22)};  // the ±2 % bound at Table 2.2
  for (int i = 0; i < 4; ++i) c.model_bound[i] = m[i];
  ASSERT_EQ(ev.configure(c), Status::kOk);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01;
  const double bias[4] = {0.9 * 2.67e4, -2.67e4, 0.0, 6.22};
  long alarms = 0;
  double peak = 0;
  T r[4];
  for (long k = 0; k < 1000000; ++k) {
    for (int i = 0; i < 4; ++i) r[i] = static_cast<T>(bias[i] + static_cast<double>(ev.sigma(i)) * n01(rng));
    if (ev.update(r, 0xF) != 0) ++alarms;
    for (int i = 0; i < 4; ++i) {
      const double g = static_cast<double>(std::fmax(ev.cusum(i).upper(), ev.cusum(i).lower()) / ev.sigma(i));
      peak = std::fmax(peak, g);
    }
  }
  std::printf("1e6 noise ticks x 4 channels: %ld alarm ticks, largest CUSUM statistic %.2f sigma (threshold 5)\n",
              alarms, peak);
  EXPECT_EQ(alarms, 0);
}

TEST(Evaluator, NoAlarmOnAMillionNoiseSamplesDouble) { no_alarm_on_noise<double>(1); }
TEST(Evaluator, NoAlarmOnAMillionNoiseSamplesFloat) { no_alarm_on_noise<float>(2); }

TEST(ModelBound, TwoPercentAtTable22) {
  hstmon::ThesisReducedModel<double> m;
  double b[4];
  ASSERT_EQ(hstmon::thesis_model_bound(m, hstmon::ThesisUncertainty<double>{}, b), Status::kOk);
  std::printf("model bound at ±2 %%: Pmi %.3f bar, Pmo %.3f bar, Ppp %.3f bar, wm %.3f rad/s\n", b[0] * 1e-5,
              b[1] * 1e-5, b[2] * 1e-5, b[3]);
  EXPECT_NEAR(b[0], 2.67e4, 0.05e4);
  EXPECT_NEAR(b[1], 2.67e4, 0.05e4);
  EXPECT_NEAR(b[2], 4.92e5, 0.05e5);
  EXPECT_NEAR(b[3], 6.22, 0.05);
  hstmon::ThesisReducedModel<float> mf;
  float bf[4];
  ASSERT_EQ(hstmon::thesis_model_bound(mf, hstmon::ThesisUncertainty<float>{}, bf), Status::kOk);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(static_cast<double>(bf[i]), b[i], 0.01 * b[i]);
  hstmon::ThesisUncertainty<double> bad;
  bad.kf = -0.1;
  EXPECT_EQ(hstmon::thesis_model_bound(m, bad, b), Status::kInvalidParams);
  hstmon::ThesisUncertainty<double> with_kp;
  with_kp.kp = 0.02;
  double bk[4];
  ASSERT_EQ(hstmon::thesis_model_bound(m, with_kp, bk), Status::kOk);
  EXPECT_GT(bk[2], b[2] + 1.5e5);
}

}  // namespace
