// Issue 7: a transmitter at the top of its range is not a sensor fault. The thesis's PRV
// 50 % blockage raises Ppp from 171 to 227 bar (355 bar at the peak of the transient), past
// the 200 bar of the rig's WIKA S-10 transmitters (Table 2.1); at heavy load (kp = 0.65·kp0)
// from 209 to 248 bar, past 250 bar in the transient. The reading then sits at the range
// end: a stuck check would call that a frozen sensor and the diagnosis would switch from
// kp− to sensor_p_pp. The monitor must mask Ppp as saturated and keep diagnosing on the
// other channels. A loop break, which pins the reading LOW (≤ 4 mA), stays a sensor fault.
//
// Stream: host_sim's stiff reference of the thesis rig, steady, kp halved at 2 s (not in
// the logged inputs), through the 1 kHz sensor chain, Ppp clipped at its range end as an
// input card does.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/monitor.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"
#include "hstmon_sim/log_layout.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace {

namespace sim = hstmon::sim;
using Mon = hstmon::Monitor<double>;
using hstmon::MatchStatus;

constexpr double kFaultTime = 2.0;  // [s]
constexpr double kBar = 1e5;        // [Pa]

/// A PRV setting (kp = load·kp0) and the top of Ppp's transmitter range.
struct Case {
  double load;      ///< kp factor of the setting [-]
  double ppp_hi;    ///< Ppp range end [Pa]
  const char* what;
};
const Case kNominal200{1.0, 200 * kBar, "Table 2.2 load, Ppp 0-200 bar (Table 2.1 as listed)"};
const Case kHeavy250{0.65, 250 * kBar, "heavy load, Ppp 0-250 bar (host_sim's transmitter)"};

sim::SensorConfig sensors_for(const Case& c) {
  sim::SensorConfig s = sim::thesis_fast_sensors(1000.0);
  s.channels.at(2).range_hi = c.ppp_hi;
  return s;
}

/// Steady, kp halved at kFaultTime; pinned_low_from > 0: Ppp's loop breaks then.
sim::ThesisMeasurements blockage(const Case& c, double pinned_low_from = -1.0) {
  sim::ThesisScenario sc;
  sc.name = "blockage";
  hstmon::ThesisInputs<double> u;
  u.kp = sim::kThesisKpNominal * c.load;
  hstmon::ThesisInputs<double> blocked = u;
  blocked.kp *= 0.5;
  sc.schedule = {{0.0, u}, {kFaultTime, blocked}};
  sc.logged = {{0.0, u}};
  sc.duration = 4.0;
  sc.initial = sim::InitialCondition::kSteady;
  auto ms = sim::measure(sc, sensors_for(c), 5);
  if (pinned_low_from > 0) {
    for (auto& s : ms) {
      if (s.t >= pinned_low_from) s.y[2] = 0.0;  // the input card clamps 0 mA to the range start
    }
  }
  return ms;
}

struct MonitorRun {
  std::vector<Mon::Event> events;
  std::uint8_t saturated_seen = 0;
  std::uint8_t masked = 0, faults = 0;
  MatchStatus status = MatchStatus::kNominal;
  std::string names;  // consistent hypotheses at the end
  std::string dump() const {
    std::string s;
    for (const auto& e : events) {
      s += "  t=" + std::to_string(e.time) + " " + hstmon::to_string(e.kind);
      for (int j = 0; j < e.count; ++j) s += std::string(" ") + e.candidate[j].name;
      s += "\n";
    }
    return s;
  }
};

MonitorRun monitor(const Case& cs, const sim::ThesisMeasurements& log) {
  const sim::SensorConfig sensors = sensors_for(cs);
  Mon::Config c;
  c.observer.tick = 1e-3;
  for (int i = 0; i < 4; ++i) {
    const auto& ch = sensors.channels.at(static_cast<std::size_t>(i));
    c.evaluator.noise_sigma[i] = ch.noise_std;
    c.sensors.range_lo[i] = ch.range_lo;
    c.sensors.range_hi[i] = ch.range_hi;
  }
  Mon mon;
  EXPECT_EQ(mon.configure({}, c, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount), hstmon::Status::kOk);
  EXPECT_EQ(mon.reset_steady(log.front().u), hstmon::Status::kOk);
  MonitorRun r;
  Mon::Measurement m;
  m.valid = 0xF;
  for (const auto& s : log) {
    for (int i = 0; i < 4; ++i) m.y[i] = s.y[static_cast<std::size_t>(i)];
    mon.step(s.t, s.u, m);
    r.saturated_seen |= mon.sensors().saturated();
    Mon::Event e;
    while (mon.pop_event(e)) r.events.push_back(e);
  }
  r.masked = mon.matcher().sensor_masked();
  r.faults = mon.matcher().sensor_faults();
  r.status = mon.matcher().status();
  for (int j = 0; j < mon.matcher().candidate_count(); ++j) r.names += std::string(j ? "," : "") + mon.matcher().candidate(j).name;
  return r;
}

