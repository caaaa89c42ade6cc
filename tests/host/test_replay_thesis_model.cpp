// `hstmon replay` on either implementation of the thesis equations (ReplayOptions::thesis,
// --thesis-model): the hand-written specialisation (the default, for speed) and the engine's
// thesis.json give the same replay of the shipped logs — the same events at the same times
// with the same candidates, and residual statistics equal to 1e-9.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"

namespace {

using namespace hstmon;

class ReplayThesisModel : public ::testing::TestWithParam<const char*> {};

TEST_P(ReplayThesisModel, EngineReplaysAsTheSpecialisation) {
  const std::string path = std::string(HSTMON_EXAMPLES_DIR) + "/" + GetParam();
  const host::LogData log = host::read_log(path);
  ASSERT_TRUE(log.ok()) << path;
  host::ReplayOptions spec;
  host::ReplayOptions engine;
  engine.thesis = ThesisImpl::kEngine;
  const host::ReplayResult a = host::replay(log, ThesisParams<double>{}, ThesisInputs<double>{}, spec);
  const host::ReplayResult b = host::replay(log, ThesisParams<double>{}, ThesisInputs<double>{}, engine);
  const auto outcome = [](const host::ReplayResult& r) {
    return std::make_tuple(r.ticks, r.start, r.final_status, r.health, r.max_substeps);
  };
  EXPECT_EQ(outcome(a), outcome(b));
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].t, b.events[i].t) << i;
    EXPECT_EQ(a.events[i].event, b.events[i].event) << i;
    ASSERT_EQ(a.events[i].candidates.size(), b.events[i].candidates.size()) << i;
    for (std::size_t j = 0; j < a.events[i].candidates.size(); ++j) {
      EXPECT_EQ(a.events[i].candidates[j].fault, b.events[i].candidates[j].fault);
      EXPECT_NEAR(a.events[i].candidates[j].score, b.events[i].candidates[j].score, 1e-9);
    }
  }
  for (std::size_t c = 0; c < 4; ++c) {
    const double scale = c < 3 ? 1e5 : 1.0;  // 1 bar; 1 rad/s
    EXPECT_EQ(a.channels[c].n, b.channels[c].n);
    EXPECT_NEAR(a.channels[c].rms(), b.channels[c].rms(), 1e-9 * (a.channels[c].rms() + scale)) << c;
    EXPECT_NEAR(a.channels[c].max_abs, b.channels[c].max_abs, 1e-9 * (a.channels[c].max_abs + scale)) << c;
    EXPECT_NEAR(a.channels[c].mean(), b.channels[c].mean(), 1e-9 * scale) << c;
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedLogs, ReplayThesisModel,
                         ::testing::Values("prv_blockage.csv", "prv_blockage_das.csv", "prv_staircase_das.csv"));

}  // namespace
