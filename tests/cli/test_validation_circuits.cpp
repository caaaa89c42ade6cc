// An independent hydraulic simulator's logs of two machines described by a user's circuit
// file (tests/data/validation_circuits: a closed-circuit HST; tests/data/validation_paper:
// the seed paper's rig with paper.json as shipped), through
// `hstmon replay --circuit C LOG.csv.gz --json`, judged by the rules of their answers.json
// (score_circuit.py, score_paper.py): no event on a nominal log nor before the fault; the
// first event no earlier than t_visible − 0.05 s and no later than t_steady + 5 s; the
// truth or a member of its class among the last event's candidates; no `cleared` after
// the fault (they all persist). The cases isolated today must stay isolated: the last
// event `isolated` with a class member first, or `ambiguous` within the class. And their
// gap cases through `hstmon gap --circuit`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../support/cli_events.hpp"
#include "../support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kData = fs::path(HSTMON_SOURCE_DIR) / "tests" / "data";

struct CliRun {
  int status = -1;
  std::vector<Json> events;
  std::string err;
};

CliRun replay(const fs::path& circuit, const fs::path& log) {
  const fs::path err = fs::temp_directory_path() / ("hstmon_validation_circuits_" + log.stem().string() + ".err");
  const std::string cmd = std::string("'") + HSTMON_CLI + "' replay --circuit '" + circuit.string() + "' '" +
                          log.string() + "' --json --no-progress 2>'" + err.string() + "'";
  hstmon_test::CliEvents run = hstmon_test::run_cli_events(cmd);
  CliRun r;
  r.status = run.status;
  r.events = std::move(run.events);
  std::ifstream e(err);
  r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
  return r;
}

struct Case {
  std::string set;   // folder under tests/data
  std::string name;  // log stem
  bool isolated;     // isolated on the truth or its class today
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.set << "/" << c.name; }

class ValidationCircuits : public ::testing::TestWithParam<Case> {};

TEST_P(ValidationCircuits, ScoresByTheSetsRules) {
  const Case& k = GetParam();
#if !defined(__OPTIMIZE__)
  // The closed-circuit HST takes about 5 s per 30 s log optimised (its stiff nodes need
  // up to 88 RK4 substeps per tick): minutes each at -O0. The optimised builds
  // (host-check's -O1, release, the sanitizers' RelWithDebInfo) judge these logs.
  if (k.set == "validation_circuits") GTEST_SKIP() << "closed-circuit logs run in optimised builds only";
#endif
  const fs::path dir = kData / k.set;
  std::ifstream in(dir / "answers.json");
  ASSERT_TRUE(in) << (dir / "answers.json");
  const Json answers = Json::parse(in);
  const Json& truth = answers.at("replay").at(k.name);
  const bool nominal = truth.at("truth").is_string();  // "none"

  const CliRun r = replay(dir / answers.at("circuit").get<std::string>(), dir / "logs" / (k.name + ".csv.gz"));
  ASSERT_EQ(r.status, 0) << r.err;
  if (nominal) {
    EXPECT_TRUE(r.events.empty()) << "false alarm: " << r.events.front().dump();
    return;
  }
  ASSERT_FALSE(r.events.empty()) << "not detected";
  const double t_inject = truth.at("t_inject").get<double>();
  const double first = r.events.front().at("t").get<double>();
  EXPECT_GE(first, t_inject) << "event before the fault: " << r.events.front().dump();
  EXPECT_GE(first, truth.at("t_visible").get<double>() - 0.05) << r.events.front().dump();
  EXPECT_LE(first, truth.at("t_steady").get<double>() + 5.0) << "detected too late";
  for (const Json& e : r.events) EXPECT_NE(e.at("event"), "cleared") << "cleared while the fault persists: " << e.dump();

  std::set<std::string> cls;
  for (const Json& f : truth.at("class")) cls.insert(f.get<std::string>());
  for (const Json& f : truth.at("truth")) cls.insert(f.get<std::string>());
  const Json& last = r.events.back();
  std::vector<std::string> names;
  for (const Json& c : last.at("candidates")) names.push_back(c.at("fault"));
  EXPECT_TRUE(std::any_of(names.begin(), names.end(), [&](const std::string& n) { return cls.count(n) > 0; }))
      << "truth not in the last event: " << last.dump();
  if (!k.isolated) return;
  const bool isolated_first = last.at("event") == "isolated" && !names.empty() && cls.count(names.front()) > 0;
  const bool within_class = last.at("event") == "ambiguous" && !names.empty() &&
                            std::all_of(names.begin(), names.end(), [&](const std::string& n) { return cls.count(n) > 0; });
  EXPECT_TRUE(isolated_first || within_class) << "not isolated: " << last.dump();
}

