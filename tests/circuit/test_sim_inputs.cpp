// hstmon-sim --circuit F --inputs LOG: a logged run's input columns drive the circuit on
// the log's clock and rows. A swash-plate ramp of closed_loop_hst.json re-simulated from
// its own 100 Hz log matches the original run within the interpolation's error (linear
// between rows far closer than each row held); inputs absent from the log keep their
// parameter-file values (named in a note); a log without an input column, or without a
// time column, is an error at file:line:column; --compare prints the residual measured −
// simulated per channel in bar and rpm.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/cli_run.hpp"
#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"

namespace {

using hstmon::circuit_tools::CircuitLog;
using hstmon::circuit_tools::LoadedCircuit;
using hstmon_test::CliRun;

const std::string kDir = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/";
const std::string kSim = std::string("'") + HSTMON_SIM + "'";

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("hstmon_sim_inputs_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

void write(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

LoadedCircuit load(const std::string& name) { return hstmon_test::load_circuit_file(kDir + name); }

CircuitLog read(const std::string& path, const LoadedCircuit& c) {
  CircuitLog log = hstmon::circuit_tools::read_circuit_log(path, c.file);
  EXPECT_TRUE(log.ok()) << (log.error ? log.error->to_string() : "");
  return log;
}

// The largest |a − b| of sensor channel ch over the rows both logs hold at the same time
// (the first `rows` of them).
double max_gap(const CircuitLog& a, const CircuitLog& b, std::size_t ch, std::size_t rows = SIZE_MAX) {
  EXPECT_EQ(a.rows(), b.rows());
  double worst = 0.0;
  for (std::size_t k = 0; k < a.rows() && k < b.rows() && k < rows; ++k) {
    EXPECT_NEAR(a.t[k], b.t[k], 1e-9);
    worst = std::max(worst, std::fabs(a.sensors[ch][k] - b.sensors[ch][k]));
  }
  return worst;
}

// The original run: the swash plate ramps 0.5 → 0.9 from 1.003 s to 2.503 s (corners off
// the 10 ms rows) and the load torque 150 → 250 N·m from 2 s to 3 s, given as their corner
// rows only (linear between them is exactly the ramp), written at 100 Hz without noise
// from t0 = 20 s.
class SwashRamp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    corners_ = temp("corners.csv");
    original_ = temp("original.csv");
    write(corners_,
          "t[s],n_engine[rpm],swash,t_load[N*m]\n"
          "20,2000,0.5,150\n21.003,2000,0.5,150\n22,2000,0.7,150\n22.503,2000,0.9,200\n23,2000,0.9,250\n"
          "24,2000,0.9,250\n");
    const CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " +
                                              corners_ + " --rate 100 --no-noise --out " + original_ + " 2>&1");
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  static void TearDownTestSuite() {
    std::remove(corners_.c_str());
    std::remove(original_.c_str());
  }
  static std::string corners_, original_;
};
std::string SwashRamp::corners_, SwashRamp::original_;

TEST_F(SwashRamp, OriginalRunIsOnTheLogsClock) {
  const LoadedCircuit c = load("closed_loop_hst.json");
  const CircuitLog o = read(original_, c);
  ASSERT_EQ(o.rows(), 401u);  // 20 … 24 s at 100 Hz, both ends written
  EXPECT_DOUBLE_EQ(o.t.front(), 20.0);
  EXPECT_NEAR(o.t.back(), 24.0, 1e-9);
  const int eps = c.file.input_index("eps");
  ASSERT_GE(eps, 0);
  // Linear between the corner rows: at 21.5 s the swash is 0.5 + 0.2·(0.497/0.997).
  EXPECT_NEAR(o.inputs[static_cast<std::size_t>(eps)][150], 0.5 + 0.2 * 0.497 / 0.997, 1e-8);
}

TEST_F(SwashRamp, ReSimulatedFromItsOwnRowsMatchesWithinInterpolationError) {
  const LoadedCircuit c = load("closed_loop_hst.json");
  const std::string linear = temp("linear.csv"), step = temp("step.csv");
  CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " + original_ +
                                      " --no-noise --out " + linear + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("note"), std::string::npos) << "every input is in the log: " << r.out;
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " + original_ +
                               " --inputs-hold step --no-noise --out " + step + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const CircuitLog o = read(original_, c), lin = read(linear, c), zoh = read(step, c);
  ASSERT_EQ(lin.rows(), o.rows());  // the log's own rows
  ASSERT_EQ(zoh.rows(), o.rows());
  // Channel noise (σ): p_a, p_b 0.5 bar, p_c 0.05 bar, w_m 2 rpm. Linear between the rows
  // differs from the ramps only within the rows holding a corner: well below noise (0.09
  // bar in p_b, 0.1 rpm when written, after the load ramp's corner at 22.503 s).
  const double sigma[4] = {0.5e5, 0.5e5, 0.05e5, 2.0 * 2.0 * M_PI / 60.0};
  for (std::size_t ch = 0; ch < 4; ++ch) {
    const double lin_gap = max_gap(o, lin, ch), zoh_gap = max_gap(o, zoh, ch);
    EXPECT_LT(lin_gap, 0.25 * sigma[ch]) << "channel " << ch;
    // Each row held lags the ramps by half a row: 2.5 bar in p_b, 6 rpm when written.
    if (ch == 1 || ch == 3) {
      EXPECT_GT(zoh_gap, 10.0 * lin_gap) << "channel " << ch;
    }
  }
  std::remove(linear.c_str());
  std::remove(step.c_str());
}

