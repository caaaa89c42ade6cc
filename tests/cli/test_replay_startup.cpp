// Start-ups and transients through the whole host path (issue 12): logs of the rig as it
// is run — the logger starts before the supply, PRV steps every 2 s, fast or lagged
// transducers, a machine ±2 % off Table 2.2 — replayed as `hstmon replay` does.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"
#include "hstmon_sim/log_layout.hpp"
#include "hstmon_sim/machine_error.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/param_fault.hpp"
#include "hstmon_sim/rig_run.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "../support/replay_events.hpp"

namespace {

namespace sim = hstmon::sim;

sim::RigRun rig_from_rest(double duration) {
  sim::RigRun r;
  r.duration = duration;
  r.from_rest = true;
  r.load.shape = sim::LoadShape::kSteps;
  return r;
}

hstmon::host::ReplayResult replay(const sim::ThesisScenario& sc, double rate_hz, double lag_s) {
  sim::SensorConfig sensors = sim::rig_fast_sensors(rate_hz);
  for (auto& ch : sensors.channels) ch.tau = lag_s;
  const auto ms = sim::measure(sc, sensors, 5, sim::perturbed_params(7, 0.02));
  std::ostringstream os;
  sim::write_log(os, ms, {});
  const auto log = hstmon::host::read_log_from_memory(os.str(), "rig.csv", {});
  EXPECT_TRUE(log.ok());
  return hstmon::host::replay(log, {}, {}, {});
}

using hstmon_test::event_lines;

// From rest, load steps, every transducer from none to 10 ms: nothing is raised.
TEST(ReplayStartup, StartFromRestAndLoadStepsRaiseNothing) {
  for (double lag : {0.0, 3e-3, 10e-3}) {
    for (double rate : {1000.0, 100.0}) {
      const auto r = replay(sim::thesis_rig_run(rig_from_rest(7.0)), rate, lag);
      EXPECT_EQ(r.start, hstmon::InitialState::kMeasured);
      EXPECT_GT(r.startup_hold, 0.0) << "a start from rest has a start-up to wait for";
      EXPECT_TRUE(r.events.empty()) << "lag " << lag << " s, " << rate << " Hz:\n" << event_lines(r);
    }
  }
}

// A 50 % PRV blockage present from the first sample: the machine is never seen healthy,
// so the data cannot tell the fault from a model that does not fit this machine. The
// monitor detects it once the start-up is over; at the first steady stretch the envelope
// check withdraws the diagnosis and says what it had named.
TEST(ReplayStartup, FaultFromTheFirstSampleIsOutOfTheEnvelopeAndNamedAsWhatItResembles) {
  for (double rate : {1000.0, 100.0}) {
    const auto sc = sim::with_input_fault(sim::thesis_rig_run(rig_from_rest(3.0)), &hstmon::ThesisInputs<double>::kp,
                                          0.5, 0.0);
    const auto r = replay(sc, rate, 0.0);
    ASSERT_EQ(r.events.size(), 1u) << rate << " Hz:\n" << event_lines(r);
    EXPECT_EQ(r.events.front().event, "out_of_envelope");
    EXPECT_GE(r.events.front().t, r.startup_hold) << "not judged during the start-up";
    EXPECT_NE(r.events.front().why.find("which named kp-"), std::string::npos) << event_lines(r);
    EXPECT_EQ(r.final_status, "out_of_envelope");
    EXPECT_TRUE(r.envelope.checked && r.envelope.out) << r.envelope.text;
  }
}

// The same blockage from 2 s, after the machine was seen steady: the envelope holds, and
// the fault is detected after its onset and isolated.
TEST(ReplayStartup, FaultAfterTheFirstSteadyStretchIsIsolated) {
  for (double rate : {1000.0, 100.0}) {
    const auto sc = sim::with_input_fault(sim::thesis_rig_run(rig_from_rest(5.0)), &hstmon::ThesisInputs<double>::kp,
                                          0.5, 2.0);
    const auto r = replay(sc, rate, 0.0);
    EXPECT_TRUE(r.envelope.checked && !r.envelope.out) << r.envelope.text;
    ASSERT_FALSE(r.events.empty()) << rate << " Hz";
    EXPECT_EQ(r.events.front().event, "detected");
    EXPECT_GE(r.events.front().t, 2.0) << event_lines(r);
    EXPECT_LT(r.events.front().t, 2.05) << event_lines(r);
    EXPECT_EQ(r.final_status, "isolated") << event_lines(r);
    ASSERT_FALSE(r.events.back().candidates.empty());
    EXPECT_EQ(r.events.back().candidates.front().fault, "kp-") << event_lines(r);
  }
}

}  // namespace