INSTANTIATE_TEST_SUITE_P(
    Logs, ValidationCircuits,
    ::testing::Values(
        Case{"validation_circuits", "nominal_A", false}, Case{"validation_circuits", "nominal_B", false},
        Case{"validation_circuits", "fault_motor_disp", true}, Case{"validation_circuits", "fault_pump_leak", true},
        Case{"validation_circuits", "fault_leak_B", true}, Case{"validation_circuits", "fault_relief_B", true},
        Case{"validation_circuits", "fault_speed_sensor", true}, Case{"validation_paper", "nominal_C", false},
        Case{"validation_paper", "nominal_D", false}, Case{"validation_paper", "fault_prv_block", true},
        Case{"validation_paper", "fault_friction", true}, Case{"validation_paper", "fault_dcv_block", true}),
    [](const ::testing::TestParamInfo<Case>& i) { return i.param.set.substr(11) + "_" + i.param.name; });

// A relief setting dropped below a later working pressure (fault_relief_B: 300 -> 165 bar,
// seen from 25 s when line B needs 171 bar): once named it stays named — no `unexplained`
// between the operating points after it — and its size is the setting's, because the
// fault moves the valve's whole characteristic (setting_shift.hpp), not its cracking
// pressure alone.
TEST(ValidationCircuitsSetting, ReliefSettingStaysIsolatedAtItsSize) {
#if !defined(__OPTIMIZE__)
  GTEST_SKIP() << "closed-circuit logs run in optimised builds only";
#endif
  const fs::path dir = kData / "validation_circuits";
  const CliRun r = replay(dir / "circuit.json", dir / "logs" / "fault_relief_B.csv.gz");
  ASSERT_EQ(r.status, 0) << r.err;
  bool named = false;
  for (const Json& e : r.events) {
    const bool isolated = e.at("event") == "isolated" && !e.at("candidates").empty() &&
                          e.at("candidates").front().at("fault") == "p_rv_b-";
    if (named) {
      EXPECT_TRUE(isolated) << "the relief setting, once isolated, was dropped: " << e.dump();
    }
    named = named || isolated;
  }
  ASSERT_TRUE(named) << "p_rv_b- never isolated";
  const Json& lead = r.events.back().at("candidates").front();
  EXPECT_NEAR(lead.at("size").get<double>() * 300e5, 165e5, 0.05 * 165e5) << lead.dump();
}

// The gap cases: `hstmon gap --circuit C --fit F --check K --json` names the truth's
// effect (or none) and, for an effect, its size within 20 % (score_*.py's rule).
struct GapCase {
  std::string set;
  std::string name;
};

void PrintTo(const GapCase& c, std::ostream* os) { *os << c.set << "/" << c.name; }

class ValidationCircuitsGap : public ::testing::TestWithParam<GapCase> {};

TEST_P(ValidationCircuitsGap, NamesTheEffectAndItsSize) {
  const GapCase& k = GetParam();
  const fs::path dir = kData / k.set;
  std::ifstream in(dir / "answers.json");
  ASSERT_TRUE(in) << (dir / "answers.json");
  const Json answers = Json::parse(in);
  const Json& g = answers.at("gap").at(k.name);
  const auto log = [&](const std::string& n) { return (dir / "logs" / (n + ".csv.gz")).string(); };
  const std::string cmd = std::string("'") + HSTMON_CLI + "' gap --circuit '" +
                          (dir / g.at("circuit").get<std::string>()).string() + "' --fit '" +
                          log(g.at("fit").get<std::string>()) + "' --check '" + log(g.at("check").get<std::string>()) +
                          "' --json 2>/dev/null";
  const hstmon_test::CliRun run = hstmon_test::run_command(cmd);
  const std::string& out = run.out;
  ASSERT_EQ(run.exit_code, 0) << out;
  const std::size_t brace = out.find('{');
  ASSERT_NE(brace, std::string::npos) << out;
  Json j;
  std::istringstream(out.substr(brace)) >> j;
  const std::string verdict = j.value("verdict", "");
  const std::string truth = g.at("truth");
  if (truth == "none") {
    EXPECT_TRUE(verdict == "none" || verdict == "no_significant_gap") << verdict;
    return;
  }
  ASSERT_EQ(verdict, truth);
  const Json ranked = j.value("ranked", Json::array());
  const auto named =
      std::find_if(ranked.begin(), ranked.end(), [&](const Json& r) { return r.value("effect", "") == verdict; });
  ASSERT_NE(named, ranked.end()) << "the verdict's effect is not ranked";
  const double size = g.at("size").get<double>();
  EXPECT_NEAR(named->at("magnitude").get<double>(), size, 0.2 * std::fabs(size));
}

INSTANTIATE_TEST_SUITE_P(Logs, ValidationCircuitsGap,
                         ::testing::Values(GapCase{"validation_circuits", "gap_none_nominal"},
                                           GapCase{"validation_circuits", "gap_drain_B"},
                                           GapCase{"validation_circuits", "gap_offset_p_a"},
                                           GapCase{"validation_paper", "gap_none"},
                                           GapCase{"validation_paper", "gap_leak_pmi"}),
                         [](const ::testing::TestParamInfo<GapCase>& i) {
                           return i.param.set.substr(11) + "_" + i.param.name;
                         });

}  // namespace
