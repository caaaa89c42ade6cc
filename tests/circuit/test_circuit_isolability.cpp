// Detectability, isolability classes and sensor placement of the shipped circuits
// (circuit_isolability.hpp): what their physics says can and cannot be told apart, on the
// steady signature and on the monitor's table (slopes and orders too), and the JSON of
// `hstmon-fdi isolability --circuit`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

#include "../support/cli_run.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
using ChannelSig = hstmon::ChannelSignature;

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

// A two-channel table of hand-made rows; the entries past them read as circuit_fault_table
// writes them (0, slope ?, order 0, no direction).
struct Hand {
  ct::CircuitFaultTable t;
  void add(const std::string& name, ChannelSig ch0, ChannelSig ch1, float d0, float d1) {
    t.names.push_back(name);
    ct::CircuitFaultTable::Row r{};
    r.sensor = false;
    for (int i = 0; i < ct::CircuitFaultTable::Row::kChannels; ++i) r.channel[i] = {hstmon::kQualZero, hstmon::kQualAny, 0};
    r.channel[0] = ch0;
    r.channel[1] = ch1;
    r.direction[0] = d0;
    r.direction[1] = d1;
    t.rows.push_back(r);
  }
  ct::CircuitFaultTable done() {
    for (std::size_t k = 0; k < t.rows.size(); ++k) t.rows[k].name = t.names[k].c_str();
    return std::move(t);
  }
};

std::size_t at(const ct::Isolability& r, const std::string& f) {
  return static_cast<std::size_t>(std::find(r.faults.begin(), r.faults.end(), f) - r.faults.begin());
}

TEST(CircuitIsolability, SlopeOrOrderSplitsWhatTheSteadySignatureCannot) {
  using hstmon::kQualAny;
  using hstmon::kQualPlus;
  using hstmon::kQualZero;
  Hand h;
  // Same magnitudes, parallel directions; a reaches channel 0 first, b channel 1: under a
  // the matcher sees channel 0 alarm alone first, where b's smallest order is channel 1's.
  h.add("a+", {kQualPlus, kQualPlus, 1}, {kQualPlus, kQualPlus, 2}, 0.8f, 0.6f);
  h.add("b+", {kQualPlus, kQualPlus, 2}, {kQualPlus, kQualPlus, 1}, 0.8f, 0.6f);
  // Parallel too, c's 0 on channel 1 only small (its direction is not 0 there): the steady
  // rule lets a smaller d look like c. But c's slope there is a known 0, d's a +.
  h.add("c+", {kQualPlus, kQualPlus, 0}, {kQualZero, kQualZero, 0}, 0.99995f, 0.01f);
  h.add("d+", {kQualPlus, kQualPlus, 0}, {kQualPlus, kQualPlus, 0}, 0.99995f, 0.01f);
  const ct::CircuitFaultTable t = h.done();

  const ct::Isolability steady = ct::circuit_isolability(t, ct::SignatureParts::kSteadyOnly);
  EXPECT_TRUE(same_class(steady, "a+", "b+"));
  EXPECT_TRUE(same_class(steady, "c+", "d+"));

  const ct::Isolability full = ct::circuit_isolability(t);
  const std::size_t a = at(full, "a+"), b = at(full, "b+"), c = at(full, "c+"), d = at(full, "d+");
  EXPECT_EQ(full.isolable[a][b], 1);
  EXPECT_EQ(full.split[a][b], unsigned{ct::kSplitOrder});
  EXPECT_EQ(full.isolable[c][d], 1);
  EXPECT_EQ(full.split[c][d], unsigned{ct::kSplitSlope});
  EXPECT_EQ(full.split[b][a], full.split[a][b]);
  EXPECT_FALSE(same_class(full, "a+", "b+"));
  EXPECT_FALSE(same_class(full, "c+", "d+"));

  // Orders unknown on one side (all 0: the table's "any channel first") split nothing.
  Hand u;
  u.add("a+", {kQualPlus, kQualPlus, 1}, {kQualPlus, kQualPlus, 2}, 0.8f, 0.6f);
  u.add("e+", {kQualPlus, kQualAny, 0}, {kQualPlus, kQualAny, 0}, 0.8f, 0.6f);
  const ct::Isolability unknown = ct::circuit_isolability(u.done());
  EXPECT_EQ(unknown.split[0][1], 0u);
  EXPECT_TRUE(same_class(unknown, "a+", "e+"));
}

TEST(CircuitIsolability, MonitorTableKeepsTheThesisClassesTheCampaignConfuses) {
  // thesis.json's campaign (docs/fault_campaign.md) confuses Dm- with Rbl+, Rbl± with Rf±
  // and Pbp± with sensor_p_pp; the monitor's table keeps these orders 0 (p_pp, their most
  // visible channel, is not on the fastest path) and slopes equal to the steady signs, so
  // its relation predicts the same classes and weak pairs as the steady one.
  const ct::LoadedCircuit c = load("thesis");
  const ct::Isolability full = ct::circuit_isolability(hstmon::fdi::circuit_signature_table(c));
  const ct::Isolability steady = ct::circuit_isolability(ct::circuit_fault_table(c), ct::SignatureParts::kSteadyOnly);
  EXPECT_EQ(full.classes, steady.classes);
  EXPECT_EQ(full.weak, steady.weak);
  EXPECT_TRUE(same_class(full, "Pbp+", "sensor_p_pp"));
  EXPECT_TRUE(weak(full, "Dm-", "Rbl+"));
  EXPECT_TRUE(weak(full, "Rf+", "Rbl+"));
  // Where both slopes are known and opposite, the magnitudes are too (a slope is kept only
  // where it is the steady sign): Dm+/Dm- is split by both.
  const std::size_t p = at(full, "Dm+"), m = at(full, "Dm-");
  EXPECT_EQ(full.split[p][m], unsigned{ct::kSplitSteady | ct::kSplitSlope});
}

