// Input faults in the circuit simulator: from the fault's time the machine gets the factor
// times the input the log records, and the log keeps the setting (a PRV half blocked is
// kp−, not a new PRV setting). `--fault NAME=FACTOR@T` reads a parameter's name as a
// parameter fault and an input's name as an input fault.
#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <string>

#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_circuit/circuit_sim.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

ct::CircuitSimOptions quiet(double duration) {
  ct::CircuitSimOptions o;
  o.duration = duration;
  o.rate = 100.0;
  o.noise = false;
  return o;
}

TEST(SimInputFault, MachineGetsTheFactorAndTheLogKeepsTheSetting) {
  const ct::LoadedCircuit c = hstmon_test::load_example("thesis");
  const int kp = c.file.input_index("kp");
  ASSERT_GE(kp, 0);
  const double setting = c.values.inputs.v[kp];

  ct::CircuitSimOptions faulted = quiet(2.0);
  ct::InputStep f;
  ASSERT_FALSE(ct::parse_param_fault("kp=0.5@1", c.file, f).has_value());
  EXPECT_TRUE(f.input_fault);
  EXPECT_EQ(f.input, kp);
  EXPECT_EQ(f.param, -1);
  faulted.steps.push_back(f);
  const ct::CircuitLog a = ct::simulate_circuit(c, faulted);

  ct::CircuitSimOptions stepped = quiet(2.0);
  ct::InputStep s;
  s.t = 1.0;
  s.input = kp;
  s.value = 0.5 * setting;
  stepped.steps.push_back(s);
  const ct::CircuitLog b = ct::simulate_circuit(c, stepped);

  ASSERT_EQ(a.rows(), b.rows());
  for (std::size_t k = 0; k < a.rows(); ++k) {
    EXPECT_EQ(a.inputs[static_cast<std::size_t>(kp)][k], setting) << "row " << k;
    for (std::size_t ch = 0; ch < a.sensors.size(); ++ch) {
      ASSERT_EQ(a.sensors[ch][k], b.sensors[ch][k]) << c.file.sensors[ch].name << " row " << k;
    }
  }
  const std::size_t p_pp = 2;
  ASSERT_EQ(c.file.sensors[p_pp].name, "p_pp");
  EXPECT_GT(a.sensors[p_pp].back() - a.sensors[p_pp][99], 10e5);  // half the PRV area: Ppp far higher
}

TEST(SimInputFault, ParameterNamesStayParameterFaultsAndUnknownNamesListBoth) {
  const ct::LoadedCircuit c = hstmon_test::load_example("thesis");
  ct::InputStep f;
  ASSERT_FALSE(ct::parse_param_fault("Rf=1.2@3", c.file, f).has_value());
  EXPECT_FALSE(f.input_fault);
  EXPECT_EQ(f.param, c.file.param_index("Rf"));
  EXPECT_EQ(f.input, -1);
  EXPECT_EQ(f.factor, 1.2);
  const std::optional<std::string> err = ct::parse_param_fault("nope=0.5@1", c.file, f);
  ASSERT_TRUE(err.has_value());
  EXPECT_NE(err->find("no parameter or input 'nope'"), std::string::npos) << *err;
  EXPECT_NE(err->find("inputs: Psupl, Ps, Pbp, kp"), std::string::npos) << *err;
  EXPECT_TRUE(ct::parse_param_fault("kp=0@1", c.file, f).has_value());  // a factor must be > 0
}

}  // namespace
