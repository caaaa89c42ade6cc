/// @file test_crosscheck.cpp
/// The TCG against the nonlinear model (docs/fdi.md publishes the full table).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hstmon_fdi/crosscheck.hpp"
#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {
namespace {

const std::vector<CrosscheckRow>& rows() {
  static const std::vector<CrosscheckRow> r = run_crosscheck();
  return r;
}

std::string pattern(const CrosscheckRow& r, QualSign ChannelCheck::*field) {
  std::string s;
  for (const ChannelCheck& c : r.channel) s += qual_symbol(c.*field);
  return s;
}

const CrosscheckRow& row(const std::string& c, const std::string& fault) {
  for (const CrosscheckRow& r : rows()) {
    if (r.case_name == c && r.fault == fault) return r;
  }
  throw std::runtime_error("no row " + fault + "@" + c);
}

TEST(Crosscheck, DpUpRblUpDmDownShareOneSteadyPattern) {
  EXPECT_EQ(pattern(row("nominal", "Dp+"), &ChannelCheck::ss), "+---");
  EXPECT_EQ(pattern(row("nominal", "Rbl+"), &ChannelCheck::ss), "+---");
  EXPECT_EQ(pattern(row("nominal", "Dm-"), &ChannelCheck::ss), "+---");
  EXPECT_EQ(pattern(row("nominal", "kp-"), &ChannelCheck::ss), "+-+-");
}

TEST(Crosscheck, WeightedTcgPredictsEveryNonlinearInitialSlope) {
  for (const CrosscheckRow& r : rows()) {
    for (std::size_t c = 0; c < 4; ++c) {
      EXPECT_EQ(r.channel[c].tcg_weighted, r.channel[c].slope0) << r.fault << "@" << r.case_name << " ch " << c;
    }
  }
}

TEST(Crosscheck, QualitativeTcgSlopesAgreeExceptStorageParameters) {
  for (const CrosscheckRow& r : rows()) {
    // K and J only scale integrators whose inputs are zero at a steady state.
    const bool storage = r.fault[0] == 'K' || r.fault[0] == 'J';
    for (std::size_t c = 0; c < 4; ++c) {
      const ChannelCheck& ch = r.channel[c];
      if (storage) {
        EXPECT_EQ(ch.slope0, kQualZero) << r.fault;
        EXPECT_EQ(ch.ss, kQualZero) << r.fault;
        continue;
      }
      EXPECT_TRUE(qual_agrees(ch.tcg_slope, ch.slope0)) << r.fault << "@" << r.case_name << " ch " << c;
      EXPECT_EQ(ch.tcg_order, ch.order0) << r.fault << "@" << r.case_name << " ch " << c;
      if (ch.early != kQualAny) {
        EXPECT_EQ(ch.early, ch.slope0) << r.fault << "@" << r.case_name << " ch " << c;
      }
    }
  }
}

TEST(Crosscheck, LinearisedSteadyStateWrongOnlyForDpOnPpp) {
  for (const CrosscheckRow& r : rows()) {
    for (std::size_t c = 0; c < 4; ++c) {
      const ChannelCheck& ch = r.channel[c];
      const bool known = r.fault == "Dp-" && c == 2;  // Ppp has a maximum in Dp near Table 2.2
      // Cross-port leakage moves Pmi by ~1e-12 relative at the heavy point: below the
      // steady-state solver's resolution, read as 0.
      const bool unresolved = ch.ss == kQualZero && std::fabs(ch.ss_rel) < 1e-12;
      if (known || unresolved) continue;
      EXPECT_EQ(ch.lin_secant, ch.ss) << r.fault << "@" << r.case_name << " ch " << c;
      EXPECT_EQ(ch.lin_tangent, ch.ss) << r.fault << "@" << r.case_name << " ch " << c;
    }
  }
  EXPECT_EQ(row("nominal", "Dp-").channel[2].ss, kQualMinus);
  EXPECT_EQ(row("nominal", "Dp-").channel[2].lin_tangent, kQualPlus);
}

}  // namespace
}  // namespace hstmon::fdi
