// Issue 3's scenario through the whole host path: host_sim log of the thesis rig with a
// 50 % PRV blockage (kp halved at t = 80 s, not in the logged inputs) → CSV → replay →
// Monitor (observer, sensor checks, evaluator, matcher with the generated table).
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"
#include "hstmon_sim/log_layout.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace {

constexpr double kFaultTime = 80.0;  // [s]

hstmon::host::ReplayResult replay_scenario(const hstmon::sim::ThesisScenario& sc, double rate_hz) {
  const auto ms = hstmon::sim::measure(sc, hstmon::sim::thesis_fast_sensors(rate_hz), 11);
  std::ostringstream os;
  hstmon::sim::write_log(os, ms, {});
  const auto log = hstmon::host::read_log_from_memory(os.str(), "blockage.csv", {});
  EXPECT_TRUE(log.ok());
  return hstmon::host::replay(log, {}, {}, {});
}

// The PRV-blockage scenario shortened to 70 … 82 s (steady start) for test speed.
hstmon::sim::ThesisScenario short_blockage() {
  auto sc = hstmon::sim::thesis_prv_blockage();
  sc.schedule[1].t_start = 2.0;  // fault 2 s into the run
  sc.duration = 4.0;
  return sc;
}

TEST(ReplayDiagnosis, PrvBlockageDetectedAndIsolatedAsKpMinus) {
  for (double rate : {1000.0, 100.0}) {
    const auto r = replay_scenario(short_blockage(), rate);
    ASSERT_GE(r.events.size(), 2u) << "rate " << rate;
    const auto& det = r.events.front();
    EXPECT_EQ(det.event, "detected");
    const double fault_t = 2.0;
    const double delay = det.t - fault_t;
    std::printf("rate %.0f Hz: detected %.1f ms after the blockage\n", rate, delay * 1e3);
    EXPECT_GE(delay, 0.0) << "no alarm before the fault";
    EXPECT_LT(delay, rate >= 1000.0 ? 0.05 : 0.1);
    bool isolated_kp = false;
    for (const auto& e : r.events) {
      if (e.event != "isolated") continue;
      for (const auto& c : e.candidates) isolated_kp |= c.fault == "kp-";
      std::printf("rate %.0f Hz: isolated %.1f ms after the blockage, best %s\n", rate, (e.t - fault_t) * 1e3,
                  e.candidates.empty() ? "-" : e.candidates.front().fault.c_str());
      EXPECT_EQ(e.candidates.front().fault, "kp-");
    }
    EXPECT_TRUE(isolated_kp) << "rate " << rate;
    EXPECT_EQ(r.final_status, "isolated");
  }
}

TEST(ReplayDiagnosis, NominalLogRaisesNoEvent) {
  auto sc = hstmon::sim::thesis_prv_blockage();
  sc.schedule.resize(1);  // no fault
  sc.duration = 20.0;
  const auto r = replay_scenario(sc, 1000.0);
  EXPECT_TRUE(r.events.empty());
  EXPECT_EQ(r.final_status, "nominal");
}

TEST(ReplayDiagnosis, ShippedExampleIsIsolated) {
  const auto log = hstmon::host::read_log(std::string(HSTMON_SOURCE_DIR) + "/examples/prv_blockage.csv");
  ASSERT_TRUE(log.ok());
  const auto r = hstmon::host::replay(log, {}, {}, {});
  ASSERT_FALSE(r.events.empty());
  EXPECT_NEAR(r.events.front().t, kFaultTime, 0.05);
  EXPECT_EQ(r.final_status, "isolated");
}

}  // namespace
