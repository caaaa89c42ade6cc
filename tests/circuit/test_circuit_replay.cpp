// Each shipped circuit simulated in-process (hstmon-sim --circuit's code: full equations,
// Rosenbrock-4, the sensors' noise), then replayed through Observer<CircuitModel>
// (hstmon replay --circuit's code): residual RMS within 2× the sensor noise on every
// channel, for a start and an input step. The shipped logs examples/circuits/*.csv too.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "../support/loaded_circuit.hpp"
#include "../support/sim_options.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/circuit_sim.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

std::string example(const std::string& file) { return std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/" + file; }

ct::LoadedCircuit load(const std::string& name) {
  ct::LoadedCircuit c = hstmon_test::load_example(name);
  EXPECT_EQ(c.params_path, example(name + ".params.json"));
  return c;
}

// Every channel measured, residual RMS ≤ 2σ of its sensor, and a healthy observer.
void expect_noise_level(const ct::LoadedCircuit& c, const ct::CircuitReplayResult& r, const char* what) {
  ASSERT_EQ(r.channels.size(), c.file.sensors.size());
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const double sigma = c.file.sensors[ch].noise;
    ASSERT_GT(sigma, 0.0) << c.file.sensors[ch].name;
    EXPECT_TRUE(r.measured[ch]);
    EXPECT_EQ(r.channels[ch].n + r.clipped[ch], r.rows);
    const double ratio = r.channels[ch].rms() / sigma;
    std::printf("%-16s %-9s %-6s RMS/σ %.3f  mean/σ %+.3f\n", c.file.name.c_str(), what, c.file.sensors[ch].name.c_str(),
                ratio, r.channels[ch].mean() / sigma);
    EXPECT_LE(ratio, 2.0) << c.file.name << " " << c.file.sensors[ch].name << " (" << what << ")";
  }
  EXPECT_EQ(r.health, 0u) << c.file.name;
}

struct Case {
  const char* name;
  std::vector<std::string> steps;
};

TEST(CircuitReplay, SimulatedThenReplayedAtNoiseLevel) {
  const Case cases[] = {{"paper", {"A_prv=2.5 mm2@1"}},
                        {"closed_loop_hst", {"T_L=300 N*m@0.7", "eps=0.8@1.4"}},
                        {"test_stand", {"throttle=0.7@1"}}};
  for (const Case& k : cases) {
    const ct::LoadedCircuit c = load(k.name);
    ct::CircuitSimOptions o = hstmon_test::sim_options(2.0, 200.0, 7 + static_cast<std::uint64_t>(&k - cases));
    for (const std::string& s : k.steps) {
      ct::InputStep st;
      const auto err = ct::parse_input_step(s, c.file, st);
      ASSERT_FALSE(err.has_value()) << *err;
      o.steps.push_back(st);
    }
    const ct::CircuitLog log = ct::simulate_circuit(c, o);
    ASSERT_EQ(log.rows(), 400u);
    // Through the text a log file holds, as hstmon replay reads it.
    const ct::CircuitLog back = ct::parse_circuit_log(ct::circuit_log_text(c.file, log), "sim.csv", c.file);
    ASSERT_TRUE(back.ok()) << back.error->to_string();
    ASSERT_EQ(back.rows(), log.rows());
    const ct::CircuitReplayResult r = ct::replay_circuit(c, back, {});
    EXPECT_EQ(r.rows, 400u);
    expect_noise_level(c, r, "simulated");
  }
}

// A sample on a step: the thesis rig with a flow sensor at the DCV inlet
// (bench/circuits/thesis_q_dcv.json), supply stepped at a sample instant. The motor-inlet
// volume settles in microseconds; the sample must not show the flow reversing through the
// DCV in between (a transducer cannot), and the replay sees no spike there.
TEST(CircuitReplay, SampleOnAStepShowsTheFastVolumesSettled) {
  ct::LoadedCircuit c;
  ASSERT_FALSE(ct::load_circuit(std::string(HSTMON_SOURCE_DIR) + "/bench/circuits/thesis_q_dcv.json", "", c).has_value());
  ct::CircuitSimOptions o = hstmon_test::sim_options(1.0, 1000.0);
  o.noise = false;
  ct::InputStep st;
  ASSERT_FALSE(ct::parse_input_step("Psupl=30 bar@0.5", c.file, st).has_value());
  o.steps.push_back(st);
  const ct::CircuitLog log = ct::simulate_circuit(c, o);
  ASSERT_EQ(log.rows(), 1000u);
  std::size_t q = 0;
  while (q < c.file.sensors.size() && c.file.sensors[q].name != "q_in") ++q;
  ASSERT_LT(q, c.file.sensors.size());
  const std::vector<double>& flow = log.sensors[q];
  EXPECT_GT(flow[500], 0.5 * flow[499]) << "the sample on the step shows the flow reversing";
  EXPECT_NEAR(flow[500], flow[501], 0.05 * flow[499]);
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, {});
  EXPECT_LT(r.channels[q].max_abs, 0.02 * flow[499]) << "residual peak at t = " << r.channels[q].t_max;
}

TEST(CircuitReplay, FromRestAtNoiseLevel) {
  // A start from rest: the closed loop's suction side goes below 0 bar gauge (no
  // cavitation in the model) where its transmitters clip at 0: those rows are not compared.
  for (const char* name : {"closed_loop_hst", "test_stand"}) {
    const ct::LoadedCircuit c = load(name);
    ct::CircuitSimOptions o = hstmon_test::sim_options(2.0, 200.0, 11);
    o.from_rest = true;
    const ct::CircuitReplayResult r = ct::replay_circuit(c, ct::simulate_circuit(c, o), {});
    EXPECT_NE(r.start, hstmon::InitialState::kSteady) << name << ": a start from rest is no steady state";
    expect_noise_level(c, r, "from rest");
  }
}

TEST(CircuitReplay, ShippedLogsAtNoiseLevel) {
  for (const char* name : {"paper", "closed_loop_hst", "test_stand"}) {
    const ct::LoadedCircuit c = load(name);
    const ct::CircuitLog log = ct::read_circuit_log(example(std::string(name) + ".csv"), c.file);
    ASSERT_TRUE(log.ok()) << log.error->to_string();
    EXPECT_TRUE(log.notes.empty());
    EXPECT_GE(log.rows(), 1000u);
    EXPECT_LE(log.t.back(), 10.0);
    const ct::CircuitReplayResult r = ct::replay_circuit(c, log, {});
    expect_noise_level(c, r, "shipped");
  }
}

TEST(CircuitReplay, WrongInputsShowInTheResiduals) {
  // The test stand's log replayed with the throttle column dropped: the observer holds the
  // nominal opening after the step, and the flow and pressure residuals leave the noise.
  const ct::LoadedCircuit c = load("test_stand");
  ct::CircuitLog log = ct::read_circuit_log(example("test_stand.csv"), c.file);
  ASSERT_TRUE(log.ok());
  log.inputs[static_cast<std::size_t>(c.file.input_index("throttle"))].clear();
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, {});
  bool noted = false;
  for (const auto& n : r.notes) noted = noted || n.find("throttle") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_GT(r.channels[0].rms(), 10.0 * c.file.sensors[0].noise);
}

}  // namespace
