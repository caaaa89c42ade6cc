// `hstmon gap` on bad input: never a crash, exit status 2 and a message naming
// file:line:column; on good logs, --json prints one object with the equations.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using hstmon_test::CliRun;

CliRun run(const std::string& args) { return hstmon_test::run_hstmon("gap " + args); }

fs::path write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("hstmon_gap_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

std::string log_text(int rows, double kp2) {
  std::string s = "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  for (int k = 0; k < rows; ++k) {
    const double kp = k < rows / 2 ? 4.41e-8 : kp2;
    char b[160];
    std::snprintf(b, sizeof b, "%.3f,35,%.4e,33.1,1.9,171.1,1678\n", 0.01 * k, kp);
    s += b;
  }
  return s;
}

TEST(GapCli, BadNumberNamesFileLineColumn) {
  const fs::path good = write("good.csv", log_text(40, 4.41e-8));
  std::string bad = log_text(40, 4.41e-8);
  bad.replace(bad.find("33.1"), 4, "3x.1");
  const fs::path badf = write("bad.csv", bad);
  const CliRun r = run("--fit '" + badf.string() + "' --check '" + good.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("bad.csv:2:"), std::string::npos) << r.out;
}

TEST(GapCli, MissingFileAndTooShortLogExitTwo) {
  const fs::path good = write("good.csv", log_text(40, 4.41e-8));
  EXPECT_EQ(run("--fit /nonexistent/x.csv --check '" + good.string() + "'").exit_code, 2);
  const fs::path tiny = write("tiny.csv", log_text(3, 4.41e-8));
  const CliRun r = run("--fit '" + tiny.string() + "' --check '" + good.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
}

TEST(GapCli, JsonHasEquationsForEveryPressureNodeAndTheShaft) {
  const fs::path a = write("a.csv", log_text(400, 3e-8));
  const fs::path b = write("b.csv", log_text(300, 6e-8));
  const CliRun r = run("--fit '" + a.string() + "' --check '" + b.string() + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out.substr(r.out.find('{')), nullptr, false);
  ASSERT_TRUE(j.is_object()) << r.out;
  std::string names;
  for (const auto& e : j["where"]["check"]["equations"]) {
    names += e["equation"].get<std::string>() + " ";
    for (const char* k : {"unit", "mean", "rms", "rms_over_noise"}) EXPECT_TRUE(e.contains(k)) << k;
  }
  EXPECT_EQ(names, "flow:p_mi flow:p_mo flow:p_pp torque:w_m ");
}

// The report folder's plots.gp names its files relative to the folder, so the plots
// redraw from inside it (cd DIR && gnuplot plots.gp), wherever gap ran.
TEST(GapCli, ReportPlotsRedrawFromInsideTheFolder) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
  const fs::path log = write("report.csv", log_text(400, 6e-8));
  const fs::path dir = log.parent_path() / "report";
  fs::remove_all(dir);
  const CliRun r = run("--fit '" + log.string() + "' --check '" + log.string() + "' --report '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  ASSERT_TRUE(fs::exists(dir / "plots.gp"));
  fs::remove(dir / "residual_time.png");
  EXPECT_EQ(std::system(("cd '" + dir.string() + "' && gnuplot plots.gp 2>/dev/null").c_str()), 0);
  EXPECT_TRUE(fs::exists(dir / "residual_time.png"));
  fs::remove_all(dir);
}

}  // namespace
