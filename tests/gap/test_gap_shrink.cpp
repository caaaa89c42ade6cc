// How far a gap shrinks (hstmon_gap/shrink.hpp): the share of the gap above the sensor
// noise that a model change removes, so an effect that leaves only noise shrinks the gap
// fully, however close to the noise the gap was.
#include <gtest/gtest.h>

#include "hstmon_gap/shrink.hpp"

namespace {

using hstmon::gap::plain_shrink;
using hstmon::gap::shrink;

TEST(GapShrink, AnEffectLeavingOnlyNoiseShrinksTheGapFully) {
  // A gap 3.26× the noise brought to the noise (the motor-leakage case that read 0.69).
  EXPECT_DOUBLE_EQ(shrink(3.26, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(shrink(3.26, 0.95), 1.0);  // a noise estimate a little high
  EXPECT_NEAR(shrink(3.26, 1.006), 0.964, 1e-3);
  EXPECT_NEAR(plain_shrink(3.26, 1.006), 0.691, 1e-3);
}

TEST(GapShrink, NothingRemovedIsZeroAndFarFromNoiseItIsThePlainRatio) {
  EXPECT_DOUBLE_EQ(shrink(5.0, 5.0), 0.0);
  EXPECT_LT(shrink(5.0, 6.0), 0.0);  // a set that makes the check log worse
  EXPECT_NEAR(shrink(33.18, 7.78), plain_shrink(33.18, 7.78), 2e-3);
}

TEST(GapShrink, OrderedAsThePlainRatioAndNeverBelowIt) {
  for (double b : {1.2, 3.0, 30.0}) {
    double last = 2.0;
    for (double a = 0.5; a <= b; a += 0.05) {
      const double s = shrink(b, a);
      EXPECT_LE(s, last) << b << " " << a;
      EXPECT_GE(s, plain_shrink(b, a) - 1e-12) << b << " " << a;
      last = s;
    }
  }
}

TEST(GapShrink, NoGapAboveTheNoiseFallsBackToThePlainRatio) {
  EXPECT_DOUBLE_EQ(shrink(0.9, 0.8), plain_shrink(0.9, 0.8));
  EXPECT_DOUBLE_EQ(shrink(0.0, 0.8), 0.0);
}

}  // namespace
