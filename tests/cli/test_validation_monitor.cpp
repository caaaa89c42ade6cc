// The independent simulator's monitor logs (tests/data/validation, answers.json) through
// `hstmon replay --json`, judged by score_monitor.py's rules: no `detected` event before
// the fault or on a nominal log, exit status 0, and the true fault among the candidates of
// the last event at or after the fault.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kData = fs::path(HSTMON_SOURCE_DIR) / "tests" / "data" / "validation";

struct CliRun {
  int status = -1;
  std::vector<Json> events;  // detected, isolated, ambiguous, unexplained, cleared
};

// Decompresses name.csv.gz (gzip is on every Debian machine) and replays it with the CLI.
CliRun replay(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hstmon_validation_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path csv = dir / (name + ".csv");
  const std::string unzip = "gzip -dc '" + (kData / (name + ".csv.gz")).string() + "' > '" + csv.string() + "'";
  CliRun r;
  if (std::system(unzip.c_str()) != 0) return r;
  const std::string cmd = std::string("'") + HSTMON_CLI + "' replay '" + csv.string() + "' --json";
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  fs::remove(csv);
  std::size_t a = 0;
  while (a < out.size()) {
    std::size_t b = out.find('\n', a);
    if (b == std::string::npos) b = out.size();
    const Json j = Json::parse(out.substr(a, b - a), nullptr, false);
    a = b + 1;
    if (j.is_object() && j.value("type", "") == "event") r.events.push_back(j);
  }
  return r;
}

class ValidationMonitor : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidationMonitor, ScoresByTheValidationRules) {
  std::ifstream in(kData / "answers.json");
  ASSERT_TRUE(in) << "tests/data/validation/answers.json";
  const Json answers = Json::parse(in);
  const Json& c = answers.at("monitor").at(GetParam());
  const bool nominal = c.at("fault").is_null();
  const double t_fault = nominal ? 0.0 : c.at("t_fault").get<double>();

  const CliRun r = replay(GetParam());
  ASSERT_EQ(r.status, 0);
  for (const Json& e : r.events) {
    if (e.at("event") != "detected") continue;
    const double t = e.at("t").get<double>();
    EXPECT_FALSE(nominal) << "false alarm at t = " << t << " s: " << e.dump();
    if (!nominal) {
      EXPECT_GE(t, t_fault) << "detected before the fault: " << e.dump();
    }
  }
  if (nominal) return;
  const Json* last = nullptr;
  for (const Json& e : r.events) {
    const std::string k = e.at("event");
    if ((k == "isolated" || k == "detected" || k == "ambiguous") && e.at("t").get<double>() >= t_fault &&
        !e.at("candidates").empty()) {
      last = &e;
    }
  }
  ASSERT_NE(last, nullptr) << "no event with candidates after the fault";
  std::vector<std::string> names;
  for (const Json& k : last->at("candidates")) names.push_back(k.at("fault"));
  EXPECT_NE(std::find(names.begin(), names.end(), c.at("fault").get<std::string>()), names.end())
      << "truth " << c.at("fault") << " not in " << last->dump();
}

INSTANTIATE_TEST_SUITE_P(Logs, ValidationMonitor,
                         ::testing::Values("m_nominal_steps_1khz", "m_nominal_steps_100hz_lag", "m_kp_minus",
                                           "m_rbl_plus", "m_bias_p_mi", "m_stuck_w_m"));

}  // namespace
