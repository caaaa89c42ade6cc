/// @file test_propagation.cpp
/// Backward propagation from e31+ (thesis §2.5.1) and forward propagation of Rpl+
/// (§2.5.2, Fig. 2.17) on the linearised graph of Fig. 2.14.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "hstmon/thesis_reduced.hpp"
#include "hstmon_fdi/backward.hpp"
#include "hstmon_fdi/fault_catalogue.hpp"
#include "hstmon_fdi/thesis_forward.hpp"
#include "hstmon_fdi/qual.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"

namespace hstmon::fdi {
namespace {

std::set<std::string> names(const BackwardResult& r, bool input) {
  std::set<std::string> s;
  for (const Candidate& c : r.candidates) {
    if (c.input == input) s.insert(c.name + qual_symbol(c.sign));
  }
  return s;
}

TEST(Backward, E31UpGivesTheThesisCandidates) {
  const CausalGraph g = thesis_tcg(ValveModel::kLinearised);
  const BackwardResult r = backward_propagate(g, "e31", +1);
  // The thesis's set, verbatim (Kpmi/Kpmo/Kpp are the C elements' stiffnesses).
  const std::set<std::string> thesis = {"Kpp+", "Rpl+", "Dp+",   "J1-",    "Rf-",   "Dm+",  "Rbl1-", "Rbl2-",
                                        "Kpmi+", "Kpmo-", "Rin-", "Rlkg1+", "Rlkg2-", "Ripl+", "Rout-"};
  EXPECT_EQ(names(r, false), thesis);
  // The effort sources are reached too; the thesis leaves inputs out of its list.
  EXPECT_EQ(names(r, true), (std::set<std::string>{"Psupl+", "Ps-", "Pbp+"}));
}

TEST(Backward, InstantaneousEdgesFirst) {
  const CausalGraph g = thesis_tcg(ValveModel::kLinearised);
  const BackwardResult r = backward_propagate(g, "p_pp", +1);
  ASSERT_FALSE(r.candidates.empty());
  EXPECT_EQ(r.candidates.front().name, "Kpp");  // the single dt edge into e31
  int last = 0;
  for (const Candidate& c : r.candidates) {
    EXPECT_GE(c.order, last) << c.name;
    last = c.order;
  }
  // Dm sits on four edges; the torque edge e8 = Dm·e7 is reached first (order 2) and
  // the swept-flow edges, which would ask for Dm−, are reported as conflicts.
  bool dm_conflict = false;
  for (const Conflict& c : r.conflicts) dm_conflict = dm_conflict || c.name == "Dm";
  EXPECT_TRUE(dm_conflict);
}

TEST(Backward, ParsesObservations) {
  std::string n;
  int s = 0;
  parse_observation("p_pp-", n, s);
  EXPECT_EQ(n, "p_pp");
  EXPECT_EQ(s, -1);
  EXPECT_THROW(parse_observation("e31", n, s), std::invalid_argument);
}

TEST(Forward, RplUpMatchesFig2_17) {
  const CausalGraph g = thesis_tcg(ValveModel::kLinearised);
  const ForwardResult f = forward_qualitative(g, {{"Rpl", +1}}, 4);
  const ChannelPrediction& ppp = f.channel[kChPpp];
  EXPECT_EQ(ppp.magnitude, kQualPlus);
  EXPECT_EQ(ppp.slope, kQualPlus);  // e31 rises first (one dt: f31 → e31)
  EXPECT_EQ(ppp.order, 1);
  EXPECT_EQ(f.channel[kChPmi].magnitude, kQualPlus);
  EXPECT_EQ(f.channel[kChPmo].magnitude, kQualMinus);
  EXPECT_EQ(f.channel[kChWm].magnitude, kQualMinus);
  EXPECT_EQ(f.channel[kChWm].order, 2);
  EXPECT_EQ(f.channel[kChPmi].order, 3);
  EXPECT_EQ(f.channel[kChPmo].order, 3);
  // The catalogue's kp− is the same fault on the nonlinear graph.
  const ForwardResult k = forward_qualitative(thesis_tcg(ValveModel::kNonlinear), fault_steps("kp", -1, ValveModel::kNonlinear), 4);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(k.channel[static_cast<std::size_t>(c)].slope, f.channel[static_cast<std::size_t>(c)].slope);
    EXPECT_EQ(k.channel[static_cast<std::size_t>(c)].order, f.channel[static_cast<std::size_t>(c)].order);
  }
}

TEST(Forward, WeightedResolvesOppositePaths) {
  // Dm+ raises the motor torque Dm·(Pmi − Pmo) > 0: the torque paths via e8 (+) and e21
  // (−) meet at e24, qualitatively ?, by the operating-point gains +.
  const CausalGraph g = thesis_tcg(ValveModel::kNonlinear);
  const ForwardResult q = forward_qualitative(g, {{"Dm", +1}}, 3);
  const ForwardResult w = forward_weighted(g, {{"Dm", +1}}, 3);
  EXPECT_EQ(q.channel[kChWm].slope, kQualAny);
  EXPECT_EQ(w.channel[kChWm].slope, kQualPlus);
  EXPECT_EQ(q.channel[kChPmi].slope, kQualMinus);  // more swept flow: Pmi falls at once
  EXPECT_THROW(forward_qualitative(g, {{"nope", 1}}, 3), std::invalid_argument);
}

TEST(Forward, LinearSteadyStateOfKpDown) {
  for (ValveModel v : {ValveModel::kNonlinear, ValveModel::kLinearised}) {
    const CausalGraph g = thesis_tcg(v);
    const std::array<double, 4> y = linear_steady_change(g, fault_steps("kp", -1, v));
    EXPECT_GT(y[kChPmi], 0.0);
    EXPECT_LT(y[kChPmo], 0.0);
    EXPECT_GT(y[kChPpp], 0.0);
    EXPECT_LT(y[kChWm], 0.0);
  }
}

}  // namespace
}  // namespace hstmon::fdi
