// Bad data gives a clear message (naming the file where there is one) and a non-zero exit,
// through the API and through `hstmon identify`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "hstmon_host/params_file.hpp"

#include "hstmon_ident/operating_points.hpp"
#include "hstmon_ident/steady_windows.hpp"
#include "hstmon_ident/thesis_fit.hpp"
#include "synthetic_logs.hpp"

#include "../support/cli_run.hpp"

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

// Writes a thesis log (bar, rad/s) from LogData columns.
std::string write_log(const fs::path& path, const host::LogData& log) {
  using host::Signal;
  std::ofstream f(path);
  f << "t[s],p_sup[bar],p_s[bar],p_bp[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rad/s]\n";
  const Signal cols[] = {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp, Signal::kPMi, Signal::kPMo, Signal::kPPp, Signal::kWm};
  for (std::size_t i = 0; i < log.rows(); ++i) {
    f << log.t[i];
    for (Signal s : cols) {
      const double v = log.column(s)[i];
      f << ',' << (s == Signal::kKp || s == Signal::kWm ? v : v * 1e-5);
    }
    f << '\n';
  }
  return path.string();
}

TEST(IdentErrors, TooFewOperatingPoints) {
  const auto log = testing::steady_staircase_log(1, {}, 10, sim::thesis_das_sensors(), {1.0, 0.5});
  const auto w = find_steady_windows(log);
  std::vector<OperatingPoint> pts;
  std::vector<std::string> settings;
  append_operating_points(log, w, {}, pts, settings);
  const auto r = fit_thesis_steady(pts, settings);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->find("too few operating points"), std::string::npos) << *r.error;

  const fs::path d = temp_dir();
  const std::string file = write_log(d / "two_loads.csv", log);
  const CliRun run = run_hstmon("identify " + file + " --out " + (d / "p.json").string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("two_loads.csv"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("too few operating points"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(d / "p.json"));
}

TEST(IdentErrors, NoSteadyWindow) {
  const fs::path d = temp_dir();
  const fs::path file = d / "ramp.csv";
  {
    std::ofstream f(file);
    f << "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
    for (int i = 0; i < 200; ++i) f << i * 0.01 << ',' << 30 + 0.5 * i << ',' << 2 + 0.1 * i << ',' << 100 + i << ',' << 10 * i << '\n';
  }
  const CliRun run = run_hstmon("identify " + file.string() + " --out " + (d / "p.json").string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("ramp.csv: error: no steady window"), std::string::npos) << run.out;
}

/// Fits `count` windows at the nominal operating point, only Ppp and ωm measured, each
/// window its own kp; `noise` scales their sums of squares. kf and Rf + Rbl enter only
/// through one combination: the design is singular.
ThesisFitResult fit_windows_at_one_point(int count, double noise) {
  std::array<double, 4> y{};
  EXPECT_TRUE(thesis_steady_outputs(ThesisParams<double>{}, ThesisInputs<double>{}, y));
  std::vector<OperatingPoint> pts;
  std::vector<std::string> settings;
  for (int k = 0; k < count; ++k) {
    OperatingPoint p;
    p.source = "mem window " + std::to_string(k);
    p.setting = static_cast<std::size_t>(k);
    p.y = {NAN, NAN, y[2], y[3]};
    p.n = 10;
    p.ss = {0, 0, 9 * 25e6 * noise, 9 * 0.0036 * noise};
    pts.push_back(p);
    settings.push_back(p.source);
  }
  return fit_thesis_steady(pts, settings);
}

TEST(IdentErrors, SingularDesign) {
  const auto r = fit_windows_at_one_point(3, 1.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->find("singular design"), std::string::npos) << *r.error;
}

// Issue 16: with a kp per window there can be hundreds of parameters; the message names
// a few and counts the rest (it was 77,774 characters long).
TEST(IdentErrors, SingularDesignMessageStaysShort) {
  const auto r = fit_windows_at_one_point(300, 1e12);  // noise so large no kp is determined
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->find("singular design"), std::string::npos) << *r.error;
  EXPECT_LT(r.error->size(), 700u) << *r.error;
  EXPECT_NE(r.error->find(" more"), std::string::npos) << *r.error;
}

TEST(IdentErrors, NaNs) {
  auto log = testing::steady_staircase_log(2);
  const auto w = find_steady_windows(log);
  std::vector<OperatingPoint> pts;
  std::vector<std::string> settings;
  append_operating_points(log, w, {}, pts, settings);
  pts[2].y[1] = std::numeric_limits<double>::infinity();
  const auto r = fit_thesis_steady(pts, settings);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error->find("non-finite"), std::string::npos) << *r.error;
  log.values[host::index(host::Signal::kPMo)][5] = NAN;
  const auto wr = find_steady_windows(log);
  ASSERT_TRUE(wr.error.has_value());
  EXPECT_NE(wr.error->find("non-finite"), std::string::npos);

  const fs::path d = temp_dir();
  const fs::path file = d / "nan.csv";
  {
    std::ofstream f(file);
    f << "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n0,30,2,150,1600\n4,nan,2,150,1600\n";
  }
  const CliRun run = run_hstmon("identify " + file.string() + " --out " + (d / "p.json").string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("nan.csv:3"), std::string::npos) << run.out;
}

TEST(IdentErrors, UsageAndGoodRun) {
  EXPECT_EQ(run_hstmon("identify").exit_code, 1);
  const fs::path d = temp_dir();
  const std::string file = write_log(d / "good.csv", testing::steady_staircase_log(4));
  EXPECT_EQ(run_hstmon("identify " + file).exit_code, 1);  // --out missing
  const CliRun run = run_hstmon("identify " + file + " --out " + (d / "good.json").string() + " --header " +
                          (d / "good.hpp").string());
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("NOT IDENTIFIABLE"), std::string::npos);
  EXPECT_NE(run.out.find("RMS Error"), std::string::npos);
  const auto pf = host::read_params_file((d / "good.json").string());
  ASSERT_TRUE(pf.ok()) << pf.error->to_string();
  EXPECT_NEAR(pf.params->kf / ThesisParams<double>{}.kf, 1.0, 0.01);
  std::ifstream h(d / "good.hpp");
  const std::string text((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("do not edit"), std::string::npos);
  EXPECT_NE(text.find("constexpr ThesisParams<float>"), std::string::npos);
}

}  // namespace
}  // namespace hstmon::ident
