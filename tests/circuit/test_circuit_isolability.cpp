// Detectability, isolability classes and sensor placement of the shipped circuits
// (circuit_isolability.hpp): what their physics says can and cannot be told apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

ct::LoadedCircuit load(const std::string& name) {
  ct::LoadedCircuit c;
  const auto err = ct::load_circuit(std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/" + name + ".json", "", c);
  EXPECT_FALSE(err.has_value()) << (err ? err->to_string() : std::string());
  return c;
}

bool same_class(const ct::Isolability& r, const std::string& a, const std::string& b) {
  for (const auto& c : r.classes) {
    if (std::count(c.begin(), c.end(), a) && std::count(c.begin(), c.end(), b)) return true;
  }
  return false;
}

bool weak(const ct::Isolability& r, const std::string& a, const std::string& b) {
  for (const auto& [x, y] : r.weak) {
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return false;
}

TEST(CircuitIsolability, ProductsAreOneClass) {
  // Closed loop: the pump's flow is eps·Dp·ω — its stroke input and its displacement
  // cannot be told apart by any steady measurement; test stand: D·n likewise.
  const ct::Isolability cl = ct::circuit_isolability(ct::circuit_fault_table(load("closed_loop_hst")));
  EXPECT_TRUE(same_class(cl, "Dp-", "eps-"));
  EXPECT_TRUE(same_class(cl, "Dp+", "eps+"));
  EXPECT_FALSE(same_class(cl, "Dp-", "Dp+"));
  const ct::Isolability ts = ct::circuit_isolability(ct::circuit_fault_table(load("test_stand")));
  EXPECT_TRUE(same_class(ts, "D-", "n_drive-"));
  EXPECT_TRUE(weak(ts, "D-", "R_leak-"));  // a leak and a smaller delivery look alike on p and q
}

TEST(CircuitIsolability, ThesisConfusionsOfTheCampaignArePredicted) {
  // The fault campaign reports Rbl+ together with Dm- (docs/fault_campaign.md).
  const ct::Isolability th = ct::circuit_isolability(ct::circuit_fault_table(load("thesis")));
  EXPECT_TRUE(weak(th, "Dm-", "Rbl+") || same_class(th, "Dm-", "Rbl+"));
  EXPECT_FALSE(same_class(th, "kp-", "Dp+"));  // the blockage stays isolable
  EXPECT_NE(std::find(th.undetectable.begin(), th.undetectable.end(), "dp_t_prv+"), th.undetectable.end());
}

TEST(CircuitIsolability, MatrixIsSymmetricWithTheClasses) {
  const ct::Isolability r = ct::circuit_isolability(ct::circuit_fault_table(load("paper")));
  const std::size_t n = r.faults.size();
  ASSERT_EQ(r.isolable.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(r.isolable[i][i], 0);
    for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(r.isolable[i][j], r.isolable[j][i]);
  }
  for (const auto& cls : r.classes) EXPECT_GE(cls.size(), 2u);
}

TEST(CircuitIsolability, PumpFlowSensorSeparatesALeakFromALowDelivery) {
  const auto ranked = ct::rank_added_sensors(load("test_stand"));
  ASSERT_FALSE(ranked.empty());
  const auto it = std::find_if(ranked.begin(), ranked.end(), [](const ct::SensorCandidate& s) { return s.name == "q(pump)"; });
  ASSERT_NE(it, ranked.end());
  EXPECT_GE(it->weak_cleared, 1);
  EXPECT_EQ(it - ranked.begin(), 0) << "q(pump) should rank first, got " << ranked.front().name;
}

}  // namespace
