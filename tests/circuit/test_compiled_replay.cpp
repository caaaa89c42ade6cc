// The replay on a circuit compiled into the program (compiled_circuits.hpp) gives the
// interpreter's numbers: every residual statistic, event, score and size bit for bit, on
// the shipped logs of each compiled circuit at the ticks its kernel was generated for,
// and on a circuit that is not compiled the interpreter runs. So does the fit when it
// takes the monitor's steady outputs and bound instead of solving them again.
#include <gtest/gtest.h>

#include <string>

#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/compiled_circuits.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

std::string source(const std::string& file) { return std::string(HSTMON_SOURCE_DIR) + "/" + file; }

// Equal as numbers, NaN equal to NaN (a size that no fit gave).
bool same_number(double a, double b) { return a == b || (a != a && b != b); }

void expect_same_replay(const ct::CircuitReplayResult& a, const ct::CircuitReplayResult& b, const std::string& what) {
  EXPECT_EQ(a.ticks, b.ticks) << what;
  EXPECT_EQ(a.health, b.health) << what;
  EXPECT_EQ(a.max_substeps, b.max_substeps) << what;
  EXPECT_EQ(a.implicit_ticks, b.implicit_ticks) << what;
  EXPECT_EQ(a.start, b.start) << what;
  EXPECT_EQ(a.startup_hold, b.startup_hold) << what;
  EXPECT_EQ(a.final_status, b.final_status) << what;
  EXPECT_EQ(a.notes, b.notes) << what;
  ASSERT_EQ(a.channels.size(), b.channels.size()) << what;
  for (std::size_t ch = 0; ch < a.channels.size(); ++ch) {
    EXPECT_EQ(a.channels[ch].n, b.channels[ch].n) << what << " channel " << ch;
    EXPECT_EQ(a.channels[ch].mean(), b.channels[ch].mean()) << what << " channel " << ch;
    EXPECT_EQ(a.channels[ch].rms(), b.channels[ch].rms()) << what << " channel " << ch;
    EXPECT_EQ(a.channels[ch].max_abs, b.channels[ch].max_abs) << what << " channel " << ch;
    EXPECT_EQ(a.channels[ch].t_max, b.channels[ch].t_max) << what << " channel " << ch;
  }
  ASSERT_EQ(a.events.size(), b.events.size()) << what;
  for (std::size_t e = 0; e < a.events.size(); ++e) {
    const auto& x = a.events[e];
    const auto& y = b.events[e];
    EXPECT_EQ(x.t, y.t) << what << " event " << e;
    EXPECT_EQ(x.event, y.event) << what << " event " << e;
    EXPECT_EQ(x.consistent, y.consistent) << what << " event " << e;
    EXPECT_EQ(x.why, y.why) << what << " event " << e;
    ASSERT_EQ(x.candidates.size(), y.candidates.size()) << what << " event " << e;
    for (std::size_t k = 0; k < x.candidates.size(); ++k) {
      EXPECT_EQ(x.candidates[k].fault, y.candidates[k].fault) << what << " event " << e;
      EXPECT_EQ(x.candidates[k].score, y.candidates[k].score) << what << " event " << e;
      EXPECT_TRUE(same_number(x.candidates[k].size, y.candidates[k].size)) << what << " event " << e;
      EXPECT_EQ(x.candidates[k].size_text, y.candidates[k].size_text) << what << " event " << e;
    }
  }
}

struct Case {
  const char* circuit;  // "" = the built-in thesis rig
  const char* log;
  bool compiled;  // a kernel of the program is this circuit at this log's tick
  bool events;    // the log's replay raises events (a fault log)
};

TEST(CompiledReplay, SameNumbersAsTheInterpreter) {
  const Case cases[] = {
      {"", "examples/prv_blockage.csv", true, true},  // 10 ms tick
      {"", "examples/prv_staircase_das.csv", true, false},
      {"examples/circuits/paper.json", "examples/circuits/paper_dm_fault.csv", true, true},                    // 5 ms
      {"examples/circuits/paper.json", "tests/data/validation_paper/logs/fault_friction.csv.gz", true, true},  // 1 ms
      {"examples/circuits/closed_loop_hst.json", "examples/circuits/closed_loop_hst.csv", true, false},        // 5 ms
      {"examples/circuits/test_stand.json", "examples/circuits/test_stand.csv", false, false},
      // Not compiled; input changes in both directions, and a verdict that rests on the
      // windows before the detection (the fit's past windows: their steady outputs and bound).
      {"tests/data/validation_circuits/circuit.json", "tests/data/validation_circuits/logs/fault_leak_B.csv.gz", false,
       true},
  };
  for (const Case& k : cases) {
    const std::string what = std::string(*k.circuit ? k.circuit : "thesis (built in)") + " on " + k.log;
    ct::LoadedCircuit c;
    ASSERT_FALSE(ct::load_circuit(*k.circuit ? source(k.circuit) : std::string(), "", c).has_value()) << what;
    const ct::CircuitLog log = ct::read_circuit_log(source(k.log), c.file);
    ASSERT_TRUE(log.ok()) << what << ": " << log.error->to_string();
    ct::CircuitReplayOptions o;
    const ct::CircuitReplayResult compiled = ct::replay_circuit(c, log, o);
    o.interpret = true;
    const ct::CircuitReplayResult interpreted = ct::replay_circuit(c, log, o);
    o.share_bound = false;  // the fit solves its own steady states, as the monitor does
    const ct::CircuitReplayResult unshared = ct::replay_circuit(c, log, o);
    EXPECT_EQ(compiled.compiled, k.compiled) << what;
    EXPECT_FALSE(interpreted.compiled) << what;
    EXPECT_EQ(!compiled.events.empty(), k.events) << what;
    expect_same_replay(compiled, interpreted, what);
    expect_same_replay(compiled, unshared, what + " (fit's own steady solves)");
  }
}

TEST(CompiledReplay, AnotherCircuitIsNotTakenForACompiledOne) {
  // The thesis rig with one leakage resistance referred to another parameter: the same
  // shape, another circuit, which only the interpreter may run.
  ct::LoadedCircuit c;
  ASSERT_FALSE(ct::load_circuit("", "", c).has_value());
  hstmon::host::HostCircuit d = c.file.circuit;
  d.stiff_mask = hstmon::generated::thesis_circuit::kCircuit.stiff_mask;
  int kernels = 0;
  EXPECT_TRUE(ct::with_compiled_kernel(d, [&](auto) { ++kernels; }));
  EXPECT_EQ(kernels, 1);
  for (int e = 0; e < d.n_elements; ++e) {
    if (d.elements[e].kind == hstmon::circuit::ElementKind::kLaminar) {
      d.elements[e].r[hstmon::circuit::kR].index =
          static_cast<std::uint8_t>(d.elements[e].r[hstmon::circuit::kR].index + 1);
      break;
    }
  }
  EXPECT_FALSE(ct::with_compiled_kernel(d, [&](auto) { ++kernels; }));
  EXPECT_EQ(kernels, 1);
}

}  // namespace
