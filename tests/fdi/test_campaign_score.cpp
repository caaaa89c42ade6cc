// The campaigns' scoring of one run: "isolated on the truth or its class" (campaign_score.hpp).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "campaign_score.hpp"

namespace {

using hstmon::host::ReplayEvent;

// An event at t with candidates (name, weight), best first.
ReplayEvent event(double t, const std::string& kind, const std::vector<std::pair<std::string, double>>& cands) {
  ReplayEvent e;
  e.t = t;
  e.event = kind;
  for (const auto& [name, score] : cands) {
    hstmon::host::ReplayCandidate c;
    c.fault = name;
    c.score = score;
    e.candidates.push_back(c);
  }
  return e;
}

const std::vector<std::string> kClass = {"Dp+", "eps+"};  // one product: no sensor splits them

TEST(CampaignScore, AmbiguousWithinTheTruthsClassIsolatesIt) {
  const std::vector<ReplayEvent> ev = {event(4.1, "detected", {{"Dp+", 0.9}}),
                                       event(7.5, "ambiguous", {{"eps+", 1.0}, {"Dp+", 0.7}})};
  const auto s = hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass);
  EXPECT_TRUE(s.detected);
  EXPECT_TRUE(s.isolated_class);
  EXPECT_NEAR(s.isolation_delay, 3.5, 1e-12);
}

TEST(CampaignScore, AnOutsiderLeftConsistentIsNotIsolation) {
  const std::vector<ReplayEvent> ev = {event(7.5, "ambiguous", {{"Dp+", 1.0}, {"eps+", 1.0}, {"sensor_w_m", 0.06}})};
  EXPECT_FALSE(hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass).isolated_class);
}

TEST(CampaignScore, IsolatedCountsWhenItsFirstIsInTheClass) {
  const std::vector<ReplayEvent> ev = {event(7.5, "isolated", {{"eps+", 1.0}, {"sensor_w_m", 0.05}})};
  EXPECT_TRUE(hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass).isolated_class);
  EXPECT_FALSE(hstmon_campaign::score(ev, "Dp+", 4.0, 0.01).isolated_class);  // no class given
}

TEST(CampaignScore, WithoutAClassOnlyTiesCount) {
  const std::vector<ReplayEvent> tie = {event(7.5, "ambiguous", {{"Dp+", 1.0}, {"eps+", 1.0}})};
  EXPECT_TRUE(hstmon_campaign::score(tie, "Dp+", 4.0, 0.01).isolated_class);
  const std::vector<ReplayEvent> near = {event(7.5, "ambiguous", {{"Dp+", 1.0}, {"eps+", 0.99}})};
  EXPECT_FALSE(hstmon_campaign::score(near, "Dp+", 4.0, 0.01).isolated_class);
}

TEST(CampaignScore, AClearAtTheEndNamesNothingUnderTheCircuitSetsRule) {
  // The fault persists to the end of the run: a last "cleared" is noted either way; under
  // score_circuit.py's rule it withdraws what came before, under score_monitor.py's not.
  const std::vector<ReplayEvent> ev = {event(7.5, "isolated", {{"Dp+", 1.0}}), event(9.0, "cleared", {})};
  const auto circuit_rule = hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass, true);
  EXPECT_TRUE(circuit_rule.cleared_at_end);
  EXPECT_FALSE(circuit_rule.in_last);
  EXPECT_FALSE(circuit_rule.isolated_class);
  const auto monitor_rule = hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass);
  EXPECT_TRUE(monitor_rule.cleared_at_end);
  EXPECT_TRUE(monitor_rule.in_last);
  EXPECT_TRUE(monitor_rule.isolated_class);
}

TEST(CampaignScore, OnlyTheFinalStretchOfDecisionsCounts) {
  // Isolated early, then a wrong verdict last: not isolated.
  const std::vector<ReplayEvent> ev = {event(7.5, "isolated", {{"Dp+", 1.0}}),
                                       event(12.0, "ambiguous", {{"Dm-", 1.0}, {"Dp+", 0.5}})};
  EXPECT_FALSE(hstmon_campaign::score(ev, "Dp+", 4.0, 0.01, kClass).isolated_class);
}

}  // namespace