void expect_kp_minus_with_ppp_masked(const Case& c) {
  const auto log = blockage(c);
  std::size_t pinned = 0;
  for (const auto& s : log) pinned += s.y[2] == c.ppp_hi ? 1 : 0;
  ASSERT_GT(pinned, 10u) << "the scenario must pin Ppp at its range end";
  const MonitorRun r = monitor(c, log);
  std::printf("%s: Ppp at its range end in %zu samples; events\n%s  consistent at the end: %s\n", c.what, pinned,
              r.dump().c_str(), r.names.c_str());
  ASSERT_GE(r.events.size(), 2u) << r.dump();
  EXPECT_EQ(r.events.front().kind, hstmon::MatchEventKind::kDetected);
  EXPECT_NEAR(r.events.front().time, kFaultTime, 0.01);
  EXPECT_EQ(r.saturated_seen, 0b0100);
  EXPECT_EQ(r.masked, 0b0100) << "Ppp masked as evidence";
  EXPECT_EQ(r.faults, 0) << "but not a sensor fault";
  EXPECT_EQ(r.status, MatchStatus::kIsolated) << hstmon::to_string(r.status);
  ASSERT_GE(r.events.back().count, 1);
  EXPECT_STREQ(r.events.back().candidate[0].name, "kp-") << r.dump();
  for (const auto& e : r.events) {
    if (e.kind == hstmon::MatchEventKind::kUnexplained) ADD_FAILURE() << "unexplained\n" << r.dump();
    // A decision never names a sensor; the "detected" event lists what is consistent so far.
    if (e.kind == hstmon::MatchEventKind::kDetected) continue;
    for (int j = 0; j < e.count; ++j) EXPECT_NE(std::string(e.candidate[j].name).rfind("sensor_", 0), 0u) << r.dump();
  }
}

TEST(SaturatedTransmitter, PppPinnedHighByTheThesisBlockageKeepsKpMinus) { expect_kp_minus_with_ppp_masked(kNominal200); }
TEST(SaturatedTransmitter, PppPinnedHighAtHeavyLoadKeepsKpMinus) { expect_kp_minus_with_ppp_masked(kHeavy250); }

// The same run with Ppp's loop broken 1 s after the blockage: from then on Ppp reads the
// bottom of its range — a sensor fault, and only sensor_p_pp is left. The status stays
// "isolated"; the change of the isolated candidate is a further "isolated" event.
TEST(SaturatedTransmitter, LoopBreakAfterwardsIsSensorPpp) {
  const MonitorRun r = monitor(kNominal200, blockage(kNominal200, kFaultTime + 1.0));
  std::printf("then the loop breaks: events\n%s", r.dump().c_str());
  EXPECT_EQ(r.faults, 0b0100);
  EXPECT_EQ(r.status, MatchStatus::kIsolated);
  EXPECT_EQ(r.names, "sensor_p_pp");
  ASSERT_GE(r.events.size(), 3u) << r.dump();
  const auto& last = r.events.back();
  EXPECT_EQ(last.kind, hstmon::MatchEventKind::kIsolated) << r.dump();
  EXPECT_GE(last.time, kFaultTime + 1.0) << r.dump();
  ASSERT_GE(last.count, 1);
  EXPECT_STREQ(last.candidate[0].name, "sensor_p_pp") << r.dump();
  bool kp_isolated_before = false;
  for (const auto& e : r.events) {
    if (e.kind == hstmon::MatchEventKind::kIsolated && e.time < kFaultTime + 1.0 && e.count >= 1)
      kp_isolated_before = kp_isolated_before || std::string(e.candidate[0].name) == "kp-";
  }
  EXPECT_TRUE(kp_isolated_before) << r.dump();
}

// Through the host replay with the rig's ranges given (what a parameter file's "sensors"
// section sets): the same verdict.
TEST(SaturatedTransmitter, ReplayWithTheRigsRangesKeepsKpMinus) {
  const auto ms = blockage(kNominal200);
  std::ostringstream os;
  sim::write_log(os, ms, {});
  const auto log = hstmon::host::read_log_from_memory(os.str(), "heavy_blockage.csv", {});
  ASSERT_TRUE(log.ok());
  hstmon::host::ReplayOptions o;
  o.sensors.hi[2] = 200 * kBar;
  const auto r = hstmon::host::replay(log, {}, {}, o);
  std::string d;
  for (const auto& e : r.events) {
    d += "  t=" + std::to_string(e.t) + " " + e.event;
    for (const auto& c : e.candidates) d += " " + c.fault;
    d += "\n";
  }
  std::printf("replay:\n%s", d.c_str());
  ASSERT_GE(r.events.size(), 2u) << d;
  for (const auto& e : r.events) {
    if (e.event == "detected") continue;
    EXPECT_NE(e.event, "unexplained") << d;
    for (const auto& c : e.candidates) EXPECT_NE(c.fault.rfind("sensor_", 0), 0u) << d;
  }
  EXPECT_EQ(r.events.back().event, "isolated") << d;
  ASSERT_FALSE(r.events.back().candidates.empty()) << d;
  EXPECT_EQ(r.events.back().candidates.front().fault, "kp-") << d;
}

}  // namespace
