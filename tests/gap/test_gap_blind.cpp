// Blind tests of the gap analysis: a fit log and a check log (different kp / p_sup
// staircases and durations) come from the truth simulator with an effect switched on; the
// analysis is not told which. Every single-effect case must rank the true effect first
// with ≥ 80 % shrink on the check log; the nominal case must report no significant gap;
// two effects at once must both come out on top. Every case runs twice: logs that start at
// a steady state and logs that start at rest (supply on at the first sample, a start-up
// the analysis must follow from the measured first sample).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "hstmon_gap/gap.hpp"
#include "hstmon_gap/synth.hpp"

namespace {

using namespace hstmon::gap;

struct Case {
  std::string label;
  std::vector<ActiveEffect> truth;
  StartRule start = StartRule::kSteady;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.label; }

GapResult run_case(const Case& c, double rate = 100.0, double dur_a = 6.0, double dur_b = 4.0,
                   const SynthNoise& noise = {}) {
  ExtendedModel truth;
  truth.effects = c.truth;
  InputSeries ua = staircase_profile('A', dur_a, rate), ub = staircase_profile('B', dur_b, rate);
  ua.start = ub.start = c.start;
  const auto a = synth_log(truth, ua, noise, 11, "fit");
  const auto b = synth_log(truth, ub, noise, 12, "check");
  EXPECT_TRUE(a.ok() && b.ok());
  GapResult r = run_gap(a, b, hstmon::ThesisParams<double>{}, hstmon::ThesisInputs<double>{});
  std::printf("[%s] verdict %s, %d sims, %.1f s\n", c.label.c_str(), r.verdict.c_str(), r.simulations, r.seconds);
  for (std::size_t i = 0; i < r.ranking.size(); ++i) {
    std::printf("   %zu. %-40s shrink_check %.3f dBIC %.4g\n", i + 1, r.ranking[i].name.c_str(),
                r.ranking[i].shrink_check, r.ranking[i].delta_bic_fit);
  }
  return r;
}

ActiveEffect eff(Effect e, std::vector<double> v, int channel = 2) {
  ActiveEffect a;
  a.id = e;
  a.values = std::move(v);
  a.channel = channel;
  return a;
}

class SingleEffect : public ::testing::TestWithParam<Case> {};

TEST_P(SingleEffect, TrueEffectRankedFirstAndShrinksCheckGap) {
  const Case& c = GetParam();
  const GapResult r = run_case(c);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_FALSE(r.ranking.empty());
  const EffectFit& top = r.ranking.front();
  ASSERT_EQ(top.effects.size(), 1u) << top.name;
  EXPECT_EQ(top.effects.front(), c.truth.front().id) << "top: " << top.name;
  EXPECT_GE(top.shrink_check, 0.8);
  EXPECT_EQ(r.verdict, "explained");
  if (c.truth.front().id == Effect::kSensorOffset) {
    EXPECT_EQ(top.offset_channel, c.truth.front().channel);
  }
}

std::vector<Case> single_effects(StartRule start) {
  std::vector<Case> v = {{"coulomb_friction", {eff(Effect::kCoulombFriction, {1.5})}},
                         {"pressure_torque_loss", {eff(Effect::kPressureTorqueLoss, {0.06})}},
                         {"motor_leakage", {eff(Effect::kMotorLeakage, {3e-11, 1e-11})}},
                         {"prv_cracking", {eff(Effect::kPrvCracking, {15e5})}},
                         {"supply_flow_limit", {eff(Effect::kSupplyFlowLimit, {1.45e-3, 3e5})}},
                         {"air_entrainment", {eff(Effect::kAirEntrainment, {0.3})}},
                         {"sensor_lag", {eff(Effect::kSensorLag, {0.03})}},
                         {"sensor_offset", {eff(Effect::kSensorOffset, {1e5}, 0)}}};
  for (auto& c : v) c.start = start;
  return v;
}

INSTANTIATE_TEST_SUITE_P(Blind, SingleEffect, ::testing::ValuesIn(single_effects(StartRule::kSteady)),
                         [](const ::testing::TestParamInfo<Case>& i) { return i.param.label; });
INSTANTIATE_TEST_SUITE_P(BlindFromRest, SingleEffect, ::testing::ValuesIn(single_effects(StartRule::kRest)),
                         [](const ::testing::TestParamInfo<Case>& i) { return i.param.label; });

TEST(GapBlind, NominalReportsNoSignificantGap) {
  for (StartRule start : {StartRule::kSteady, StartRule::kRest}) {
    const GapResult r = run_case({"nominal", {}, start});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.verdict, "no_significant_gap");
    EXPECT_TRUE(r.ranking.empty());
  }
}

class TwoEffects : public ::testing::TestWithParam<StartRule> {};

TEST_P(TwoEffects, BothOnTop) {
  const GapResult r = run_case(
      {"coulomb+lag", {eff(Effect::kCoulombFriction, {1.0}), eff(Effect::kSensorLag, {0.03})}, GetParam()});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_FALSE(r.ranking.empty());
  std::vector<Effect> top = r.ranking.front().effects;
  if (top.size() == 1 && r.ranking.size() > 1) top.push_back(r.ranking[1].effects.front());
  std::sort(top.begin(), top.end());
  EXPECT_EQ(top, (std::vector<Effect>{Effect::kCoulombFriction, Effect::kSensorLag}));
  EXPECT_EQ(r.verdict, "explained_by_pair");
  EXPECT_GE(r.ranking.front().shrink_check, 0.8);
}

