// hstmon identify --circuit's fit (hstmon_ident circuit_fit.hpp) on logs of host_sim's
// reference: parameters changed in the simulated machine are recovered from its steady
// operating points; what the points cannot tell apart is said, not guessed; the
// parameter file it writes reads back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../support/loaded_circuit.hpp"
#include "../support/sim_options.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_host/circuit_values.hpp"
#include "hstmon_ident/circuit_fit.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
namespace id = hstmon::ident;

// A log of the machine c with parameters scaled as given, inputs stepped as given.
ct::CircuitLog machine_log(const ct::LoadedCircuit& c, const std::vector<std::pair<std::string, double>>& scale,
                           const std::vector<std::string>& steps, double duration) {
  ct::LoadedCircuit m;
  m.file = c.file;
  m.values = c.values;
  for (const auto& [name, f] : scale) m.values.params.v[c.file.param_index(name)] *= f;
  ct::CircuitSimOptions o = hstmon_test::sim_options(duration, 200.0, 3);
  for (const auto& s : steps) {
    ct::InputStep st;
    const auto err = ct::parse_input_step(s, c.file, st);
    EXPECT_FALSE(err.has_value()) << *err;
    o.steps.push_back(st);
  }
  return ct::simulate_circuit(m, o);
}

TEST(CircuitIdentify, RecoversChangedParametersOfThePaperRig) {
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  const auto log = machine_log(c, {{"Rmlkg", 0.8}, {"Rfric", 1.25}},
                               {"A_prv=2.5 mm2@4", "A_prv=3 mm2@8", "A_prv=4.5 mm2@12", "A_dcv=4 mm2@16"}, 20.0);
  id::CircuitFitOptions o;
  o.fit = {"Rmlkg", "Rfric"};
  const id::CircuitFitResult r = id::fit_circuit(c, {log}, o);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.points.size(), 5u);
  ASSERT_EQ(r.value.size(), 2u);
  EXPECT_NEAR(r.value[0] / c.values.params.v[c.file.param_index("Rmlkg")], 0.8, 0.005);
  EXPECT_NEAR(r.value[1] / c.values.params.v[c.file.param_index("Rfric")], 1.25, 0.005);
  EXPECT_GT(r.rms_before, 20.0);
  EXPECT_LT(r.rms_after, 1.0);  // down to the noise of the means
  EXPECT_TRUE(r.notes.empty()) << r.notes.front();

  // The file it writes is a parameter file of the circuit with the fitted values.
  const std::string text = id::fitted_values_json(c, r);
  const auto back = hstmon::host::parse_circuit_values_json(text, "fit.json", c.file);
  ASSERT_TRUE(back.ok()) << back.error->to_string();
  EXPECT_EQ(back.values->params.v[c.file.param_index("Rmlkg")], r.value[0]);
  EXPECT_EQ(back.values->params.v[c.file.param_index("Dm")], c.values.params.v[c.file.param_index("Dm")]);
}

TEST(CircuitIdentify, HoldsWhatThePointsCannotTellApart) {
  // Paper rig: both orifices' coefficient is Cd·A·√(2/ρ), so Cd and ρ enter only as Cd/√ρ.
  // ρ moves the fit half as much as Cd: it is held, and Cd carries the pair's effect.
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  const auto log = machine_log(c, {{"Cd", 0.95}}, {"A_prv=2.5 mm2@4", "A_prv=4 mm2@8"}, 12.0);
  id::CircuitFitOptions o;
  o.fit = {"Cd", "rho"};
  const id::CircuitFitResult r = id::fit_circuit(c, {log}, o);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  ASSERT_EQ(r.held.size(), 1u);
  EXPECT_EQ(r.held[0].name, "rho");
  EXPECT_NE(r.held[0].why.find("only together with Cd"), std::string::npos) << r.held[0].why;
  EXPECT_EQ(r.held[0].value, c.values.params.v[c.file.param_index("rho")]);
  ASSERT_EQ(r.names, std::vector<std::string>{"Cd"});
  EXPECT_NEAR(r.value[0] / c.values.params.v[c.file.param_index("Cd")], 0.95, 0.005);
}

TEST(CircuitIdentify, RefusesUnknownOrLiteralNames) {
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  id::CircuitFitOptions o;
  o.fit = {"Rnope"};
  const id::CircuitFitResult r = id::fit_circuit(c, {}, o);
  ASSERT_TRUE(r.error.has_value());
  EXPECT_NE(r.error->find("Rnope"), std::string::npos);
  o.fit = {};
  EXPECT_TRUE(id::fit_circuit(c, {}, o).error.has_value());
}

}  // namespace

namespace {

// A test stand whose bypass (not logged) shuts at 3 s while the inputs hold: the loading
// throttle's coefficient halves. The held stretch is split there, each side is its own
// operating point, and nothing is averaged across the switch.
TEST(CircuitIdentify, AnUnloggedEventSplitsTheHeldStretch) {
  const ct::LoadedCircuit c = hstmon_test::load_example("test_stand");
  ct::CircuitSimOptions o = hstmon_test::sim_options(6.0, 1000.0, 9);
  ct::InputStep shut;
  ASSERT_FALSE(ct::parse_param_fault("k_throttle=0.7@3", c.file, shut).has_value());
  o.steps.push_back(shut);
  const ct::CircuitLog log = ct::simulate_circuit(c, o);
  std::vector<std::string> notes;
  const auto points = id::circuit_operating_points(c, {log}, 0.2, &notes);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LT(points[0].t1, 3.0);
  EXPECT_GT(points[1].t0, 3.0);
  const int p_line = 0;
  EXPECT_GT(points[1].mean[p_line] - points[0].mean[p_line], 1e5) << "the throttle shut raises the line pressure";
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.front().find("while the inputs hold"), std::string::npos) << notes.front();
}

// A drive speed logged with its sensor's scatter (0.5 %, over the old fixed 0.5 %
// tolerance) still holds: the tolerance follows the input's own noise.
TEST(CircuitIdentify, AMeasuredInputsScatterStillHolds) {
  const ct::LoadedCircuit c = hstmon_test::load_example("test_stand");
  ct::CircuitSimOptions o = hstmon_test::sim_options(4.0, 1000.0);
  ct::CircuitLog log = ct::simulate_circuit(c, o);
  const int n = c.file.input_index("n_drive");
  ASSERT_GE(n, 0);
  std::uint32_t state = 12345u;
  for (double& v : log.inputs[static_cast<std::size_t>(n)]) {
    state = state * 1664525u + 1013904223u;
    const double uniform = (static_cast<double>(state >> 8) / 16777216.0) - 0.5;  // ±0.5
    v *= 1.0 + 0.01 * uniform * 1.7;  // about 0.5 % RMS
  }
  const auto points = id::circuit_operating_points(c, {log}, 0.2);
  EXPECT_EQ(points.size(), 1u);
}

}  // namespace
