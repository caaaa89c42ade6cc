// Classes said plainly (candidate_class.hpp, fault_words.hpp, operating_points.hpp): a
// fault and a set of faults in an engineer's words, derived from the circuit file's
// elements and nodes; what would tell the final candidates apart (an added sensor, a
// change of operating point, or nothing in reach); and the pairs a change of operating
// point splits. On the shipped circuits and the open validation circuit (hst45).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hstmon_circuit/candidate_class.hpp"
#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/fault_words.hpp"
#include "hstmon_circuit/operating_points.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

using hstmon_test::load_hst45;

bool split_pair(const ct::OperatingPointSplit& s, const std::string& a, const std::string& b) {
  for (const auto& [x, y] : s.pairs) {
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return false;
}

TEST(FaultWords, EachFaultOfTheValidationCircuit) {
  const ct::LoadedCircuit c = load_hst45();
  const ct::FaultMeaning drain_b = ct::fault_meaning(c, "R_ext_b-");
  EXPECT_EQ(drain_b.effect, ct::FaultEffect::kLeak);
  EXPECT_EQ(drain_b.words, "a leak from line B to tank");
  EXPECT_EQ(ct::fault_meaning(c, "R_ip-").words, "a leak between line A and line B");
  EXPECT_EQ(ct::fault_meaning(c, "R_ip+").effect, ct::FaultEffect::kRestriction);
  // The pump's displacement, its stroke and the engine speed: one delivery loss.
  for (const char* f : {"Dp-", "eps-", "n_e-"}) {
    const ct::FaultMeaning m = ct::fault_meaning(c, f);
    EXPECT_EQ(m.effect, ct::FaultEffect::kDeliveryLoss) << f;
    EXPECT_EQ(m.words.rfind("a delivery loss at pump", 0), 0u) << f << ": " << m.words;
  }
  EXPECT_EQ(ct::fault_meaning(c, "Dm-").effect, ct::FaultEffect::kDisplacementLoss);
  EXPECT_EQ(ct::fault_meaning(c, "T_L+").words, "more load torque on shaft motor");
  EXPECT_EQ(ct::fault_meaning(c, "c_m+").words, "more friction on shaft motor");
  EXPECT_EQ(ct::fault_meaning(c, "p_ch-").words, "a lower pressure at C");
  EXPECT_EQ(ct::fault_meaning(c, "p_rv_b-").effect, ct::FaultEffect::kOpensEarly);
  EXPECT_EQ(ct::fault_meaning(c, "sensor_p_a").words, "a fault of sensor p_a");
  EXPECT_EQ(ct::fault_meaning(c, "no_such-").effect, ct::FaultEffect::kOther);
}

TEST(FaultWords, ClassesOfTheValidationCircuit) {
  const ct::LoadedCircuit c = load_hst45();
  EXPECT_EQ(ct::class_words(c, {"R_ext_a-", "R_ip-", "R_im-"}), "a leak from line A");
  EXPECT_EQ(ct::class_words(c, {"R_ip-", "R_im-"}), "a leak between line A and line B");
  EXPECT_EQ(ct::class_words(c, {"Dp-", "eps-", "n_e-"}), "a delivery loss at pump");
  // A leak from A and the pump's delivery into A both take flow out of line A.
  EXPECT_EQ(ct::class_words(c, {"R_ext_a-", "R_ip-", "Dp-", "eps-"}), "a flow loss from line A (a leak or a delivery loss)");
  EXPECT_EQ(ct::class_words(c, {"R_ext_b-", "sensor_p_b"}), "a leak from line B to tank or a fault of sensor p_b");
  // Mixed effects: each with what its own candidates share (fault_leak_B's final set).
  EXPECT_EQ(ct::class_words(c, {"R_ext_b-", "R_ip-", "R_im-", "sensor_w_m", "p_rv_b-", "Dp-", "n_e-", "eps-"}),
            "a leak from line B, a fault of sensor w_m, relief_b opening early (setting lower) or a delivery loss at pump");
  EXPECT_EQ(ct::class_words(c, {}), "");
}

TEST(FaultWords, ShippedCircuitsSayTheirOwnNames) {
  // The words come from each file's elements: nothing names hst45's lines.
  const ct::LoadedCircuit cl = hstmon_test::load_example("closed_loop_hst");
  EXPECT_EQ(ct::class_words(cl, {"Dp-", "eps-"}).rfind("a delivery loss at ", 0), 0u) << ct::class_words(cl, {"Dp-", "eps-"});
  const ct::LoadedCircuit ts = hstmon_test::load_example("test_stand");
  EXPECT_EQ(ct::fault_meaning(ts, "R_leak-").words, "a leak from line to tank");
  const std::string ts_delivery = ct::class_words(ts, {"D-", "n_drive-"});
  EXPECT_EQ(ts_delivery.rfind("a delivery loss at ", 0), 0u) << ts_delivery;
  const ct::LoadedCircuit th = hstmon_test::load_example("thesis");
  EXPECT_EQ(ct::fault_meaning(th, "Rbl+").effect, ct::FaultEffect::kMoreTorque);
  EXPECT_EQ(ct::fault_meaning(th, "Dm-").effect, ct::FaultEffect::kDisplacementLoss);
}

TEST(FaultWords, AddedSensors) {
  EXPECT_EQ(ct::added_sensor_words("p(Pmi)"), "a pressure sensor at node Pmi");
  EXPECT_EQ(ct::added_sensor_words("w(motor)"), "a speed sensor on shaft motor");
  EXPECT_EQ(ct::added_sensor_words("q(drain_a)"), "a flow meter on drain_a");
  EXPECT_EQ(ct::added_sensor_words("odd"), "odd");
}

TEST(OperatingPoints, SpanTheInputs) {
  const ct::LoadedCircuit c = load_hst45();
  std::vector<std::string> names;
  for (const auto& p : ct::operating_points(c)) names.push_back(p.name);
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "nominal");
  for (const char* n : {"T_L 50 %", "T_L 150 %", "eps 50 %", "eps 150 %", "eps reversed", "n_e 50 %", "eps and T_L reversed"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  }
}

TEST(OperatingPoints, SplitALeakFromADeliveryLoss) {
  // One point cannot tell a case drain from line A and a cross-port leak apart, nor a leak
  // from a delivery loss; the load and the stroke can: a leak grows with the pressure
  // across it, a delivery loss with displacement × speed. The product Dp·eps stays.
  const ct::LoadedCircuit c = load_hst45();
  const ct::OperatingPointSplit s =
      ct::split_by_operating_point(c, ct::steady_fault_tables(), ct::SignatureParts::kFull);
  EXPECT_GT(s.points.size(), 3u);
  EXPECT_TRUE(split_pair(s, "R_ext_a-", "R_ip-"));
  EXPECT_TRUE(split_pair(s, "R_ip-", "Dp-"));
  EXPECT_FALSE(split_pair(s, "Dp-", "eps-"));
  EXPECT_FALSE(split_pair(s, "R_ip-", "R_im-"));
  ASSERT_EQ(s.pairs.size(), s.where.size());
}

TEST(CandidateClass, OneCandidateIsNamed) {
  const ct::LoadedCircuit c = load_hst45();
  const ct::CandidateClass k = ct::candidate_class(c, {"R_ext_b-"});
  EXPECT_EQ(k.description, "a leak from line B to tank");
  EXPECT_EQ(k.split_by, "");
  EXPECT_EQ(k.sentence, "a leak from line B to tank: R_ext_b-");
  EXPECT_EQ(ct::candidate_class(c, {}).sentence, "");
}

TEST(CandidateClass, CrossPortLeaksNeedAFlowMeter) {
  // Pump and motor cross-port leakage: one laminar law between the same two lines at
  // every operating point; only a flow measured on one of the two paths splits them.
  const ct::LoadedCircuit c = load_hst45();
  const ct::CandidateClass k = ct::candidate_class(c, {"R_ip-", "R_im-"});
  EXPECT_EQ(k.description, "a leak between line A and line B");
  EXPECT_EQ(k.groups_now, 1);
  EXPECT_EQ(k.groups_split, 2);
  EXPECT_EQ(k.split_by.rfind("a flow meter on leak_", 0), 0u) << k.split_by;
  EXPECT_EQ(k.sentence, "a leak between line A and line B: R_ip-, R_im- (" + k.split_by + " would tell them apart)");
}

TEST(CandidateClass, LeaksFromOneLineSplitByTheOperatingPoint) {
  const ct::LoadedCircuit c = load_hst45();
  const ct::CandidateClass k = ct::candidate_class(c, {"R_ext_a-", "R_ip-", "Dp-"});
  EXPECT_EQ(k.description, "a flow loss from line A (a leak or a delivery loss)");
  EXPECT_EQ(k.groups_now, 1);
  EXPECT_GE(k.groups_split, 2);
  EXPECT_EQ(k.split_by.rfind("a change of operating point (", 0), 0u) << k.split_by;
}

TEST(CandidateClass, ProductsStayTogether) {
  // Dp·eps: no sensor and no operating point splits a displacement from its stroke.
  const ct::LoadedCircuit c = load_hst45();
  const ct::CandidateClass k = ct::candidate_class(c, {"Dp-", "eps-"});
  EXPECT_EQ(k.description, "a delivery loss at pump");
  EXPECT_EQ(k.split_by, "nothing in reach");
  EXPECT_EQ(k.groups_split, 1);
  EXPECT_NE(k.sentence.find("nothing in reach tells them apart"), std::string::npos) << k.sentence;
}

TEST(CandidateClass, IsolablePairsNeedMoreData) {
  // A motor displacement loss and a sensor fault differ at the nominal point already.
  const ct::LoadedCircuit c = load_hst45();
  const ct::CandidateClass k = ct::candidate_class(c, {"Dm-", "sensor_p_c"});
  EXPECT_EQ(k.groups_now, 2);
  EXPECT_EQ(k.split_by, "more settled data at a steady operating point");
}

TEST(CandidateClass, VerdictCandidatesAreTheLastEventsConsistentOnes) {
  hstmon::host::ReplayEvent e;
  e.event = "ambiguous";
  e.consistent = 2;
  for (const char* f : {"R_ip-", "R_im-", "Dp-"}) {
    hstmon::host::ReplayCandidate k;
    k.fault = f;
    e.candidates.push_back(k);
  }
  EXPECT_EQ(ct::verdict_candidates({e}), (std::vector<std::string>{"R_ip-", "R_im-"}));
  e.event = "isolated";  // the one named, however many are still consistent
  EXPECT_EQ(ct::verdict_candidates({e}), (std::vector<std::string>{"R_ip-"}));
  hstmon::host::ReplayEvent cleared;
  cleared.event = "cleared";
  EXPECT_TRUE(ct::verdict_candidates({e, cleared}).empty());
  EXPECT_TRUE(ct::verdict_candidates({}).empty());
}

}  // namespace
