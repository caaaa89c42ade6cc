// `hstmon replay` with no --circuit runs the thesis rig as a circuit: the thesis.json built
// into the program, whose own values are Table 2.2. It must give what the shipped file
// gives, and read the thesis rig's parameter files ("model": "thesis", keys left out keep
// Table 2.2) as that circuit's.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../support/cli_run.hpp"

namespace {

using hstmon_test::CliRun;
using hstmon_test::run_hstmon;

const std::string kSrc = HSTMON_SOURCE_DIR;

// The JSON lines of a replay without the keys that name the circuit's source.
std::string without_source(const std::string& out) {
  std::istringstream in(out);
  std::string line, kept;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) continue;
    j.erase("circuit_file");
    j.erase("params_file");
    kept += j.dump() + "\n";
  }
  return kept;
}

TEST(ReplayBuiltinRig, IsTheShippedThesisCircuit) {
  const std::string log = kSrc + "/examples/prv_blockage.csv";
  const CliRun builtin = run_hstmon("replay --json " + log);
  const CliRun file = run_hstmon("replay --json --circuit " + kSrc + "/examples/circuits/thesis.json " + log);
  ASSERT_EQ(builtin.exit_code, 0) << builtin.out;
  ASSERT_EQ(file.exit_code, 0) << file.out;
  EXPECT_EQ(without_source(builtin.out), without_source(file.out));
  EXPECT_NE(builtin.out.find(R"x("circuit_file":"thesis.json (built in)")x"), std::string::npos) << builtin.out;
  EXPECT_NE(builtin.out.find(R"("fault":"kp-")"), std::string::npos) << builtin.out;
}

TEST(ReplayBuiltinRig, ReadsTheThesisParameterFiles) {
  const std::string log = kSrc + "/examples/prv_blockage.csv";
  const CliRun table = run_hstmon("replay --json --params " + kSrc + "/examples/table_2_2.json " + log);
  const CliRun builtin = run_hstmon("replay --json " + log);
  ASSERT_EQ(table.exit_code, 0) << table.out;
  EXPECT_EQ(without_source(table.out), without_source(builtin.out)) << "Table 2.2 is the built-in values";
  // A partial file: the keys it leaves out keep Table 2.2; a wrong value is located.
  const std::string partial = testing::TempDir() + "hstmon_builtin_partial.json";
  std::ofstream(partial) << "{\"model\": \"thesis\",\n \"params\": {\"Dm\": -1}}\n";
  const CliRun bad = run_hstmon("replay --params " + partial + " " + log);
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_NE(bad.out.find(partial + ":2:19: error:"), std::string::npos) << bad.out;
}

}  // namespace
