// Transmitter ranges for the replay's sensor checks: a parameter file's "sensors" section
// (units, null for no end, channels left out keep the thesis rig's ranges; every refusal
// with its line:column), and what the ranges do to a replay — a reading at the bottom of a
// range is a broken 4–20 mA loop, flagged on its first sample.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../support/params_errors.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/params_file.hpp"
#include "hstmon_host/replay.hpp"
#include "hstmon_host/sensor_ranges.hpp"

namespace hh = hstmon::host;

namespace {

constexpr double kBar = 1e5;                // [Pa]
constexpr double kRpm = M_PI / 30.0;        // [rad/s]
constexpr double kInf = std::numeric_limits<double>::infinity();

using hstmon_test::parse;

/// A thesis parameter file with `section` as its "sensors" section.
std::string with_sensors(const std::string& section) { return R"({"model": "thesis", "sensors": )" + section + "}"; }

TEST(SensorRanges, ThesisDefaults) {
  const hh::SensorRanges d = hh::thesis_sensor_ranges();
  EXPECT_EQ(d.lo[0], 0.0);
  EXPECT_EQ(d.hi[0], 200 * kBar);  // WIKA S-10, 0–200 bar (Table 2.1)
  EXPECT_EQ(d.hi[1], 200 * kBar);
  EXPECT_EQ(d.hi[2], 250 * kBar);  // assumed (the blockage reads 226.8 bar)
  EXPECT_NEAR(d.lo[3], -3000 * kRpm, 1e-12);
  EXPECT_NEAR(d.hi[3], 3000 * kRpm, 1e-12);
  const hh::SensorRanges l = hh::ReplayOptions{}.sensors;
  EXPECT_EQ(l.lo[2], d.lo[2]) << "replay's default: the live zeros";
  EXPECT_EQ(l.hi[2], kInf) << "replay's default: no assumed high end";
}

TEST(SensorRanges, ParamsFileSection) {
  const auto r = parse(R"json({
  "model": "thesis",
  "sensors": {"p_pp": ["0 bar", "400 bar"], "w_m": [null, "3000 rpm"], "p_mi": [-1e5, 2e7]}
})json");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  ASSERT_TRUE(r.sensors.has_value());
  const hh::SensorRanges d = hh::thesis_sensor_ranges();
  EXPECT_EQ(r.sensors->lo[0], -1e5);
  EXPECT_EQ(r.sensors->hi[0], 2e7);
  EXPECT_EQ(r.sensors->lo[1], d.lo[1]) << "p_mo not named: the thesis rig's";
  EXPECT_EQ(r.sensors->hi[1], d.hi[1]);
  EXPECT_EQ(r.sensors->hi[2], 400 * kBar);
  EXPECT_EQ(r.sensors->lo[3], -kInf);
  EXPECT_NEAR(r.sensors->hi[3], 3000 * kRpm, 1e-12);
  EXPECT_FALSE(parse(R"({"model": "thesis"})").sensors.has_value()) << "no section: the caller's default";
  const auto off = parse(R"({"model": "thesis", "sensors": {"p_mi": [null, null], "p_mo": [null, null],
                             "p_pp": [null, null], "w_m": [null, null]}})");
  ASSERT_TRUE(off.ok()) << off.error->to_string();
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(off.sensors->lo[static_cast<std::size_t>(c)], -kInf);
    EXPECT_EQ(off.sensors->hi[static_cast<std::size_t>(c)], kInf);
  }
}

// Each refused "sensors" section: one error at its line:column, and nothing kept.
class SensorRangesRefusal : public testing::TestWithParam<hstmon_test::ErrorCase> {};

TEST_P(SensorRangesRefusal, PointsAtTheMistake) { hstmon_test::expect_params_refused(GetParam()); }

