// hstmon gap --circuit's diagnosis (hstmon_gap circuit_gap.hpp) on logs of a machine
// that has an effect the circuit file lacks: the machine is the shipped paper.json with
// one more component written into its JSON (a leak at the motor inlet, friction on the
// motor shaft), simulated by host_sim's reference; the tool gets the shipped file. It must
// name the effect, fit its size, and shrink the withheld log's residual; on the
// machine without the effect it must say there is no gap.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/loaded_circuit.hpp"
#include "../support/sim_options.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_gap/circuit_gap.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
namespace fs = std::filesystem;

const std::string kDir = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/";

// paper.json plus `component` (named `name`) with parameter `param` = value, as files.
ct::LoadedCircuit machine_with(const std::string& name, const nlohmann::ordered_json& component, const std::string& param,
                               const std::string& quantity, double value) {
  nlohmann::ordered_json c = nlohmann::ordered_json::parse(std::ifstream(kDir + "paper.json"));
  nlohmann::ordered_json p = nlohmann::ordered_json::parse(std::ifstream(kDir + "paper.params.json"));
  c["parameters"][param] = {{"quantity", quantity}};
  c["components"][name] = component;
  p["params"][param] = value;
  const fs::path dir = fs::temp_directory_path();
  const std::string cf = (dir / ("hstmon_gap_" + name + ".json")).string();
  const std::string pf = (dir / ("hstmon_gap_" + name + ".params.json")).string();
  std::ofstream(cf) << c.dump(1);
  std::ofstream(pf) << p.dump(1);
  return hstmon_test::load_circuit_file(cf, pf);
}

ct::CircuitLog run(const ct::LoadedCircuit& m, const std::vector<std::string>& steps, double duration, std::uint64_t seed) {
  ct::CircuitSimOptions o = hstmon_test::sim_options(duration, 200.0, seed);
  for (const auto& s : steps) {
    ct::InputStep st;
    EXPECT_FALSE(ct::parse_input_step(s, m.file, st).has_value()) << s;
    o.steps.push_back(st);
  }
  return ct::simulate_circuit(m, o);
}

hstmon::gap::CircuitGapResult gap_of(const ct::LoadedCircuit& machine) {
  // The tool knows only the shipped circuit; it reads the machine's logs by column name,
  // as a file.
  const ct::LoadedCircuit model = hstmon_test::load_example("paper");
  auto as_file = [&](const ct::CircuitLog& log) {
    const ct::CircuitLog back = ct::parse_circuit_log(ct::circuit_log_text(machine.file, log), "machine.csv", model.file);
    EXPECT_TRUE(back.ok()) << back.error->to_string();
    return back;
  };
  const ct::CircuitLog fit = as_file(run(machine, {"A_prv=2.5 mm2@4", "A_prv=4 mm2@8", "A_dcv=4 mm2@12"}, 16.0, 1));
  const ct::CircuitLog check = as_file(run(machine, {"A_prv=3 mm2@4", "A_dcv=6 mm2@8"}, 12.0, 2));
  return hstmon::gap::circuit_gap(model, fit, check);
}

TEST(CircuitGap, NamesAnUnmodelledLeakAndItsSize) {
  const auto m = machine_with("extra_leak", {{"type", "laminar_leakage"}, {"from", "Pmi"}, {"to", "tank"}, {"R", "Rx"}},
                              "Rx", "resistance", 1e12);
  const auto r = gap_of(m);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.verdict, "leak(Pmi)");
  ASSERT_FALSE(r.ranked.empty());
  EXPECT_NEAR(r.ranked[0].magnitude * 1e12, 1.0, 0.03);  // conductance 1/Rx
  EXPECT_LT(r.ranked[0].rms_check, 0.1 * r.rms_check);
}

TEST(CircuitGap, NamesUnmodelledShaftFriction) {
  const auto m = machine_with("extra_friction", {{"type", "friction"}, {"shaft", "motor"}, {"c", "Cx"}}, "Cx", "damping",
                              0.004);
  const auto r = gap_of(m);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.verdict, "friction(motor)");
  EXPECT_NEAR(r.ranked[0].magnitude / 0.004, 1.0, 0.03);
}

TEST(CircuitGap, NoGapOnTheModelledMachine) {
  const auto r = gap_of(hstmon_test::load_example("paper"));
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.verdict, "none");
}

}  // namespace
