// Bad data through `hstmon identify` (the one path: thesis.json unless --circuit): a clear
// message naming the file (and line where there is one), a non-zero exit, and no file
// written; a good run writes a parameter file every command reads and a header.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "../support/cli_run.hpp"
#include "synthetic_logs.hpp"

namespace hstmon::ident {
namespace {

namespace fs = std::filesystem;

using hstmon_test::CliRun;
using hstmon_test::run_hstmon;

fs::path temp_dir_path() { return fs::temp_directory_path() / ("hstmon-ident-test-" + std::to_string(::getpid())); }

fs::path temp_dir() {
  const fs::path d = temp_dir_path();
  fs::create_directories(d);
  return d;
}

// This process's scratch folder goes when the tests end (static destruction).
struct RemoveTempDirAtExit {
  ~RemoveTempDirAtExit() {
    std::error_code ec;
    fs::remove_all(temp_dir_path(), ec);
  }
} const remove_temp_dir_at_exit;

std::string write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

// `hstmon identify` on a log named `name` with `text` (and `options`): exit 2, a message
// that names the log and holds `says`, and no parameter file written.
void expect_identify_error(const std::string& name, const std::string& text, const std::string& options,
                           const std::string& says) {
  const fs::path d = temp_dir();
  const std::string file = write_text(d / name, text);
  const fs::path out = d / (name + ".params.json");
  const CliRun run = run_hstmon("identify " + file + options + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find(file), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(says), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST(IdentErrors, TooFewOperatingPoints) {
  // Two loads where three settings are asked for.
  const auto log = testing::steady_staircase_log(1, {}, 10, sim::thesis_das_sensors(), {1.0, 0.5});
  expect_identify_error("two_loads.csv", testing::thesis_log_csv(log), " --min-settings 3",
                        "2 distinct operating point(s)");
}

TEST(IdentErrors, NoSteadyOperatingPoint) {
  std::string text = "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  for (int i = 0; i < 200; ++i) {
    text += std::to_string(i * 0.01) + ',' + std::to_string(30 + 0.5 * i) + ',' + std::to_string(2 + 0.1 * i) + ',' +
            std::to_string(100 + i) + ',' + std::to_string(10 * i) + '\n';
  }
  expect_identify_error("ramp.csv", text, "", "0 operating point(s)");
}

TEST(IdentErrors, NaNsNameTheLine) {
  expect_identify_error("nan.csv", "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n0,30,2,150,1600\n4,nan,2,150,1600\n",
                        "", "nan.csv:3");
}

TEST(IdentErrors, UsageAndGoodRun) {
  EXPECT_EQ(run_hstmon("identify").exit_code, 1);
  EXPECT_EQ(run_hstmon("identify --fit nosuch x.csv").exit_code, 2);
  const fs::path d = temp_dir();
  const std::string file = write_text(d / "good.csv", testing::thesis_log_csv(testing::steady_staircase_log(4)));
  const std::string out = (d / "good.json").string(), header = (d / "good.hpp").string();
  const CliRun run = run_hstmon("identify " + file + " --out " + out + " --header " + header);
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("held at its start value"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("Table 2.3 form"), std::string::npos) << run.out;
  // The parameter file is the monitor's: replay reads it.
  const CliRun replay = run_hstmon("replay " + file + " --params " + out);
  EXPECT_EQ(replay.exit_code, 0) << replay.out;
  std::ifstream h(header);
  const std::string text((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("hstmon identify"), std::string::npos);
}

}  // namespace
}  // namespace hstmon::ident
