// HeldStepDetector (held_step_detector.hpp): a step in a residual at held inputs fires,
// beyond the noise and a share of the model bound; noise, a slow drift and a start still
// settling do not; the reference it leaves is the pre-step level.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hstmon/held_step_detector.hpp"

namespace {

using Detector = hstmon::HeldStepDetector<double, 2>;

constexpr double kRate = 1000.0;          // samples per second
const double kSigma[2] = {5000.0, 0.05};  // 0.05 bar, 0.05 rad/s
const double kBound[2] = {3e5, 10.0};     // the model bound: 3 bar, 10 rad/s

Detector make() {
  Detector d;
  EXPECT_TRUE(d.configure(kSigma, 0x3u, Detector::Config{}));
  d.hold(0.0);
  return d;
}

// Feeds r(t) + noise on both channels until t_end; the time of the first firing, or NaN.
template <class F>
double run(Detector& d, F r, double t_end, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < static_cast<int>(t_end * kRate); ++k) {
    const double t = k / kRate;
    const double y[2] = {r(t, 0) + kSigma[0] * n(rng), r(t, 1) + kSigma[1] * n(rng)};
    if (d.add(t, y, 0x3u, kBound)) return t;
  }
  return std::nan("");
}

TEST(HeldStepDetector, AStepInsideTheBoundFiresWithinHalfASecond) {
  Detector d = make();
  // A residual bias of 2 bar (inside the model bound) all along; at 5 s p steps by 1 bar.
  const double t = run(d, [](double s, int i) { return i == 0 ? 2e5 + (s >= 5.0 ? 1e5 : 0.0) : 0.0; }, 10.0);
  ASSERT_FALSE(std::isnan(t));
  EXPECT_GE(t, 5.0);
  EXPECT_LE(t, 5.6);
  EXPECT_EQ(d.step_mask(), 0x1u);
  double mean[2], var[2];
  ASSERT_EQ(d.reference(mean, var), 0x3u);
  EXPECT_NEAR(mean[0], 2e5, 1e3);  // the level before the step
  EXPECT_GT(var[0], 0.0);
  EXPECT_FALSE(d.add(t + 0.1, mean, 0x3u, kBound)) << "fires once per hold";
}

TEST(HeldStepDetector, NoiseAndASlowDriftDoNotFire) {
  Detector d = make();
  // 10 minutes of noise with the oil warming: 1 bar and 1 rad/s per minute.
  EXPECT_TRUE(std::isnan(run(d, [](double t, int i) { return (i == 0 ? 1e5 : 1.0) * t / 60.0; }, 600.0, 7)));
}

TEST(HeldStepDetector, AStepSmallerThanItsShareOfTheBoundDoesNotFire) {
  Detector d = make();
  // 0.2 bar is 40 σ of a block mean but under 10 % of the 3 bar bound.
  EXPECT_TRUE(std::isnan(run(d, [](double t, int i) { return i == 0 && t >= 5.0 ? 2e4 : 0.0; }, 10.0)));
}

TEST(HeldStepDetector, AResidualStillSettlingJudgesNothing) {
  Detector d = make();
  // The end of a start from rest: the residual decays from 8 rad/s with τ = 0.5 s, and
  // the detector was told to start at 0 s (a settle time too short for this machine).
  EXPECT_TRUE(std::isnan(run(d, [](double t, int i) { return i == 1 ? 8.0 * std::exp(-t / 0.5) : 0.0; }, 10.0)));
}

TEST(HeldStepDetector, NothingBeforeTheSettleNorAfterANewHold) {
  Detector d = make();
  d.hold(20.0);  // the inputs moved; the model settles until 20 s
  EXPECT_TRUE(std::isnan(run(d, [](double t, int i) { return i == 0 && t >= 5.0 ? 1e6 : 0.0; }, 19.9)));
  double mean[2], var[2];
  EXPECT_EQ(d.reference(mean, var), 0u);
}

TEST(HeldStepDetector, RejectsABadConfiguration) {
  Detector d;
  Detector::Config c;
  c.ref_blocks = 2;
  EXPECT_FALSE(d.configure(kSigma, 0x3u, c));
  c = Detector::Config{};
  c.ref_blocks = 14;  // span 18 > 16 blocks kept
  EXPECT_FALSE(d.configure(kSigma, 0x3u, c));
  const double y[2] = {0.0, 0.0};
  EXPECT_FALSE(d.add(1.0, y, 0x3u, kBound));
}

}  // namespace
