// The rig conditions of hstmon-sim on any circuit: a transducer lag on every channel, the
// pressure channels through an ADC over their range (or a fixed step), and a machine off
// its parameter file (machine_spread.hpp). Each is off by default, changes only what it
// names, and is written in the log's comments; the thesis scenarios and their options are
// refused on a circuit without the thesis rig's inputs, naming what to use instead.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <stdexcept>
#include <string>

#include "../support/cli_run.hpp"
#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_circuit/machine_spread.hpp"

namespace {

using hstmon::circuit_tools::CircuitLog;
using hstmon::circuit_tools::CircuitSimOptions;
using hstmon::circuit_tools::LoadedCircuit;
using hstmon::circuit_tools::simulate_circuit;

// paper.json without noise: 2 s at 1 kHz, the PRV closed by a fifth at 0.5 s (the load rises).
CircuitSimOptions quiet_step_run(const LoadedCircuit& c) {
  CircuitSimOptions o;
  o.duration = 2.0;
  o.rate = 1000.0;
  o.noise = false;
  hstmon::circuit_tools::InputStep s;
  s.t = 0.5;
  s.input = 1;  // A_prv
  s.value = c.values.inputs.v[1] * 0.8;
  o.steps.push_back(s);
  return o;
}

bool is_pressure(const LoadedCircuit& c, std::size_t ch) {
  return c.file.sensors[ch].quantity == hstmon::host::CircuitQuantity::kPressure;
}

TEST(SimTransducers, AdcPutsEveryPressureOnItsRangesGridAndLeavesSpeedAlone) {
  const LoadedCircuit c = hstmon_test::load_example("paper");
  CircuitSimOptions o = quiet_step_run(c);
  const CircuitLog ideal = simulate_circuit(c, o);
  o.transducers.pressure_adc_bits = 10;
  const CircuitLog adc = simulate_circuit(c, o);
  ASSERT_EQ(adc.rows(), ideal.rows());
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    const auto& s = c.file.sensors[ch];
    const double step = (s.hi - s.lo) / 1023.0;
    for (std::size_t k = 0; k < adc.rows(); ++k) {
      if (!is_pressure(c, ch)) {
        ASSERT_EQ(adc.sensors[ch][k], ideal.sensors[ch][k]) << s.name << " row " << k;
        continue;
      }
      const double codes = (adc.sensors[ch][k] - s.lo) / step;
      ASSERT_NEAR(codes, std::round(codes), 1e-6) << s.name << " row " << k;
      ASSERT_LE(std::fabs(adc.sensors[ch][k] - ideal.sensors[ch][k]), 0.5 * step * (1.0 + 1e-9)) << s.name;
    }
  }
}

TEST(SimTransducers, PressureStepQuantisesThePressuresOnly) {
  const LoadedCircuit c = hstmon_test::load_example("paper");
  CircuitSimOptions o = quiet_step_run(c);
  o.transducers.pressure_step = 0.1e5;  // 0.1 bar
  const CircuitLog q = simulate_circuit(c, o);
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    if (!is_pressure(c, ch)) continue;
    for (const double v : q.sensors[ch]) ASSERT_NEAR(v / 0.1e5, std::round(v / 0.1e5), 1e-6);
  }
}

TEST(SimTransducers, LagTrailsAStepAndSettlesOnTheIdealReading) {
  const LoadedCircuit c = hstmon_test::load_example("paper");
  CircuitSimOptions o = quiet_step_run(c);
  const CircuitLog ideal = simulate_circuit(c, o);
  o.transducers.lag = 0.02;  // 20 ms
  const CircuitLog lagged = simulate_circuit(c, o);
  const std::size_t p = 2;  // p_pp, the loading pump's pressure
  ASSERT_EQ(c.file.sensors[p].name, "p_pp");
  const std::size_t before = 499, after = 510, settled = 1999;  // rows: 0.499 s, 10 ms after the step, 2 s
  const double at_step = ideal.sensors[p][before];
  EXPECT_NEAR(lagged.sensors[p][before], at_step, 1e-9 * at_step);  // a steady start reads steady
  const double rise = ideal.sensors[p][after] - at_step;
  ASSERT_GT(rise, 0.1e5);  // the load step raises p_pp by more than 0.1 bar within 10 ms
  EXPECT_LT(lagged.sensors[p][after] - lagged.sensors[p][before], 0.5 * rise);  // 20 ms lag: about a fifth of it
  EXPECT_NEAR(lagged.sensors[p][settled], ideal.sensors[p][settled], 1e-3 * ideal.sensors[p][settled]);
}

