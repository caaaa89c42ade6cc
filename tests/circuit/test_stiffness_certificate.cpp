// The stiffness certificate's parts (stiffness_certificate.hpp, laws.hpp conductance_range):
// each law's conductance range holds every sampled slope over its pressure range; the
// interval radius bound is above the spectral radius of every sampled matrix in its range;
// and certify_reduced refuses what it cannot prove.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "hstmon/circuit/dense.hpp"
#include "hstmon/circuit/laws.hpp"
#include "hstmon/circuit/stiffness_certificate.hpp"

namespace {

namespace circuit = hstmon::circuit;
using circuit::Coeffs;
using circuit::ElementKind;

/// g = ∂Q/∂pa at pa − pb = dp (pb = 0), by the law itself.
double slope(ElementKind kind, const Coeffs<double>& k, double dp) {
  return circuit::element_flow(kind, k, dp, 0.0, 0.0).dpa;
}

void expect_range_holds(ElementKind kind, const Coeffs<double>& k, double lo, double hi, const char* what) {
  SCOPED_TRACE(what);
  double g_lo = 0.0, g_hi = 0.0;
  circuit::conductance_range(kind, k, lo, hi, g_lo, g_hi);
  ASSERT_LE(g_lo, g_hi);
  for (int i = 0; i <= 200; ++i) {
    const double dp = lo + (hi - lo) * i / 200.0;
    const double g = slope(kind, k, dp);
    EXPECT_GE(g, g_lo * (1.0 - 1e-12)) << "dp " << dp;
    EXPECT_LE(g, g_hi * (1.0 + 1e-12)) << "dp " << dp;
  }
}

TEST(ConductanceRange, OrificeOnEitherSideAndAcrossZero) {
  Coeffs<double> k;
  k.c[0] = 2e-7;  // k·opening [m³/(s·√Pa)]
  k.c[1] = 1e5;   // ΔP_t [Pa]
  expect_range_holds(ElementKind::kOrifice, k, 2e6, 6e6, "turbulent, forward");
  expect_range_holds(ElementKind::kOrifice, k, -6e6, -2e6, "turbulent, reverse");
  expect_range_holds(ElementKind::kOrifice, k, -3e4, 8e4, "laminar band, across zero");
  expect_range_holds(ElementKind::kOrifice, k, -2e6, 5e6, "across zero, both regimes");
  // The range is tight: its ends are the slopes at the far and near ends.
  double lo, hi;
  circuit::conductance_range(ElementKind::kOrifice, k, 2e6, 6e6, lo, hi);
  EXPECT_DOUBLE_EQ(lo, slope(ElementKind::kOrifice, k, 6e6));
  EXPECT_DOUBLE_EQ(hi, slope(ElementKind::kOrifice, k, 2e6));
}

TEST(ConductanceRange, LaminarMachineSource) {
  Coeffs<double> k;
  k.c[0] = 3e-12;
  expect_range_holds(ElementKind::kLaminar, k, -1e7, 1e7, "laminar");
  expect_range_holds(ElementKind::kMachine, k, -1e7, 1e7, "machine: no pressure slope");
  expect_range_holds(ElementKind::kFlowSource, k, -1e7, 1e7, "source: none either");
}

TEST(ConductanceRange, PoppetShutAndOpening) {
  Coeffs<double> k;
  k.c[0] = 1e-7;              // k
  k.c[1] = 1e5;               // ΔP_t
  k.c[2] = 1.5e7;             // crack
  k.c[3] = 1.0 / (2.0e6);     // 1/(full − crack)
  k.c[4] = 1.7e7;             // full
  double lo, hi;
  circuit::conductance_range(ElementKind::kPoppet, k, 0.0, 1.4e7, lo, hi);
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, 0.0);  // shut over the whole range
  expect_range_holds(ElementKind::kPoppet, k, 1.0e7, 2.0e7, "cracking and full open");
}

TEST(ConductanceRange, CompensatedPumpEveryRegion) {
  Coeffs<double> k;
  k.c[0] = 1e-3;   // Q0
  k.c[1] = -1e-11; // s1 = −1/R
  k.c[2] = 1.5e7;  // Pc
  k.c[3] = 1.8e7;  // Pk
  const double e = k.c[3] - k.c[2];
  k.c[5] = 5e-17;                                       // curvature
  k.c[4] = k.c[0] + k.c[1] * 0.0;                       // Q1 (continuity at Pc)
  k.c[6] = k.c[4] + k.c[1] * e - k.c[5] * e * e;        // Q2
  k.c[7] = -2e-9;                                       // s3
  // The pressure rise is pb − pa = −(pa − pb): ranges of pa − pb.
  expect_range_holds(ElementKind::kCompPump, k, -1.2e7, -1.0e7, "region 1");
  expect_range_holds(ElementKind::kCompPump, k, -1.7e7, -1.6e7, "region 2");
  expect_range_holds(ElementKind::kCompPump, k, -2.5e7, -1.9e7, "region 3");
  expect_range_holds(ElementKind::kCompPump, k, -2.5e7, -1.0e7, "all three");
}

/// Checks interval_radius_bound against `samples` random members of [lo, hi] (u: uniform
/// on [-1, 1]).
template <int N>
void expect_bound_above_members(const double (&lo)[N][N], const double (&hi)[N][N], int samples, std::mt19937& rng,
                                std::uniform_real_distribution<double>& u, int trial) {
  const double bound = circuit::interval_radius_bound(lo, hi, N);
  for (int k = 0; k < samples; ++k) {
    Eigen::Matrix<double, N, N> J;
    for (int r = 0; r < N; ++r) {
      for (int c = 0; c < N; ++c) J(r, c) = lo[r][c] + (hi[r][c] - lo[r][c]) * (0.5 + 0.5 * u(rng));
    }
    EXPECT_LE(J.eigenvalues().cwiseAbs().maxCoeff(), bound * (1.0 + 1e-12)) << "trial " << trial;
  }
}

