// The independent simulator's gap logs (tests/data/validation/g_*, answers.json), judged by
// score_gap.py's rules on `hstmon gap` in process: nominal → no significant gap; an effect
// in the library → ranked first with shrink_check ≥ 0.8; outside the library → never
// `explained` while a check channel stays above 3× its noise. And the located equation
// (largest imbalance over noise on the check log) is the one answers.json names.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "hstmon_gap/gap.hpp"
#include "hstmon_host/log_reader.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace hstmon::gap;

const fs::path kData = fs::path(HSTMON_SOURCE_DIR) / "tests" / "data" / "validation";

// Decompresses name.csv.gz (gzip is on every Debian machine) and reads it.
hstmon::host::LogData read_gz(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hstmon_gap_validation_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path csv = dir / (name + ".csv");
  const std::string unzip = "gzip -dc '" + (kData / (name + ".csv.gz")).string() + "' > '" + csv.string() + "'";
  hstmon::host::LogData log;
  if (std::system(unzip.c_str()) != 0) return log;
  log = hstmon::host::read_log(csv.string());
  fs::remove(csv);
  return log;
}

class ValidationGap : public ::testing::TestWithParam<std::string> {};

TEST_P(ValidationGap, ScoresByTheValidationRules) {
  std::ifstream in(kData / "answers.json");
  ASSERT_TRUE(in) << "tests/data/validation/answers.json";
  const Json c = Json::parse(in).at("gap").at(GetParam());
  const auto fit = read_gz(GetParam() + "_fit");
  const auto check = read_gz(GetParam() + "_check");
  ASSERT_TRUE(fit.ok() && check.ok());
  const GapResult r = run_gap(fit, check, hstmon::ThesisParams<double>{}, hstmon::ThesisInputs<double>{});
  ASSERT_TRUE(r.ok) << r.error;
  std::printf("[%s] %s\n", GetParam().c_str(), r.verdict_text.c_str());
  // Every log starts at rest: the run starts from the measured first sample.
  if (c.at("effect").is_null()) {
    EXPECT_EQ(r.verdict, "no_significant_gap");
    return;
  }
  ASSERT_NE(r.where_check.located, -1);
  EXPECT_EQ(equation_names()[static_cast<std::size_t>(r.where_check.located)], c.at("equation").get<std::string>());
  if (c.at("in_library").get<bool>()) {
    ASSERT_FALSE(r.ranking.empty());
    EXPECT_EQ(r.ranking.front().name, c.at("effect").get<std::string>());
    EXPECT_GE(r.ranking.front().shrink_check, 0.8);
  } else {
    double worst = 0;
    if (!r.ranking.empty()) {
      for (std::size_t k = 0; k < kChannels; ++k) {
        const auto& ch = r.where_check.channels[k];
        if (ch.present) worst = std::max(worst, r.ranking.front().rms_after_check[k] / ch.noise);
      }
    }
    EXPECT_FALSE(r.verdict.rfind("explained", 0) == 0 && worst > 3.0) << r.verdict_text;
    EXPECT_NE(r.verdict.rfind("explained", 0), 0u) << "nothing in the library has this effect";
    ASSERT_FALSE(r.discovered.empty());
    EXPECT_EQ(r.discovered.front().equation, c.at("equation").get<std::string>());
  }
}

INSTANTIATE_TEST_SUITE_P(Independent, ValidationGap,
                         ::testing::Values("g_nominal", "g_coulomb", "g_load_pump_leakage"),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