// One case a line.
// clang-format off
const hstmon_test::ErrorCase kRefused[] = {
    {"SensorsSection", "{\"model\": \"thesis\",\n \"sensr\": {}}", 2, 2, "or 'sensors' (transmitter ranges)"},
    {"SensorsSection", with_sensors("[0, 1]"), 1, 32, "'sensors' must be an object"},
    {"SensorsSection", with_sensors(R"({"p_sup": [0, 1]})"), 1, 33, "unknown key 'p_sup' in 'sensors' (known: p_mi, p_mo, p_pp, w_m)"},
    {"SensorsSection", with_sensors(R"({"p_mi": 2e7})"), 1, 41, "sensors.p_mi must be a range [low, high]"},
    {"SensorsSection", with_sensors(R"({"p_mi": [0, 1, 2]})"), 1, 41, "must be a range [low, high]"},
    {"SensorsSection", with_sensors(R"({"p_mi": ["200 bar", "0 bar"]})"), 1, 41, "sensors.p_mi: the low end must be below the high end, got [20000000, 0] Pa"},
    {"SensorsSection", with_sensors(R"({"p_mi": [0, 0]})"), 1, 41, "the low end must be below"},
    {"SensorsSection", with_sensors(R"({"p_pp": ["0 rpm", "250 bar"]})"), 1, 41, "sensors.p_pp low end: unknown pressure unit 'rpm'"},
    {"SensorsSection", with_sensors(R"({"w_m": [0, "3000 bar"]})"), 1, 40, "sensors.w_m high end: unknown speed unit 'bar'"},
    {"SensorsSection", with_sensors(R"({"w_m": [true, 1]})"), 1, 40, "sensors.w_m low end must be a number [rad/s], a string with a unit, or null, got boolean"},
    {"SensorsSection", with_sensors(R"({"p_mo": [0, "1e308 bar"]})"), 1, 41, "not finite"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(ParamsFileRefusals, SensorRangesRefusal, testing::ValuesIn(kRefused),
                         hstmon_test::error_case_name);

// A 100 Hz log with p_pp at 0 bar for 1 s: with the thesis rig's ranges it is out of range
// on the first sample; with a file that puts the live zero lower (a −10 bar range start)
// the same reading is in range, and only the stuck check finds it, 50 samples later.
TEST(SensorRanges, RangesDecideHowFastALoopBreakIsFlagged) {
  std::string text = "t[s],p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n";
  char buf[128];
  for (int k = 0; k < 400; ++k) {
    const double w = 0.05 * std::sin(1.7 * k);  // scatter, so nothing else repeats
    const double ppp = (k >= 100 && k < 200) ? 0.0 : 171.08 + w;
    std::snprintf(buf, sizeof buf, "%.2f,%.5f,%.5f,%.5f,%.4f\n", 0.01 * k, 33.18 + w, 1.9 - w, ppp, 1678.0 + 10 * w);
    text += buf;
  }
  const auto log = hh::read_log_from_memory(text, "loop_break.csv", {});
  ASSERT_TRUE(log.ok());
  auto first_sensor_event = [&](const hh::ReplayOptions& o) {
    const auto r = hh::replay(log, {}, {}, o);
    for (const auto& e : r.events) {
      if (e.event != "detected" && !e.candidates.empty() && e.candidates.front().fault == "sensor_p_pp") return e.t;
    }
    return -1.0;
  };
  hh::ReplayOptions o;
  o.init = hh::InitMode::kSteady;
  EXPECT_NEAR(first_sensor_event(o), 1.0, 1e-9) << "thesis ranges: out of range at once";
  const auto pf = parse(R"({"model": "thesis", "sensors": {"p_pp": ["-10 bar", "250 bar"]}})");
  ASSERT_TRUE(pf.ok() && pf.sensors);
  o.sensors = *pf.sensors;
  EXPECT_NEAR(first_sensor_event(o), 1.49, 1e-9) << "in range: stuck after 50 samples at 100 Hz";
}

}  // namespace