// Random interval matrices — some with the damped-oscillator sign pattern the 2-state
// bound uses, some without — and random members of each.
TEST(IntervalRadiusBound, AboveEverySampledMember) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 0.3);
  for (int trial = 0; trial < 300; ++trial) {
    double lo2[2][2], hi2[2][2];
    const bool pattern = trial % 2 == 0;
    for (int r = 0; r < 2; ++r) {
      for (int c = 0; c < 2; ++c) {
        double m = 500.0 * u(rng);
        if (pattern && r == c) m = -std::fabs(m) - 200.0;
        if (pattern && r == 0 && c == 1) m = std::fabs(m) * 1e5;
        if (pattern && r == 1 && c == 0) m = -std::fabs(m) * 1e-5;
        const double half = w(rng) * std::fabs(m) * 0.5;
        lo2[r][c] = m - half;
        hi2[r][c] = m + half;
        if (pattern && r == c && hi2[r][c] > 0.0) hi2[r][c] = 0.0;
      }
    }
    expect_bound_above_members(lo2, hi2, 20, rng, u, trial);
  }
  for (int trial = 0; trial < 100; ++trial) {
    double lo3[3][3], hi3[3][3];
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        const double m = 300.0 * u(rng), half = w(rng) * std::fabs(m);
        lo3[r][c] = m - half;
        hi3[r][c] = m + half;
      }
    }
    expect_bound_above_members(lo3, hi3, 10, rng, u, trial);
  }
}

// A two-state, one-stiff-node system: unknowns (a, x1, x2). The certificate holds where
// the worst case contracts and stays below rho_max, and refuses otherwise.
TEST(CertifyReduced, ProvesAndRefuses) {
  const std::uint8_t ia[1] = {0}, ix[2] = {1, 2};
  const double inv_mass[2] = {1.0, 1.0};
  double lo[3][3] = {{-10.0, 1.0, 1.0}, {1.0, -300.0, 0.5}, {0.5, -0.5, -200.0}};
  double hi[3][3] = {{-9.0, 2.0, 2.0}, {2.0, -250.0, 1.0}, {1.0, -0.25, -150.0}};
  EXPECT_TRUE(circuit::certify_reduced(lo, hi, ia, 1, ix, 2, inv_mass, 800.0));
  EXPECT_FALSE(circuit::certify_reduced(lo, hi, ia, 1, ix, 2, inv_mass, 250.0)) << "ρ may reach 300";
  EXPECT_TRUE(circuit::certify_reduced(lo, hi, ia, 1, ix, 2, inv_mass, std::numeric_limits<double>::infinity()));
  // A stiff node whose diagonal may vanish: no contraction to prove.
  double lo_shut[3][3], hi_shut[3][3];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      lo_shut[r][c] = lo[r][c];
      hi_shut[r][c] = hi[r][c];
    }
  }
  hi_shut[0][0] = 0.0;
  EXPECT_FALSE(circuit::certify_reduced(lo_shut, hi_shut, ia, 1, ix, 2, inv_mass, 800.0));
}

// radius_bound_fixed<K> (compiled circuits' observer ticks) is radius_bound(J, K, ·) bit for
// bit: matrices whose rows mix scales decades apart (Pa/s against rad/s², as the paper
// circuit's), radii below, near and above rho_max, and non-finite entries.
template <typename T, int K>
void expect_fixed_matches_loop(std::mt19937& rng) {
  constexpr std::size_t kCap = 6;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-3, 5);
  for (int trial = 0; trial < 4000; ++trial) {
    T J[kCap][kCap] = {};
    for (int i = 0; i < K; ++i) {
      for (int j = 0; j < K; ++j) J[i][j] = static_cast<T>(u(rng) * std::pow(10.0, decade(rng)));
    }
    if (trial % 97 == 0) J[trial % K][(trial / 7) % K] = std::numeric_limits<T>::quiet_NaN();
    if (trial % 89 == 0) J[(trial / 3) % K][trial % K] = std::numeric_limits<T>::infinity();
    const T rho_max = static_cast<T>(std::pow(10.0, decade(rng)) * (0.5 + 0.5 * (u(rng) + 1.0)));
    const T loop = circuit::radius_bound(J, K, rho_max);
    const T fixed = circuit::radius_bound_fixed<K>(J, rho_max);
    if (std::isnan(loop)) {
      EXPECT_TRUE(std::isnan(fixed)) << "trial " << trial;
    } else {
      EXPECT_EQ(std::memcmp(&loop, &fixed, sizeof loop), 0) << "trial " << trial << ": " << loop << " vs " << fixed;
    }
  }
}

TEST(RadiusBound, FixedSizeIsTheLoopBitForBit) {
  std::mt19937 rng(29);
  expect_fixed_matches_loop<float, 1>(rng);
  expect_fixed_matches_loop<float, 2>(rng);
  expect_fixed_matches_loop<float, 3>(rng);
  expect_fixed_matches_loop<float, 4>(rng);
  expect_fixed_matches_loop<float, 6>(rng);
  expect_fixed_matches_loop<double, 4>(rng);
  expect_fixed_matches_loop<double, 5>(rng);
}

}  // namespace