INSTANTIATE_TEST_SUITE_P(GapBlind, TwoEffects, ::testing::Values(StartRule::kSteady, StartRule::kRest),
                         [](const ::testing::TestParamInfo<StartRule>& i) {
                           return std::string(i.param == StartRule::kRest ? "FromRest" : "FromSteady");
                         });

TEST(GapBlind, OffsetHiddenBehindAnotherEffectIsFoundAsThePair) {
  // A 1 bar p_pp offset under a torque loss: the torque-loss fit alone bends eta to absorb
  // part of the offset, so the offset ranks low alone and is found with it as the pair.
  const GapResult r = run_case({"torque_loss+offset",
                                {eff(Effect::kPressureTorqueLoss, {0.03}), eff(Effect::kSensorOffset, {1e5}, 2)},
                                StartRule::kRest});
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_FALSE(r.ranking.empty());
  std::vector<Effect> top = r.ranking.front().effects;
  std::sort(top.begin(), top.end());
  EXPECT_EQ(top, (std::vector<Effect>{Effect::kPressureTorqueLoss, Effect::kSensorOffset}));
  EXPECT_EQ(r.ranking.front().offset_channel, 2);
  EXPECT_GE(r.ranking.front().shrink_check, 0.8);
}

// Two physical effects where the second, fitted alone, ranks low or leaves part of itself
// unidentified, on logs like the independent simulator's (1 kHz, 12.5 s, from rest, noise
// 0.04 bar and 0.5 rpm): PRV
// cracking beside Coulomb friction (alone it fits 2.4 of 5 bar and ranks below four others,
// and a p_pp offset stands in for it); cross-port motor leakage beside Coulomb friction
// (its drain conductance, absent, stays at 0 ± its SE). The pair is the truth, not Coulomb
// friction with a sensor offset, nor Coulomb friction alone. (With 6× the speed noise,
// 0.3 rad/s, the cracking is not told from a torque loss and a p_pp offset: partly_explained.)
TEST(GapBlind, SecondEffectRankedLowAloneIsFoundAsThePair) {
  struct Second {
    const char* name;
    ActiveEffect effect;
    Effect id;
  };
  for (const Second& c : {Second{"coulomb+prv_cracking", eff(Effect::kPrvCracking, {5e5}), Effect::kPrvCracking},
                          Second{"coulomb+motor_leakage", eff(Effect::kMotorLeakage, {1e-11, 0.0}), Effect::kMotorLeakage}}) {
    const GapResult r =
        run_case({c.name, {eff(Effect::kCoulombFriction, {0.5}), c.effect}, StartRule::kRest}, 1000.0, 12.5, 12.5,
                 SynthNoise{4e3, 0.05});
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_FALSE(r.ranking.empty()) << c.name;
    std::vector<Effect> top = r.ranking.front().effects;
    std::sort(top.begin(), top.end());
    std::vector<Effect> want{Effect::kCoulombFriction, c.id};
    std::sort(want.begin(), want.end());
    EXPECT_EQ(top, want) << c.name << ": top " << r.ranking.front().name;
    EXPECT_EQ(r.verdict, "explained_by_pair") << c.name;
    EXPECT_GE(r.ranking.front().shrink_check, 0.8) << c.name;
  }
}

TEST(GapBlind, SlowSamplingCannotIdentifyTransientEffects) {
  // Thesis DAS-like sampling (here 0.5 s): lag and air entrainment only act in transients.
  ExtendedModel truth;
  truth.effects = {eff(Effect::kCoulombFriction, {1.5})};
  const auto a = synth_log(truth, staircase_profile('A', 28.0, 2.0), {}, 3);
  const auto b = synth_log(truth, staircase_profile('B', 20.0, 2.0), {}, 4);
  const GapResult r = run_gap(a, b, hstmon::ThesisParams<double>{}, hstmon::ThesisInputs<double>{});
  ASSERT_TRUE(r.ok) << r.error;
  std::vector<Effect> ni;
  for (const auto& n : r.not_identifiable) ni.push_back(n.effect);
  EXPECT_NE(std::find(ni.begin(), ni.end(), Effect::kSensorLag), ni.end());
  EXPECT_NE(std::find(ni.begin(), ni.end(), Effect::kAirEntrainment), ni.end());
  ASSERT_FALSE(r.ranking.empty());
  EXPECT_EQ(r.ranking.front().name, "coulomb_friction");
}

TEST(GapJson, HasWhereRankingVerdict) {
  ExtendedModel truth;
  truth.effects = {eff(Effect::kCoulombFriction, {1.5})};
  const auto a = synth_log(truth, staircase_profile('A', 3.0, 50.0), {}, 5);
  const auto b = synth_log(truth, staircase_profile('B', 2.0, 50.0), {}, 6);
  GapOptions o;
  o.effects = {Effect::kCoulombFriction, Effect::kSensorOffset};
  const GapResult r = run_gap(a, b, hstmon::ThesisParams<double>{}, hstmon::ThesisInputs<double>{}, o);
  const std::string j = to_json(r);
  for (const char* key : {"\"where\"", "\"ranking\"", "\"verdict\"", "\"shrink_check\"", "\"params\"", "\"tc\"",
                          "\"equations\"", "\"rms_over_noise\"", "\"envelope\"", "\"discovered\"", "\"start\"",
                          "\"stage_seconds\"", "\"verdict_rule\"", "\"autocorrelation_time\""}) {
    EXPECT_NE(j.find(key), std::string::npos) << key;
  }
}

}  // namespace