TEST(SimTransducers, BadTransducersAreRefused) {
  const LoadedCircuit c = hstmon_test::load_example("paper");
  CircuitSimOptions o = quiet_step_run(c);
  o.transducers.lag = -1e-3;
  EXPECT_THROW(simulate_circuit(c, o), std::runtime_error);
  o.transducers.lag = 0.0;
  o.transducers.pressure_adc_bits = 53;
  EXPECT_THROW(simulate_circuit(c, o), std::runtime_error);
}

TEST(MachineSpread, MovesOnlyTheUncertainParametersWithinTheSpreadAndRepeatsBySeed) {
  const LoadedCircuit c = hstmon_test::load_example("closed_loop_hst");
  std::mt19937_64 a(7), b(7), z(7);
  const LoadedCircuit m1 = hstmon::circuit_tools::spread_machine(c, 0.02, a);
  const LoadedCircuit m2 = hstmon::circuit_tools::spread_machine(c, 0.02, b);
  const LoadedCircuit same = hstmon::circuit_tools::spread_machine(c, 0.0, z);
  int moved = 0;
  for (std::size_t p = 0; p < c.file.params.size(); ++p) {
    const double v = c.values.params.v[p], v1 = m1.values.params.v[p];
    EXPECT_EQ(v1, m2.values.params.v[p]) << c.file.params[p].name;
    EXPECT_EQ(same.values.params.v[p], v) << c.file.params[p].name;
    if (!hstmon::circuit_tools::moves_steady_state(c.file.params[p])) {
      EXPECT_EQ(v1, v) << c.file.params[p].name;
      continue;
    }
    EXPECT_LE(std::fabs(v1 - v), 0.02 * std::fabs(v) * (1.0 + 1e-12)) << c.file.params[p].name;
    if (v1 != v) ++moved;
  }
  EXPECT_GT(moved, 3);
}

const std::string kSim = std::string("'") + HSTMON_SIM + "'";
const std::string kPaper = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/paper.json";

TEST(SimTransducersCli, RigConditionsRunOnACircuitAndAreWrittenInTheLog) {
  const hstmon_test::CliRun r = hstmon_test::run_command(
      kSim + " --circuit '" + kPaper +
      "' --duration 0.2 --rate 100 --lag 5 --adc-bits 12 --param-error 0.02 --machine-seed 3 --out - 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("transducers: lag 5 ms, pressure ADC 12 bits"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("machine: every uncertain parameter off the file by uniform ±0.02 (machine seed 3)"),
            std::string::npos)
      << r.out;
}

TEST(SimTransducersCli, ThesisScenarioOptionsAreRefusedWithWhatToUseInstead) {
  hstmon_test::CliRun r = hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --load steps --out - 2>&1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("--load sets up --scenario rig (on any run, --step and --fault)"), std::string::npos) << r.out;
  r = hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --scenario prv_blockage --out - 2>&1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("--scenario prv_blockage is the thesis rig's: it sets the inputs Psupl, Ps, Pbp and kp, and "
                       "circuit paper has no input 'Psupl'"),
            std::string::npos)
      << r.out;
  r = hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --preset fast --out - 2>&1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("--preset fast has no channel for sensor 'p_s' of circuit paper"), std::string::npos) << r.out;
}

// --units and --rpm choose the log's units on a circuit too; the replay reads them back.
TEST(SimTransducersCli, UnitsAndRpmChooseTheLogsUnits) {
  const hstmon_test::CliRun r =
      hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --duration 0.05 --units Pa --rpm --out - 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("t[s],a_dcv[mm2],a_prv[mm2],p_s[Pa],p_mi[Pa],p_pp[Pa],w_m[rpm]"), std::string::npos) << r.out;
  const hstmon_test::CliRun bar =
      hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --duration 0.05 --units bar --out - 2>&1");
  ASSERT_EQ(bar.exit_code, 0) << bar.out;
  EXPECT_NE(bar.out.find(",p_s[bar],"), std::string::npos) << bar.out;
}

// --list names the inputs, parameters and sensors --step, --fault and a log take.
TEST(SimTransducersCli, ListNamesWhatACircuitTakes) {
  const hstmon_test::CliRun r = hstmon_test::run_command(kSim + " --circuit '" + kPaper + "' --list 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* want : {"A_prv  area, column a_prv [mm2], nominal 3.525e-06 m2", "Rmlkg  6e+11 Pa*s/m3",
                           "w_m  speed, column w_m [rpm], noise σ"}) {
    EXPECT_NE(r.out.find(want), std::string::npos) << want << "\n" << r.out;
  }
}

}  // namespace
