// hstmon gap --circuit's diagnosis (hstmon_gap circuit_gap.hpp) on logs of a machine
// that has an effect the circuit file lacks: the machine is the shipped paper.json with
// one more component written into its JSON (a leak at the motor inlet, friction on the
// motor shaft), simulated by host_sim's reference; the tool gets the shipped file. It must
// name the effect, fit its size, and shrink the withheld log's residual; on the
// machine without the effect it must say there is no gap, also logged through a coarse
// ADC at 100 Hz or at 4.8 kHz with a pump's ripple on every pressure.
#include <gtest/gtest.h>

#include <cmath>
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

// What the logger does to the simulated readings before they reach the file.
struct Logger {
  double rate = 200.0;    ///< [Hz]
  double adc_step = 0.0;  ///< every pressure reading rounded to this [Pa]; 0: none
  double ripple = 0.0;    ///< amplitude of a sinusoid added to every pressure [Pa]
  double ripple_hz = 20.0;
};

ct::CircuitLog run(const ct::LoadedCircuit& m, const std::vector<std::string>& steps, double duration,
                   std::uint64_t seed, const Logger& logger = {}) {
  ct::CircuitSimOptions o = hstmon_test::sim_options(duration, logger.rate, seed);
  for (const auto& s : steps) {
    ct::InputStep st;
    EXPECT_FALSE(ct::parse_input_step(s, m.file, st).has_value()) << s;
    o.steps.push_back(st);
  }
  ct::CircuitLog log = ct::simulate_circuit(m, o);
  for (std::size_t ch = 0; ch < log.sensors.size() && ch < m.file.sensors.size(); ++ch) {
    if (m.file.sensors[ch].quantity != hstmon::host::CircuitQuantity::kPressure) continue;
    for (std::size_t k = 0; k < log.sensors[ch].size(); ++k) {
      double& y = log.sensors[ch][k];
      y += logger.ripple * std::sin(2.0 * M_PI * logger.ripple_hz * log.t[k]);
      if (logger.adc_step > 0.0) y = logger.adc_step * std::round(y / logger.adc_step);
    }
  }
  return log;
}

hstmon::gap::CircuitGapResult gap_of(const ct::LoadedCircuit& machine, const Logger& logger = {}) {
  // The tool knows only the shipped circuit; it reads the machine's logs by column name,
  // as a file.
  const ct::LoadedCircuit model = hstmon_test::load_example("paper");
  auto as_file = [&](const ct::CircuitLog& log) {
    const ct::CircuitLog back = ct::parse_circuit_log(ct::circuit_log_text(machine.file, log), "machine.csv", model.file);
    EXPECT_TRUE(back.ok()) << back.error->to_string();
    return back;
  };
  const ct::CircuitLog fit =
      as_file(run(machine, {"A_prv=2.5 mm2@4", "A_prv=4 mm2@8", "A_dcv=4 mm2@12"}, 16.0, 1, logger));
  const ct::CircuitLog check = as_file(run(machine, {"A_prv=3 mm2@4", "A_dcv=6 mm2@8"}, 12.0, 2, logger));
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

// The successive differences of a 0.1 bar ADC at 100 Hz read ~0 (the sensor's 0.05 bar
// noise is under the step); the floor is the step's q/√12.
TEST(CircuitGap, NoGapThroughACoarseAdcAt100Hz) {
  const auto r = gap_of(hstmon_test::load_example("paper"), {100.0, 1e4, 0.0});
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.verdict, "none");
}

// A ±0.6 bar, 20 Hz ripple on every pressure at 4.8 kHz: ten times the successive
// differences' noise, which the moving-mean scatter holds.
TEST(CircuitGap, NoGapWithRippleAt4k8) {
  const auto r = gap_of(hstmon_test::load_example("paper"), {4800.0, 0.0, 0.6e5});
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  EXPECT_EQ(r.verdict, "none");
}

}  // namespace