TEST_F(SwashRamp, CompareReportsResidualAtNoiseInBarAndRpm) {
  // The measured run with noise, re-simulated with other noise: residual RMS ≈ √2·σ.
  const std::string noisy = temp("noisy.csv");
  CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " + original_ +
                                      " --seed 7 --out " + noisy + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " + noisy +
                               " --seed 8 --compare --out /dev/null 2>/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("401 rows"), std::string::npos) << r.out;
  const struct {
    const char* name;
    double sigma;
  } want[4] = {{"p_a[bar]", 0.5}, {"p_b[bar]", 0.5}, {"p_c[bar]", 0.05}, {"w_m[rpm]", 2.0}};
  for (const auto& w : want) {
    const std::size_t at = r.out.find(std::string("  ") + w.name);
    ASSERT_NE(at, std::string::npos) << w.name << '\n' << r.out;
    const std::size_t rms_at = r.out.find("rms ", at);
    ASSERT_NE(rms_at, std::string::npos) << r.out;
    const double rms = std::stod(r.out.substr(rms_at + 4));
    EXPECT_GT(rms, 1.1 * w.sigma) << w.name << '\n' << r.out;
    EXPECT_LT(rms, 1.7 * w.sigma) << w.name << '\n' << r.out;
  }
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " + noisy +
                               " --compare --rate 50 --out /dev/null 2>&1");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  std::remove(noisy.c_str());
}

TEST_F(SwashRamp, StepsAndFaultsApplyOnTheLogsClock) {
  const LoadedCircuit c = load("closed_loop_hst.json");
  const std::string out = temp("fault.csv");
  const CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "closed_loop_hst.json --inputs " +
                                            original_ + " --no-noise --step 'T_L=300 N*m@23.5' --out " + out + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const CircuitLog o = read(original_, c), s = read(out, c);
  ASSERT_EQ(s.rows(), o.rows());
  const auto tl = static_cast<std::size_t>(c.file.input_index("T_L"));
  EXPECT_NEAR(s.inputs[tl][349], 250.0, 1e-9);  // 23.49 s: the log's
  EXPECT_NEAR(s.inputs[tl][350], 300.0, 1e-9);  // 23.5 s on: the step's
  // p_b: the same run up to the step (to the interpolation's 0.09 bar), 50 bar more
  // load pressure after it.
  EXPECT_LT(max_gap(o, s, 1, 350), 0.2e5);
  EXPECT_GT(max_gap(o, s, 1), 10e5);
  std::remove(out.c_str());
}

