// The paper's pressure-compensated pump curve: three regions, C¹ at both joins,
// Q(Pmax) = 0, monotone falling.
#include <gtest/gtest.h>

#include "hstmon/pump_curve.hpp"

namespace {

TEST(PumpCurve, JoinsAreC1AndDeadHeadIsZero) {
  hstmon::PumpCurve<double> c;
  hstmon::PumpCurveParams<double> p;
  ASSERT_TRUE(c.make(p));
  for (double P : {p.Pc, p.Pk}) {
    const double e = 1e-3;
    EXPECT_NEAR(c.flow(P - e), c.flow(P + e), 1e-12);
    EXPECT_NEAR(c.slope(P - e), c.slope(P + e), 1e-15);
  }
  EXPECT_NEAR(c.flow(p.Pmax), 0.0, 1e-15);
  EXPECT_NEAR(c.flow(0), p.Q0, 1e-18);
  EXPECT_DOUBLE_EQ(c.slope(1e6), -1.0 / p.R);
}

TEST(PumpCurve, MonotoneFallingAndConcaveInRegion2) {
  hstmon::PumpCurve<double> c;
  ASSERT_TRUE(c.make({}));
  double prev = c.flow(0);
  for (double P = 1e4; P <= 95e5; P += 1e4) {
    EXPECT_LT(c.flow(P), prev);
    prev = c.flow(P);
  }
  EXPECT_GT(c.parabola(), 0.0);
}

TEST(PumpCurve, RejectsInconsistentShape) {
  hstmon::PumpCurve<double> c;
  hstmon::PumpCurveParams<double> p;
  p.Pk = p.Pc;  // regions out of order
  EXPECT_FALSE(c.make(p));
  p = {};
  p.R = 1e9;  // leakage eats all flow before the compensator cuts in
  EXPECT_FALSE(c.make(p));
}

}  // namespace
