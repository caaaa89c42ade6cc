/// @file test_fault_tree.cpp
/// Fault trees of Figs. 2.8–2.11: the thesis infers kp− ⇒ Pmi+, Pmo−, Ppp+, ωm−.
#include <gtest/gtest.h>

#include <functional>

#include "hstmon_fdi/fault_tree.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"

namespace hstmon::fdi {
namespace {

/// Sign of the root channel that a decrease of kp explains, read from the + tree.
QualSign channel_sign_for_kp_down(const CausalGraph& g, const char* channel) {
  for (const TreeCause& c : tree_causes(fault_tree(g, channel, +1))) {
    if (c.name != "kp") continue;
    EXPECT_FALSE(c.ambiguous) << channel;
    // The + tree asks for kp with sign c.sign; kp− therefore gives the channel −c.sign.
    return c.sign == kQualMinus ? kQualPlus : kQualMinus;
  }
  ADD_FAILURE() << "kp not in the tree of " << channel;
  return kQualAny;
}

TEST(FaultTree, KpDecreaseGivesTheThesisPattern) {
  const CausalGraph g = thesis_tcg(ValveModel::kNonlinear);
  EXPECT_EQ(channel_sign_for_kp_down(g, "p_mi"), kQualPlus);
  EXPECT_EQ(channel_sign_for_kp_down(g, "p_mo"), kQualMinus);
  EXPECT_EQ(channel_sign_for_kp_down(g, "p_pp"), kQualPlus);
  EXPECT_EQ(channel_sign_for_kp_down(g, "w_m"), kQualMinus);
}

TEST(FaultTree, PmoUpIsExplainedByKpUp) {
  // "when Pmo is +ve, kp is +ve (refer Fig. 2.9)"
  const CausalGraph g = thesis_tcg(ValveModel::kNonlinear);
  const std::string text = render_fault_tree(fault_tree(g, "p_mo", +1));
  EXPECT_NE(text.find("kp+  [parameter]"), std::string::npos) << text;
  EXPECT_EQ(text.rfind("p_mo+", 0), 0u);
}

TEST(FaultTree, ExpandsEachVariableOnceAndEndsAtParameters) {
  const CausalGraph g = thesis_tcg(ValveModel::kNonlinear);
  const FaultTreeNode t = fault_tree(g, "p_mi", +1);
  int leaves = 0;
  std::function<void(const FaultTreeNode&)> walk = [&](const FaultTreeNode& n) {
    if (n.children.empty()) {
      ++leaves;
      EXPECT_NE(n.leaf, TreeLeaf::kNone) << n.name;  // every branch ends at a cause, a loop or a reference
    }
    for (const FaultTreeNode& c : n.children) walk(c);
  };
  walk(t);
  EXPECT_GT(leaves, 10);
  EXPECT_THROW(fault_tree(g, "nope", 1), std::invalid_argument);
}

}  // namespace
}  // namespace hstmon::fdi
