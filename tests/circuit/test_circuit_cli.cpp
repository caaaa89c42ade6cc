// The CLI on circuit files: `hstmon replay --circuit` on the shipped test-stand log (exit
// 0, residuals at noise level, JSON), its errors (file:line:column, exit 2), and
// `hstmon-sim --circuit` writing a log that replay reads back at noise level.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout (stderr with merge)
};

CliRun run(const std::string& cmd_line) {
  CliRun r;
  FILE* p = popen(cmd_line.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

const std::string kDir = std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/";

// Checks --json output: exit 0, every channel measured with RMS ≤ 2σ; returns the channels.
int expect_json_at_noise(const CliRun& r) {
  EXPECT_EQ(r.exit_code, 0) << r.out;
  std::istringstream lines(r.out);
  std::string line;
  int residuals = 0;
  bool head = false, diagnosis = false;
  while (std::getline(lines, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    EXPECT_FALSE(j.is_discarded()) << line;
    if (j.is_discarded()) continue;
    if (j["type"] == "replay") {
      head = true;
      EXPECT_TRUE(j["health"].empty());
    } else if (j["type"] == "residual") {
      ++residuals;
      EXPECT_TRUE(j["measured"].get<bool>());
      EXPECT_LE(j["rms"].get<double>(), 2.0 * j["sensor_noise"].get<double>()) << line;
    } else if (j["type"] == "diagnosis") {
      diagnosis = true;
      EXPECT_EQ(j["status"], "nominal") << line;  // the circuit's monitor ran and found nothing
      EXPECT_EQ(j["events"], 0) << line;
    }
  }
  EXPECT_TRUE(head);
  EXPECT_TRUE(diagnosis);
  return residuals;
}

TEST(CircuitCli, ReplayShippedTestStandLogAtNoiseLevel) {
  const CliRun r = run(std::string(HSTMON_CLI) + " replay --circuit " + kDir + "test_stand.json " + kDir +
                       "test_stand.csv --json");
  EXPECT_EQ(expect_json_at_noise(r), 2);
  const CliRun h = run(std::string(HSTMON_CLI) + " replay --circuit " + kDir + "test_stand.json " + kDir + "test_stand.csv");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("diagnosis: no fault detected"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("fault table:"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("p_line [bar]"), std::string::npos) << h.out;
}

TEST(CircuitCli, ReplayErrorsNameFileLineColumn) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string bad_log = (dir / "hstmon_circuit_cli_bad.csv").string();
  {
    std::FILE* f = std::fopen(bad_log.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("t[s],p_line[bar]\n0,147\n0.005,oops\n", f);
    std::fclose(f);
  }
  CliRun r = run(std::string(HSTMON_CLI) + " replay --circuit " + kDir + "test_stand.json " + bad_log + " 2>&1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(bad_log + ":3:7: error: not a number: 'oops'"), std::string::npos) << r.out;

  const std::string bad_circuit = (dir / "hstmon_circuit_cli_bad.json").string();
  {
    std::FILE* f = std::fopen(bad_circuit.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("{\"circuit\": \"x\",\n \"nodez\": {}}\n", f);
    std::fclose(f);
  }
  r = run(std::string(HSTMON_CLI) + " replay --circuit " + bad_circuit + " " + bad_log + " 2>&1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(bad_circuit + ":2:"), std::string::npos) << r.out;

  r = run(std::string(HSTMON_CLI) + " replay --circuit " + kDir + "test_stand.json " + kDir +
          "test_stand.csv --residuals /dev/null 2>&1");
  EXPECT_EQ(r.exit_code, 1) << r.out;
}

TEST(CircuitCli, SimWritesALogReplayReadsAtNoiseLevel) {
  const std::string out = (std::filesystem::temp_directory_path() / "hstmon_circuit_cli_sim.csv").string();
  CliRun r = run(std::string(HSTMON_SIM) + " --circuit " + kDir + "closed_loop_hst.json --duration 1 --rate 200 " +
                 "--step 'T_L=250 N*m@0.5' --seed 3 --out " + out + " 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = run(std::string(HSTMON_CLI) + " replay --circuit " + kDir + "closed_loop_hst.json " + out + " --json");
  EXPECT_EQ(expect_json_at_noise(r), 4);

  r = run(std::string(HSTMON_SIM) + " --circuit " + kDir + "closed_loop_hst.json --step nope=1@1 2>&1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("no input 'nope'"), std::string::npos) << r.out;
  r = run(std::string(HSTMON_SIM) + " --circuit " + kDir + "closed_loop_hst.json --scenario prv_blockage 2>&1");
  EXPECT_EQ(r.exit_code, 1);
}

}  // namespace
