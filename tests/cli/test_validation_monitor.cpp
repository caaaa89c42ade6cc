// The independent simulator's monitor logs (tests/data/validation, answers.json) through
// `hstmon replay --json`, judged by score_monitor.py's rules: no `detected` event before
// the fault or on a nominal log, exit status 0, and the true fault among the candidates of
// the last event at or after the fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/cli_events.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kData = fs::path(HSTMON_SOURCE_DIR) / "tests" / "data" / "validation";

// Replays name.csv.gz with the CLI (it reads gzip logs as they are).
hstmon_test::CliEvents replay(const std::string& name) {
  const std::string cmd =
      std::string("'") + HSTMON_CLI + "' replay '" + (kData / (name + ".csv.gz")).string() + "' --json";
  return hstmon_test::run_cli_events(cmd);
}

class ValidationMonitor : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidationMonitor, ScoresByTheValidationRules) {
  std::ifstream in(kData / "answers.json");
  ASSERT_TRUE(in) << "tests/data/validation/answers.json";
  const Json answers = Json::parse(in);
  const Json& c = answers.at("monitor").at(GetParam());
  const bool nominal = c.at("fault").is_null();
  const double t_fault = nominal ? 0.0 : c.at("t_fault").get<double>();

  const hstmon_test::CliEvents r = replay(GetParam());
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