TEST(SimInputs, InputsAbsentFromTheLogKeepTheirParameterFileValue) {
  const LoadedCircuit c = load("test_stand.json");
  const std::string log = temp("throttle_only.csv"), out = temp("throttle_only_out.csv");
  write(log, "# throttle closing, no drive speed logged\nt[s],throttle\n0,1\n0.5,1\n1,0.6\n1.5,0.6\n2,0.6\n");
  const CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log +
                                            " --rate 20 --no-noise --out " + out + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(log + ":2:1: note: input not in the log, held at the parameter file's value: n_drive = "
                             "1500 rpm"),
            std::string::npos)
      << r.out;
  const CircuitLog s = read(out, c);
  ASSERT_EQ(s.rows(), 41u);  // 0 … 2 s at 20 Hz
  const auto n = static_cast<std::size_t>(c.file.input_index("n_drive"));
  const auto th = static_cast<std::size_t>(c.file.input_index("throttle"));
  for (std::size_t k = 0; k < s.rows(); ++k) EXPECT_NEAR(s.inputs[n][k] * 60.0 / (2.0 * M_PI), 1500.0, 1e-9);
  EXPECT_NEAR(s.inputs[th][15], 0.8, 1e-12);  // 0.75 s: halfway down the logged ramp
  std::remove(log.c_str());
  std::remove(out.c_str());
}

// A logger's Unix time: the run is on that clock, integrated from 0 (the clock resolves
// only 2e-7 s there), its rows written back as they were.
TEST(SimInputs, ALogOnUnixTimeIsReRunOnItsRows) {
  const LoadedCircuit c = load("test_stand.json");
  const std::string log = temp("unix.csv"), out = temp("unix_out.csv");
  write(log, "t[s],n_pump[rpm],throttle\n1700000000.000,1500,1\n1700000000.005,1500,1\n1700000000.010,1500,0.9\n"
             "1700000000.015,1500,0.8\n1700000000.020,1500,0.8\n1700000000.025,1500,0.8\n");
  const CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log +
                                            " --no-noise --out " + out + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const CircuitLog in = read(log, c), s = read(out, c);
  ASSERT_EQ(s.rows(), in.rows());
  for (std::size_t k = 0; k < s.rows(); ++k) EXPECT_EQ(s.t[k], in.t[k]) << k;
  // The throttle closing raises the line pressure, the steady start does not move.
  EXPECT_NEAR(s.sensors[0][0], s.sensors[0][1], 50.0);
  EXPECT_GT(s.sensors[0][5], s.sensors[0][2] + 1e5);
  std::remove(log.c_str());
  std::remove(out.c_str());
}

TEST(SimInputs, ALogWithoutInputOrTimeColumnIsAnErrorAtItsHeader) {
  const std::string log = temp("no_inputs.csv");
  write(log, "# measured, no inputs\nt[s],p_line[bar]\n0,150\n1,151\n");
  CliRun r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log + " 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(log + ":2:1: error: --inputs: no input column of circuit test_stand in the header (its "
                             "inputs' columns: n_pump[rpm], throttle)"),
            std::string::npos)
      << r.out;
  write(log, "n_pump[rpm],throttle\n1500,1\n1500,0.5\n");
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log + " 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(log + ":1:1: error: no time column"), std::string::npos) << r.out;
  write(log, "t[s],throttle\n0,1\n");
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log + " 2>&1");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(log + ":1:1: error: --inputs: the log has 1 row"), std::string::npos) << r.out;
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --inputs " + log +
                               " --inputs-hold cubic 2>&1");
  EXPECT_NE(r.exit_code, 0) << r.out;
  r = hstmon_test::run_command(kSim + " --circuit " + kDir + "test_stand.json --compare 2>&1");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  std::remove(log.c_str());
}

}  // namespace
