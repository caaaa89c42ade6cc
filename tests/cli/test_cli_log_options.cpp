// One set of log options (issue 16): `replay`, `identify` and `gap` take --map,
// --separator, --lenient, --rate and --params with the same meaning, through one helper
// (host_sim/src/cli_log_options.hpp), and report in one style. The Spider8 export as the
// instrument writes it loads with one documented command.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <utility>

#include "../support/cli_run.hpp"
#include "../support/instrument_exports.hpp"

namespace {

using hstmon_test::CliRun;
using hstmon_test::run_hstmon;

// Per process: CTest runs this file's tests as separate processes side by side, and one
// rewriting a shared file while another reads it left the reader an empty file.
std::string write_file(const std::string& name, const std::string& text) {
  const auto path =
      std::filesystem::temp_directory_path() / ("hstmon_cli_opts_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

const std::string& spider8_path() {
  static const std::string path = write_file("spider8.txt", hstmon_test::spider8_export());
  return path;
}

// The one command README "Log format" documents for the Spider8 export.
std::string spider8_options() { return std::string("--rate 4800 ") + hstmon_test::spider8_map_args(); }

std::size_t longest_line(const std::string& s) {
  std::size_t longest = 0, start = 0;
  while (start < s.size()) {
    std::size_t end = s.find('\n', start);
    if (end == std::string::npos) end = s.size();
    longest = std::max(longest, end - start);
    start = end + 1;
  }
  return longest;
}

}  // namespace

TEST(CliLogOptions, ReplayLoadsTheSpider8ExportWithOneCommand) {
  const CliRun r = run_hstmon("replay " + spider8_path() + " " + spider8_options());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("3000 rows, t = 0 … 0.624792 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("p_pp [bar]"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("error"), std::string::npos) << r.out;
  // Notes in the circuit's units: bar, not 3500000.000000 Pa.
  EXPECT_NE(r.out.find("not in log: held at 35 bar"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("3500000"), std::string::npos) << r.out;
}

TEST(CliLogOptions, ReplayWithoutRateNamesIt) {
  const std::string maps = hstmon_test::spider8_map_args();
  const CliRun strict = run_hstmon("replay " + spider8_path() + " " + maps);
  EXPECT_EQ(strict.exit_code, 2) << strict.out;
  EXPECT_NE(strict.out.find(spider8_path() + ":4:1: error: time not strictly increasing"), std::string::npos)
      << strict.out;
  EXPECT_NE(strict.out.find("--rate HZ"), std::string::npos) << strict.out;
  // --lenient does not drop 79 % of the file quietly.
  const CliRun lenient = run_hstmon("replay --lenient " + spider8_path() + " " + maps);
  EXPECT_EQ(lenient.exit_code, 2) << lenient.out;
  EXPECT_TRUE(std::regex_search(lenient.out, std::regex(":4:1: error: time not strictly increasing in 2374 of 3000 rows")))
      << lenient.out;
  EXPECT_EQ(lenient.out.find("residual"), std::string::npos) << "nothing replayed";
  EXPECT_LT(std::count(lenient.out.begin(), lenient.out.end(), '\n'), 10) << lenient.out;
}

TEST(CliLogOptions, IdentifyTakesTheLogOptions) {
  const CliRun r = run_hstmon("identify " + spider8_path() + " " + spider8_options() + " --out " +
                       write_file("id.json", ""));
  // The log is read whole (0.625 s at one setting is one operating point, too few for the
  // thesis rig's losses: that, not the log, is the error).
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(spider8_path() + ": error: 1 operating point(s)"), std::string::npos) << r.out;
  const CliRun no_rate = run_hstmon("identify " + spider8_path() + " --map '#1=t' --out " + write_file("id2.json", ""));
  EXPECT_EQ(no_rate.exit_code, 2) << no_rate.out;
  EXPECT_NE(no_rate.out.find(":4:1: error: time not strictly increasing"), std::string::npos) << no_rate.out;
  EXPECT_NE(no_rate.out.find("--rate HZ"), std::string::npos) << no_rate.out;
  // --params is identify's parameter file too (--prior stays as its old name).
  const std::string bad = write_file("bad_params.json", "{\n  \"model\": \"thesis\",\n  \"params\": {\"Dm\": -1}\n}\n");
  const CliRun params =
      run_hstmon("identify " + spider8_path() + " " + spider8_options() + " --params " + bad + " --out x");
  EXPECT_EQ(params.exit_code, 2) << params.out;
  EXPECT_NE(params.out.find(bad + ":3:"), std::string::npos) << params.out;
  const CliRun prior =
      run_hstmon("identify " + spider8_path() + " " + spider8_options() + " --prior " + bad + " --out x");
  EXPECT_EQ(prior.exit_code, 2) << prior.out;
  EXPECT_NE(prior.out.find(bad + ":3:"), std::string::npos) << prior.out;
}

TEST(CliLogOptions, GapTakesTheLogOptions) {
  const CliRun r = run_hstmon("gap --fit " + spider8_path() + " --check " + spider8_path() + " " + spider8_options() +
                       " --effects sensor_lag");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("verdict"), std::string::npos) << r.out;
  const CliRun no_rate = run_hstmon("gap --fit " + spider8_path() + " --check " + spider8_path() + " --map '#1=t'");
  EXPECT_EQ(no_rate.exit_code, 2) << no_rate.out;
  EXPECT_NE(no_rate.out.find(":4:1: error: time not strictly increasing"), std::string::npos) << no_rate.out;
}

// A bad option value: exit 1 and one message style, `hstmon COMMAND: error: --option …`.
TEST(CliLogOptions, BadOptionValuesInOneStyle) {
  const std::string log = spider8_path();
  const std::pair<std::string, std::string> commands[] = {
      {"replay", "replay " + log},
      {"identify", "identify " + log + " --out x.json"},
      {"gap", "gap --fit " + log + " --check " + log},
  };
  for (const auto& [name, cmd] : commands) {
    const CliRun map = run_hstmon(cmd + " --map nonsense");
    EXPECT_EQ(map.exit_code, 1) << name << ": " << map.out;
    EXPECT_NE(map.out.find("hstmon " + name + ": error: --map takes COLUMN=SIGNAL or '#N=SIGNAL'"), std::string::npos)
        << name << ": " << map.out;
    const CliRun sep = run_hstmon(cmd + " --separator '|'");
    EXPECT_EQ(sep.exit_code, 1) << name << ": " << sep.out;
    EXPECT_NE(sep.out.find("hstmon " + name + ": error: --separator must be"), std::string::npos) << sep.out;
    const CliRun rate = run_hstmon(cmd + " --rate -5");
    EXPECT_EQ(rate.exit_code, 1) << name << ": " << rate.out;
    EXPECT_EQ(rate.out.rfind("hstmon: error: --rate", 0), 0u) << name << ": " << rate.out;
    EXPECT_LT(longest_line(rate.out), 120u) << name << ": " << rate.out;
  }
}

// A HYDAC HMG-style export (metadata block above the header) replays with --map.
TEST(CliLogOptions, ReplayReadsAnHmgExport) {
  const std::string log = write_file("hmg.csv", hstmon_test::hmg_export(500));
  const CliRun r = run_hstmon("replay " + log + " --map Time=t --map P1=p_mi --map P2=p_mo --map P3=p_pp --map n=w_m");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(log + ":1:1: note: lines 1-6 above the column names taken as metadata"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("500 rows"), std::string::npos) << r.out;
}

// One log, one message: `replay` reads through the circuit reader, `gap` through the
// thesis rig's; a bad field or unit gives the same line through both.
TEST(CliLogOptions, TheSameBadLogGivesTheSameErrorThroughEveryCommand) {
  const std::string head = "t[s],p_mi[bar],p_pp[bar]\n0,1,2\n";
  const std::pair<const char*, std::string> cases[] = {
      {"bad_number.csv", head + "0.01,1x,2\n"},      {"empty_field.csv", head + "0.01,,2\n"},
      {"nan_field.csv", head + "0.01,nan,2\n"},      {"big_number.csv", head + "0.01,1e400,2\n"},
      {"bad_unit.csv", "t[s],p_mi[furlong]\n0,1\n"},
  };
  for (const auto& [name, text] : cases) {
    const std::string log = write_file(name, text);
    const CliRun replay = run_hstmon("replay " + log);
    const CliRun gap = run_hstmon("gap --fit " + log + " --check " + log);
    EXPECT_EQ(replay.exit_code, 2) << replay.out;
    const std::size_t at = replay.out.find(log + ":");
    ASSERT_NE(at, std::string::npos) << replay.out;
    const std::string line = replay.out.substr(at, replay.out.find('\n', at) - at);
    EXPECT_NE(gap.out.find(line), std::string::npos) << "replay: " << line << "\ngap: " << gap.out;
  }
}

// No message fills a screen: a 5000-column export with a bad row prints a handful of
// short lines.
TEST(CliLogOptions, MessagesStayShortOnAWideExport) {
  std::string header = "t", row = "0";
  for (int k = 0; k < 5000; ++k) {
    header += ";channel_" + std::to_string(k) + "_with_a_long_descriptive_name";
    row += ";1";
  }
  const std::string log = write_file("wide.csv", header + "\n" + row + "\n" + std::string(80000, '7') + "x\n");
  const CliRun r = run_hstmon("replay " + log);
  EXPECT_EQ(r.exit_code, 2) << r.out.substr(0, 2000);
  EXPECT_LT(std::count(r.out.begin(), r.out.end(), '\n'), 15) << r.out.substr(0, 2000);
  EXPECT_LT(longest_line(r.out), 400u) << r.out.substr(0, 2000);
}

// The matcher's scores are printed in [0, 1]: a negative cosine (residuals pointing away
// from a fault's direction) is shown as 0, never as a negative score.
TEST(CliLogOptions, ScoresAreNeverNegative) {
  for (const char* log : {HSTMON_EXAMPLE_LOG, HSTMON_EXAMPLE_DAS_LOG}) {
    const CliRun r = run_hstmon(std::string("replay --json ") + log);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("\"score\":"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("\"score\":-"), std::string::npos) << r.out;
  }
}
