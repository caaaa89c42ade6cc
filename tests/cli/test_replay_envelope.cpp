// Does the thesis replay check that the model describes the machine before it names a
// fault? Logs of machines off Table 2.2, from rest with load steps, replayed as
// `hstmon replay` does (host::replay, the thesis rig's default monitor).
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
using hstmon_test::event_lines;

// A 6 s run from rest with load steps, on a machine whose parameters lie within ±spread
// of Table 2.2 (seeded), logged at 1 kHz.
hstmon::host::ReplayResult replay_machine(std::uint64_t machine, double spread) {
  sim::RigRun run;
  run.duration = 6.0;
  run.from_rest = true;
  run.load.shape = sim::LoadShape::kSteps;
  const auto ms = sim::measure(sim::thesis_rig_run(run), sim::rig_fast_sensors(1000.0), machine,
                               sim::perturbed_params(machine, spread));
  std::ostringstream os;
  sim::write_log(os, ms, {});
  const auto log = hstmon::host::read_log_from_memory(os.str(), "machine.csv", {});
  EXPECT_TRUE(log.ok());
  return hstmon::host::replay(log, {}, {}, {});
}

// Another machine (parameters up to ±50 % off): the model does not describe it, and no
// fault is named on it.
TEST(ReplayEnvelope, AnotherMachineIsOutOfTheEnvelopeAndNoFaultIsNamed) {
  for (std::uint64_t machine : {1u, 2u, 3u}) {
    const auto r = replay_machine(machine, 0.5);
    EXPECT_TRUE(r.envelope.checked && r.envelope.out) << machine << ": " << r.envelope.text;
    EXPECT_EQ(r.final_status, "out_of_envelope") << machine << ":\n" << event_lines(r);
    ASSERT_EQ(r.events.size(), 1u) << machine << ":\n" << event_lines(r);
    EXPECT_EQ(r.events.front().event, "out_of_envelope");
    EXPECT_TRUE(r.events.front().candidates.empty());
    EXPECT_NE(r.envelope.text.find("the model does not describe this machine"), std::string::npos);
  }
}

// The machine as the monitor's bound allows (±2 %, the stated parameter uncertainty):
// within the envelope, and nothing raised.
TEST(ReplayEnvelope, AMachineWithinTheStatedUncertaintyIsWithinTheEnvelope) {
  for (std::uint64_t machine : {4u, 5u, 6u}) {
    const auto r = replay_machine(machine, 0.02);
    EXPECT_TRUE(r.envelope.checked && !r.envelope.out) << machine << ": " << r.envelope.text;
    EXPECT_NE(r.envelope.text.find("within the model's envelope"), std::string::npos) << r.envelope.text;
    EXPECT_TRUE(r.events.empty()) << machine << ":\n" << event_lines(r);
    EXPECT_EQ(r.final_status, "nominal");
  }
}

// A 50 % PRV blockage from the first sample of a 0.5 s log from rest: detected once the
// start-up is over, before the machine was ever seen to match the model, and the log ends
// before a steady stretch could be judged: unverified, no fault named.
TEST(ReplayEnvelope, ADetectionOnAShortLogNeverSeenHealthyIsUnverified) {
  sim::RigRun run;
  run.duration = 0.5;
  run.from_rest = true;
  const auto sc = sim::with_input_fault(sim::thesis_rig_run(run), &hstmon::ThesisInputs<double>::kp, 0.5, 0.0);
  const auto ms = sim::measure(sc, sim::rig_fast_sensors(1000.0), 5, hstmon::ThesisParams<double>{});
  std::ostringstream os;
  sim::write_log(os, ms, {});
  const auto log = hstmon::host::read_log_from_memory(os.str(), "short.csv", {});
  ASSERT_TRUE(log.ok());
  const auto r = hstmon::host::replay(log, {}, {}, {});
  EXPECT_TRUE(r.envelope.unverified) << r.envelope.text;
  EXPECT_EQ(r.final_status, "unverified") << event_lines(r);
  ASSERT_EQ(r.events.size(), 1u) << event_lines(r);
  EXPECT_EQ(r.events.front().event, "unverified");
  EXPECT_NE(r.events.front().why.find("which named kp-"), std::string::npos) << event_lines(r);
}

}  // namespace
