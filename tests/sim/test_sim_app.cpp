// Smoke tests of the hstmon-sim executable: the thesis rig's named runs on the built-in
// thesis.json, a preset's sensor chain on paper.json, and what is refused.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string tmp_path(const std::string& name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir != nullptr ? dir : "/tmp") + "/hstmon_sim_test_" + name;
}

int run(const std::string& args) { return std::system((std::string(HSTMON_SIM_EXE) + " " + args).c_str()); }

/// The log's lines after its comments: the header, then the rows.
std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) {
    if (out.empty() && l.rfind("#", 0) == 0) continue;
    out.push_back(l);
  }
  return out;
}

/// Field i of a CSV row, as a number.
double field(const std::string& row, int i) {
  std::istringstream s(row);
  std::string f;
  for (int k = 0; k <= i; ++k) std::getline(s, f, ',');
  return std::stod(f);
}

TEST(SimApp, BlockageOnTheBuiltInThesisCircuitKeepsTheLoggedKp) {
  const std::string out = tmp_path("blockage.csv");
  ASSERT_EQ(run("--scenario prv_blockage --rate 1 --seed 1 --units bar --rpm --out " + out), 0);
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 121u);  // header + 0..119 s
  EXPECT_EQ(lines[0], "t[s],p_sup[bar],p_s[bar],p_bp[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]");
  EXPECT_EQ(lines[1].rfind("0,35,0,10,4.41e-08,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[120].rfind("119,35,0,10,4.41e-08,", 0), 0u) << lines[120];
  EXPECT_GT(field(lines[120], 7) - field(lines[80], 7), 50.0) << "p_pp rises once the PRV is half blocked";
  std::remove(out.c_str());
}

TEST(SimApp, SameSeedSameFileAndAPresetOnPaperJson) {
  const std::string a = tmp_path("a.csv"), b = tmp_path("b.csv"), p = tmp_path("p.csv");
  ASSERT_EQ(run("--scenario start_from_rest --rate 100 --seed 9 --units Pa --out " + a), 0);
  ASSERT_EQ(run("--scenario start_from_rest --rate 100 --seed 9 --units Pa --out " + b), 0);
  EXPECT_EQ(lines_of(a), lines_of(b));
  EXPECT_EQ(lines_of(a).size(), 201u);
  ASSERT_EQ(
      run("--circuit " + std::string(HSTMON_SOURCE_DIR) +
          "/examples/circuits/paper.json --start rest --preset paper_logger --duration 0.5 --no-noise --out " + p),
      0);
  const auto lp = lines_of(p);
  ASSERT_EQ(lp.size(), 251u);  // the logger's 500 Hz for 0.5 s
  EXPECT_EQ(lp[0], "t[s],a_dcv[mm2],a_prv[mm2],p_s[bar],p_mi[bar],p_pp[bar],w_m[rpm]");
  const double step = 250.0 / 4095.0;  // 12 bits over 0-250 bar
  for (std::size_t k = 1; k < lp.size(); ++k) {
    const double codes = field(lp[k], 3) / step;
    ASSERT_NEAR(codes, static_cast<double>(static_cast<long>(codes + 0.5)), 1e-4) << lp[k];
  }
  for (const auto& f : {a, b, p}) std::remove(f.c_str());
}

TEST(SimApp, RigRunWithEveryConditionSwitched) {
  const std::string out = tmp_path("rig.csv");
  ASSERT_EQ(run("--scenario rig --preset rig_fast --rate 100 --lag 2 --quant 0.01 --param-error 0.02 "
                "--start rest --supply-on 0.2 --cycle 1,0.5 --load sine --load-period 1 --blockage 2.5 "
                "--duration 3 --units bar --rpm --out " +
                out),
            0);
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 301u);  // header + 0..2.99 s at 100 Hz
  EXPECT_EQ(lines[1].rfind("0,0,0,10,", 0), 0u) << "supply still off at the first sample";
  EXPECT_EQ(lines[21].rfind("0.2,35,0,10,", 0), 0u) << lines[21];
  EXPECT_NE(run("--scenario rig --quant 0.01 --adc-bits 12 --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--scenario rig --load square --out /dev/null 2>/dev/null"), 0);
  std::remove(out.c_str());
}

TEST(SimApp, RejectsUnknownScenarioRigOptionsElsewhereAndAScenarioWithLoggedInputs) {
  EXPECT_NE(run("--scenario no_such --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--scenario prv_blockage --blockage 3 --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--scenario prv_blockage --inputs /dev/null --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--preset no_such --out /dev/null 2>/dev/null"), 0);
}

}  // namespace
