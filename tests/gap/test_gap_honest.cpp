// Honesty of `hstmon gap` on machines the library cannot describe:
// - an effect outside the library (a leakage from the loading-pump node to drain, a
//   windage torque): the verdict is not `explained`, the located equation is the one the
//   effect enters, and the discovered term names the right variable;
// - another machine (Dp, kf and the supply changed by factors 2–5): out of envelope, no
//   effect named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "hstmon_gap/gap.hpp"
#include "hstmon_gap/synth.hpp"

namespace {

using namespace hstmon::gap;

struct Logs {
  hstmon::host::LogData fit, check;
};

Logs make_logs(const ExtendedModel& truth, StartRule start, double psup_factor = 1.0, double rate = 200.0) {
  InputSeries a = staircase_profile('A', 6.0, rate), b = staircase_profile('B', 4.0, rate);
  for (auto* u : {&a, &b}) {
    u->start = start;
    for (double& p : u->Psupl) p *= psup_factor;
  }
  return {synth_log(truth, a, {}, 21, "fit"), synth_log(truth, b, {}, 22, "check")};
}

GapResult run(const Logs& l) {
  EXPECT_TRUE(l.fit.ok() && l.check.ok());
  GapResult r = run_gap(l.fit, l.check, hstmon::ThesisParams<double>{}, hstmon::ThesisInputs<double>{});
  std::printf("verdict: %s\n", r.verdict_text.c_str());
  return r;
}

std::string located(const Where& w) {
  return w.located >= 0 ? equation_names()[static_cast<std::size_t>(w.located)] : "none";
}

TEST(GapHonest, LeakageAtTheLoadingPumpIsLocatedAndDiscovered) {
  ExtendedModel truth;
  truth.extras.g_pp = 1.0 / 3e12;  // R = 3e12 Pa·s/m³
  const GapResult r = run(make_logs(truth, StartRule::kRest));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(r.verdict.rfind("explained", 0), 0u) << r.verdict;
  EXPECT_NE(r.verdict, "out_of_envelope");
  EXPECT_EQ(located(r.where_check), "flow:p_pp");
  ASSERT_FALSE(r.discovered.empty());
  const Discovery& d = r.discovered.front();
  EXPECT_EQ(d.equation, "flow:p_pp");
  ASSERT_FALSE(d.terms.empty());
  EXPECT_EQ(d.terms.front().form, "p_pp");
  EXPECT_NEAR(1.0 / d.terms.front().coefficient, 3e12, 0.3e12);
  EXPECT_GT(d.shrink_check, 0.8);
  // Added to the model, the term closes the channels' gap too.
  EXPECT_TRUE(d.simulated);
  EXPECT_GT(d.model_shrink_check, 0.8);
}

TEST(GapHonest, WindageTorqueIsLocatedOnTheShaft) {
  ExtendedModel truth;
  truth.extras.windage = 4e-5;  // ≈ 1.2 N·m at 175 rad/s
  const GapResult r = run(make_logs(truth, StartRule::kSteady, 1.0, 100.0));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(r.verdict.rfind("explained", 0), 0u) << r.verdict;
  EXPECT_EQ(located(r.where_check), "torque:w_m");
  ASSERT_FALSE(r.discovered.empty());
  const Discovery& d = r.discovered.front();
  EXPECT_EQ(d.equation, "torque:w_m");
  ASSERT_FALSE(d.terms.empty());
  // The leading term is a function of the speed.
  EXPECT_NE(d.terms.front().form.find("w_m"), std::string::npos) << d.terms.front().form;
  EXPECT_TRUE(d.simulated);
  EXPECT_GT(d.model_shrink_check, 0.8);
}

TEST(GapHonest, AnotherMachineIsOutOfEnvelopeAndNamesNoEffect) {
  ExtendedModel other;
  other.nominal.Dp *= 0.4;   // pump 2.5× smaller
  other.nominal.kf *= 3.0;   // DCV 3× larger
  const GapResult r = run(make_logs(other, StartRule::kSteady, 2.0));  // supply 2× higher
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.verdict, "out_of_envelope");
  EXPECT_TRUE(r.envelope.out);
  EXPECT_TRUE(r.ranking.empty());
  EXPECT_TRUE(r.explained_by.empty());
  EXPECT_TRUE(r.discovered.empty());
  EXPECT_NE(r.verdict_text.find("identify"), std::string::npos);
}

}  // namespace