TEST(CircuitIsolability, ClosedLoopOrdersSplitTheMotorFromTheChargeCircuit) {
  // The charge circuit's faults reach p_c first (order 1), the motor's displacement p_a,
  // p_b and w_m (order 1) and p_c only at order 2: the matcher's order test tells them
  // apart as well as their steady signatures do.
  const ct::Isolability r = ct::circuit_isolability(hstmon::fdi::circuit_signature_table(load("closed_loop_hst")));
  for (const char* charge : {"Dc+", "Dc-", "k_charge+", "p_charge-"}) {
    EXPECT_TRUE(r.split[at(r, "Dm+")][at(r, charge)] & ct::kSplitOrder) << charge;
    EXPECT_TRUE(r.split[at(r, "Dm-")][at(r, charge)] & ct::kSplitOrder) << charge;
  }
  EXPECT_EQ(r.split[at(r, "Dp+")][at(r, "eps+")], 0u);  // one product: nothing splits them
}

TEST(CircuitIsolability, AddedSensorsAreRankedOnTheMonitorsTable) {
  // The added channel's slopes and orders come from the same causal graph: q(pump) still
  // separates the test stand's leak from a low delivery best.
  const auto ranked = ct::rank_added_sensors(load("test_stand"), hstmon::fdi::signature_fault_tables());
  ASSERT_FALSE(ranked.empty());
  EXPECT_EQ(ranked.front().name, "q(pump)");
  EXPECT_GE(ranked.front().weak_cleared, 1);
}

std::string run(const std::string& cmd) {
  const hstmon_test::CliRun r = hstmon_test::run_command(cmd);
  EXPECT_EQ(r.exit_code, 0) << cmd;
  return r.out;
}

TEST(CircuitIsolability, JsonSaysWhatSplitsEachPair) {
  const std::string base = std::string(HSTMON_FDI) + " isolability --json --circuit " + HSTMON_SOURCE_DIR +
                           "/examples/circuits/thesis.json";
  for (const bool steady_only : {false, true}) {
    const nlohmann::json j = nlohmann::json::parse(run(base + (steady_only ? " --steady-only" : "")), nullptr, false);
    ASSERT_FALSE(j.is_discarded());
    EXPECT_EQ(j["relation"], steady_only ? "steady" : "full");
    const auto faults = j["faults"].get<std::vector<std::string>>();
    const auto split = j["split"];
    ASSERT_EQ(split.size(), faults.size());
    const auto idx = [&](const std::string& f) { return static_cast<std::size_t>(std::find(faults.begin(), faults.end(), f) - faults.begin()); };
    const std::size_t p = idx("Dm+"), m = idx("Dm-"), pbp = idx("Pbp+"), s = idx("sensor_p_pp"), rbl = idx("Rbl+"), dm = idx("Dm-");
    ASSERT_LT(std::max({p, m, pbp, s, rbl}), faults.size());
    EXPECT_TRUE(split[p][p].empty());
    EXPECT_TRUE(split[pbp][s].empty());  // not isolable: nothing splits them
    EXPECT_EQ(split[rbl][dm], nlohmann::json::array({"steady-weak"}));
    EXPECT_EQ(split[p][m], steady_only ? nlohmann::json::array({"steady"}) : nlohmann::json::array({"steady", "slope"}));
    EXPECT_EQ(j["matrix"][p][m], 1);
  }
}

TEST(CircuitIsolability, JsonSaysWhatAChangeOfOperatingPointSplits) {
  // hst45 (the open validation circuit): a leak and a delivery loss look alike at the
  // nominal point; at half the engine speed the delivery loss halves, the leak does not.
  const nlohmann::json j =
      nlohmann::json::parse(run(std::string(HSTMON_FDI) + " isolability --json --circuit " + HSTMON_SOURCE_DIR +
                                "/tests/data/validation_circuits/circuit.json"),
                            nullptr, false);
  ASSERT_FALSE(j.is_discarded());
  EXPECT_EQ(j["operating_points"][0], "nominal");
  bool leak_vs_delivery = false;
  for (const auto& e : j["split_by_operating_point"]) {
    const auto pair = e["pair"].get<std::vector<std::string>>();
    leak_vs_delivery = leak_vs_delivery || (pair == std::vector<std::string>{"Dp-", "R_ip-"});
    EXPECT_TRUE(e["at"].is_string());
  }
  EXPECT_TRUE(leak_vs_delivery) << j["split_by_operating_point"].dump();
  // The product Dp·eps·n_e stays one class at every point.
  bool product = false;
  for (const auto& cls : j["classes_across_operating_points"]) {
    const auto v = cls.get<std::vector<std::string>>();
    product = product || (std::count(v.begin(), v.end(), "Dp-") && std::count(v.begin(), v.end(), "eps-"));
  }
  EXPECT_TRUE(product) << j["classes_across_operating_points"].dump();
}

}  // namespace
