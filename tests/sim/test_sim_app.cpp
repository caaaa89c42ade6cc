// Smoke tests of the hstmon-sim executable.
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

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(SimApp, BlockageLogAt1HzInBarAndRpm) {
  const std::string out = tmp_path("blockage.csv");
  ASSERT_EQ(run("--scenario prv_blockage --rate 1 --seed 1 --rpm --out " + out), 0);
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 122u);  // header + 0..120 s
  EXPECT_EQ(lines[0], "t[s],p_sup[bar],p_s[bar],p_bp[bar],kp[m^3/(s*Pa^0.5)],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]");
  EXPECT_EQ(lines[1].rfind("0,35,0,10,4.41e-08,", 0), 0u);
  EXPECT_EQ(lines[121].rfind("120,35,0,10,4.41e-08,", 0), 0u);
  std::remove(out.c_str());
}

TEST(SimApp, SameSeedSameFileAndPaperModel) {
  const std::string a = tmp_path("a.csv"), b = tmp_path("b.csv"), p = tmp_path("p.csv");
  ASSERT_EQ(run("--scenario start_from_rest --rate 100 --seed 9 --units Pa --out " + a), 0);
  ASSERT_EQ(run("--scenario start_from_rest --rate 100 --seed 9 --units Pa --out " + b), 0);
  EXPECT_EQ(lines_of(a), lines_of(b));
  EXPECT_EQ(lines_of(a).size(), 202u);
  ASSERT_EQ(run("--model paper --scenario paper_start --duration 0.5 --no-noise --out " + p), 0);
  const auto lp = lines_of(p);
  ASSERT_EQ(lp.size(), 252u);  // 500 Hz for 0.5 s
  EXPECT_EQ(lp[0], "t[s],a_dcv[m^2],a_prv[m^2],p_pump[bar],p_mi[bar],p_pp[bar],w_m[rad/s]");
  for (const auto& f : {a, b, p}) std::remove(f.c_str());
}

TEST(SimApp, RigRunWithEveryConditionSwitched) {
  const std::string out = tmp_path("rig.csv");
  ASSERT_EQ(run("--scenario rig --preset rig_fast --rate 100 --lag 2 --quant 0.01 --param-error 0.02 "
                "--start rest --supply-on 0.2 --cycle 1,0.5 --load sine --load-period 1 --blockage 2.5 "
                "--duration 3 --rpm --out " + out),
            0);
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 302u);  // header + 0..3 s at 100 Hz
  EXPECT_EQ(lines[1].rfind("0,0,0,10,", 0), 0u) << "supply still off at the first sample";
  EXPECT_EQ(lines[21].rfind("0.2,35,0,10,", 0), 0u) << lines[21];
  EXPECT_NE(run("--scenario rig --quant 0.01 --adc-bits 12 --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--scenario rig --load square --out /dev/null 2>/dev/null"), 0);
  std::remove(out.c_str());
}

TEST(SimApp, RejectsMismatchedModelAndUnknownScenario) {
  EXPECT_NE(run("--model paper --scenario prv_blockage --out /dev/null 2>/dev/null"), 0);
  EXPECT_NE(run("--scenario no_such --out /dev/null 2>/dev/null"), 0);
}

}  // namespace
