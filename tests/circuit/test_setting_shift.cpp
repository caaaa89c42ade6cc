// A fault on a setting moves the element's whole characteristic (setting_shift.hpp): a
// relief valve's full-open pressure with its cracking pressure, a compensated pump's knee
// and dead-head pressures with its cut-in; a number another element shares stays put.
#include <gtest/gtest.h>

#include "circuit_fixture.hpp"
#include "hstmon/circuit/setting_shift.hpp"
#include "hstmon_circuit/circuit_faults.hpp"

namespace {

using circuit_test::load;
using circuit_test::load_paths;
using circuit_test::Model;
using hstmon::circuit::setting_companions;
using hstmon::circuit::SettingCompanions;

int param(const circuit_test::Loaded& l, const char* name) { return l.file.param_index(name); }

TEST(SettingShift, ReliefCrackingMovesItsFullOpenPressureAlong) {
  // hst45 (the independent simulator's closed-circuit HST): relief B cracks at 300 bar and
  // is fully open at 330 bar; its setting 45 % low is 165 … 195 bar, not 165 … 330 bar.
  const auto l = load_paths(std::string(HSTMON_SOURCE_DIR) + "/tests/data/validation_circuits/circuit.json",
                            std::string(HSTMON_SOURCE_DIR) + "/tests/data/validation_circuits/circuit.params.json",
                            1e-3);
  ASSERT_TRUE(l.ok);
  const int crack = param(l, "p_rv_b"), full = param(l, "p_rv_b_full");
  const SettingCompanions with = setting_companions(l.file.circuit, crack);
  EXPECT_EQ(with.index[0], full);
  EXPECT_EQ(with.index[1], -1);
  Model::Params p = l.values.params;
  hstmon::circuit_tools::apply_param_fault(l.file, p, l.values.params, static_cast<std::size_t>(crack), 0.55);
  EXPECT_DOUBLE_EQ(p.v[crack], 0.55 * 300e5);
  EXPECT_NEAR(p.v[full], 195e5, 1e-6);
  for (int k = 0; k < l.file.circuit.n_params; ++k) {
    if (k == crack || k == full) continue;
    EXPECT_EQ(p.v[k], l.values.params.v[k]) << l.file.params[static_cast<std::size_t>(k)].name;
  }
  // The full-open pressure is no setting: a fault on it is that number alone.
  EXPECT_EQ(setting_companions(l.file.circuit, full).index[0], -1);
  // Nor is a leak.
  EXPECT_EQ(setting_companions(l.file.circuit, param(l, "R_ext_b")).index[0], -1);
}

TEST(SettingShift, ReliefsThatShareTheirNumbersMoveTogether) {
  // closed_loop_hst: both crossport reliefs read p_hp_crack and p_hp; a fault on the
  // shared cracking pressure shifts the shared full-open pressure too.
  const auto l = load("closed_loop_hst", 1e-3);
  ASSERT_TRUE(l.ok);
  EXPECT_EQ(setting_companions(l.file.circuit, param(l, "p_hp_crack")).index[0], param(l, "p_hp"));
  EXPECT_EQ(setting_companions(l.file.circuit, param(l, "p_charge_crack")).index[0], param(l, "p_charge"));
}

TEST(SettingShift, CompensatorCutInMovesTheWholePumpCurve) {
  // paper.json: Pc 75, Pk 87, Pmax 90 bar; a 10 % lower compensator setting is
  // 67.5 / 79.5 / 82.5 bar, the curve's shape kept.
  const auto l = load("paper", 1e-3);
  ASSERT_TRUE(l.ok);
  const int pc = param(l, "Pc"), pk = param(l, "Pk"), pmax = param(l, "Pmax");
  const SettingCompanions with = setting_companions(l.file.circuit, pc);
  EXPECT_EQ(with.index[0], pk);
  EXPECT_EQ(with.index[1], pmax);
  Model::Params p = l.values.params;
  hstmon::circuit_tools::apply_param_fault(l.file, p, l.values.params, static_cast<std::size_t>(pc), 0.9);
  EXPECT_NEAR(p.v[pc], 67.5e5, 1e-6);
  EXPECT_NEAR(p.v[pk], 79.5e5, 1e-6);
  EXPECT_NEAR(p.v[pmax], 82.5e5, 1e-6);
  const Model m(l.file.circuit, p, l.values.inputs);
  EXPECT_TRUE(m.valid());
}

TEST(SettingShift, ANumberAnotherElementReadsIsNotDraggedAlong) {
  // Two reliefs with their own cracking pressures and one full-open pressure: a fault on
  // one cracking pressure would move the other valve's characteristic, so it moves alone.
  using Cap = hstmon::circuit::Capacity<4, 1, 4, 2, 2, 4>;
  hstmon::circuit::Circuit<Cap> c;
  c.n_nodes = 3;
  c.n_params = 4;
  for (int e = 0; e < 2; ++e) {
    hstmon::circuit::Element& el = c.elements[e];
    el.kind = hstmon::circuit::ElementKind::kPoppet;
    el.a = static_cast<std::uint8_t>(e);
    el.b = 2;
    el.r[hstmon::circuit::kK] = hstmon::circuit::param_ref(3);
    el.r[hstmon::circuit::kCrack] = hstmon::circuit::param_ref(e);
    el.r[hstmon::circuit::kFull] = hstmon::circuit::param_ref(2);
  }
  c.n_elements = 2;
  EXPECT_EQ(setting_companions(c, 0).index[0], -1);
  EXPECT_EQ(setting_companions(c, 1).index[0], -1);
  // With the valves' cracking pressures shared too, the pair moves as one.
  c.elements[1].r[hstmon::circuit::kCrack] = hstmon::circuit::param_ref(0);
  EXPECT_EQ(setting_companions(c, 0).index[0], 2);
}

}  // namespace
