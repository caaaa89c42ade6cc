// The hstmon CLI on malformed logs and parameter files: a clear error naming
// file:line:column, a non-zero exit, never a crash; --lenient still replays the valid
// rows before the error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/cli_run.hpp"

namespace {

using hstmon_test::CliRun;
using hstmon_test::run_hstmon;

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("hstmon_cli_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

const std::string kHeader = "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
const std::string kRow0 = "0,33.12,1.879,171.08,1677.7\n";
const std::string kRow1 = "0.01,33.12,1.879,171.08,1677.7\n";

void expect_error_at(const std::string& name, const std::string& text, const std::string& where) {
  const std::string path = write_file(name, text);
  const CliRun r = run_hstmon("replay " + path);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(path + ":" + where + ": error:"), std::string::npos) << r.out;
}

TEST(CliErrors, BadNumber) { expect_error_at("bad_number.csv", kHeader + kRow0 + "0.01,33.1.2,1.8,171,1677\n", "3:6"); }
TEST(CliErrors, RaggedRow) { expect_error_at("ragged.csv", kHeader + kRow0 + "0.01,33.1,1.8,171\n", "3:18"); }
TEST(CliErrors, UnknownUnit) { expect_error_at("unit.csv", "t[s],p_mi[furlong]\n0,1\n", "1:11"); }
TEST(CliErrors, TimeGoesBackwards) { expect_error_at("time.csv", kHeader + kRow1 + kRow0, "3:1"); }
TEST(CliErrors, NanValue) { expect_error_at("nan.csv", kHeader + kRow0 + "0.01,nan,1.8,171,1677\n", "3:6"); }
TEST(CliErrors, EmptyFile) { expect_error_at("empty.csv", "", "1:1"); }
TEST(CliErrors, BinaryJunk) {
  expect_error_at("junk.csv", kHeader + kRow0 + std::string("0.01,\x00\xff\xfe,1,2,3\n", 15), "3:6");
}

TEST(CliErrors, MissingFileIsNamed) {
  const CliRun r = run_hstmon("replay /nonexistent/hstmon.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("/nonexistent/hstmon.csv"), std::string::npos) << r.out;
}

TEST(CliErrors, LenientReplaysTheValidPrefix) {
  std::string text = kHeader;
  for (int i = 0; i < 50; ++i) text += std::to_string(i * 0.01) + ",33.12,1.879,171.08,1677.7\n";
  text += "0.5,33.1,oops,171,1677\n";
  const std::string path = write_file("lenient.csv", text);
  const CliRun strict = run_hstmon("replay " + path);
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_EQ(strict.out.find("residual"), std::string::npos) << "strict mode must not report results";
  const CliRun lenient = run_hstmon("replay --lenient --json " + path);
  EXPECT_EQ(lenient.exit_code, 2) << "the error still shows in the exit code";
  EXPECT_NE(lenient.out.find(path + ":52:"), std::string::npos) << lenient.out;
  EXPECT_NE(lenient.out.find("\"rows\":50"), std::string::npos) << lenient.out;
}

TEST(CliErrors, BadParamsFileNamesLineAndColumn) {
  const std::string log = write_file("ok.csv", kHeader + kRow0 + kRow1);
  const std::string params = write_file("bad.json", "{\n  \"model\": \"thesis\",\n  \"params\": {\n    \"Dm\": -1\n  }\n}\n");
  const CliRun r = run_hstmon("replay " + log + " --params " + params);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(params + ":4:"), std::string::npos) << r.out;
}

TEST(CliErrors, GoodLogReplays) {
  const std::string log = write_file("good.csv", kHeader + kRow0 + kRow1);
  const CliRun r = run_hstmon("replay " + log);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("p_pp [bar]"), std::string::npos) << r.out;
}

// Another machine's log (a test stand's line pressure and flow) through the thesis rig's
// monitor: nothing is compared, which is an error, not "within the sensor noise".
TEST(CliErrors, LogWithNoneOfTheRigsChannelsIsAnError) {
  std::string text = "t[s],n_pump[rpm],p_line[bar],q[L/min]\n";
  for (int i = 0; i < 20; ++i) text += std::to_string(i * 0.01) + ",1500,148,67\n";
  const std::string path = write_file("other_machine.csv", text);
  const CliRun r = run_hstmon("replay " + path);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(path + ": error: none of circuit thesis's sensor columns (p_mi, p_mo, p_pp, w_m)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("--circuit"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("within the sensor noise"), std::string::npos) << r.out;
}

TEST(CliErrors, UsageErrorExitsOne) {
  EXPECT_EQ(run_hstmon("replay").exit_code, 1);
  EXPECT_EQ(run_hstmon("replay x.csv --init sideways").exit_code, 1);
}

// A parameter file's "sensors" section reaches the replay: with Ppp's transmitter ranged
// to 150 bar, the shipped log's 171 bar reads over range from the first row, and the
// diagnosis is the sensor, not the PRV.
TEST(CliParams, SensorsSectionSetsTheTransmitterRanges) {
  const std::string params = write_file("ranges.json", R"({"model": "thesis", "sensors": {"p_pp": ["0 bar", "150 bar"]}})");
  const CliRun narrow = run_hstmon(std::string("replay ") + HSTMON_EXAMPLE_LOG + " --params " + params);
  EXPECT_EQ(narrow.exit_code, 0) << narrow.out;
  EXPECT_NE(narrow.out.find("isolated: sensor_p_pp"), std::string::npos) << narrow.out;
  const CliRun rig = run_hstmon(std::string("replay ") + HSTMON_EXAMPLE_LOG);
  EXPECT_EQ(rig.exit_code, 0) << rig.out;
  EXPECT_NE(rig.out.find("isolated: kp-"), std::string::npos) << rig.out;
}

// The thesis DAS samples every 4 s: the matcher's 100 ms averaging window after detection
// holds no sample, so it stays open until one arrives (before, every row scored 0 and the
// episode ended "ambiguous").
TEST(CliReplay, DasRateLogIsolatesTheBlockage) {
  const CliRun r = run_hstmon(std::string("replay ") + HSTMON_EXAMPLE_DAS_LOG);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("isolated: kp- ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("status at the end of the log: isolated"), std::string::npos) << r.out;
}

}  // namespace
