// The regularised orifice law: exact beyond the transition, C¹ at it, finite slope at
// zero, and signed_square its inverse everywhere.
#include <gtest/gtest.h>

#include <cmath>

#include "hstmon/signed_root.hpp"

namespace {

using hstmon::signed_root;
using hstmon::signed_root_slope;
using hstmon::signed_square;

TEST(SignedRoot, ExactBeyondTransition) {
  const double xt = 1e5;
  for (double x : {1e5, 2.5e5, 1.7e7, -3.3e6}) {
    EXPECT_DOUBLE_EQ(signed_root(x, xt), std::copysign(std::sqrt(std::fabs(x)), x));
  }
}

TEST(SignedRoot, ContinuousWithSlopeAtTransition) {
  const double xt = 1e5;
  const double eps = 1e-9 * xt;
  EXPECT_NEAR(signed_root(xt - eps, xt), signed_root(xt + eps, xt), 1e-6);
  EXPECT_NEAR(signed_root_slope(xt - eps, xt), signed_root_slope(xt + eps, xt), 1e-8);
  EXPECT_NEAR(signed_root_slope(0.0, xt), 1.25 / std::sqrt(xt), 1e-15);
}

TEST(SignedRoot, MonotoneAndOdd) {
  const double xt = 1e3;
  double prev = signed_root(-2 * xt, xt);
  for (int i = -1999; i <= 2000; ++i) {
    const double x = i * 1e-3 * xt;
    const double r = signed_root(x, xt);
    EXPECT_GT(r, prev);
    EXPECT_DOUBLE_EQ(signed_root(-x, xt), -r);
    prev = r;
  }
}

TEST(SignedRoot, SlopeMatchesFiniteDifference) {
  const double xt = 1e5;
  for (double x : {-3e5, -5e4, -1.0, 0.0, 3e3, 9.9e4, 4e6}) {
    const double h = 1e-4 * (std::fabs(x) + 1);
    const double fd = (signed_root(x + h, xt) - signed_root(x - h, xt)) / (2 * h);
    EXPECT_NEAR(signed_root_slope(x, xt), fd, 1e-6 * std::fabs(fd)) << x;
  }
}

TEST(SignedSquare, InvertsSignedRootEverywhere) {
  for (double xt : {1e3, 1e5}) {
    for (double x : {-2e6, -1e5, -999.0, -1.0, -1e-6, 0.0, 1e-6, 0.5, 700.0, 1e3, 5e4, 1.7e7}) {
      const double y = signed_root(x, xt);
      EXPECT_NEAR(signed_square(y, xt), x, 1e-9 * (std::fabs(x) + 1)) << "x=" << x << " xt=" << xt;
    }
  }
}

TEST(SignedSquare, FloatInverse) {
  const float xt = 1e5f;
  for (float x : {-4e4f, -10.0f, 0.0f, 25.0f, 9e4f, 2e6f}) {
    EXPECT_NEAR(signed_square(signed_root(x, xt), xt), x, 1e-5f * (std::fabs(x) + 1.0f));
  }
}

}  // namespace
