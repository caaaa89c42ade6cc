// What `hstmon gap` does not call a gap, and when it does not judge:
// - a perfect model logged at 100 Hz through a coarse (0.1 bar) ADC: the successive
//   differences read ~0, the quantisation floor step/√12 holds — no_significant_gap;
// - a machine whose parameters differ from the file's within their stated ±2 %: well
//   above the sensor noise, inside the parameter uncertainty — no_significant_gap;
// - logs too short to hold three steady settings: insufficient_data, nothing named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hstmon_gap/gap.hpp"
#include "hstmon_gap/synth.hpp"

namespace {

using namespace hstmon::gap;
using hstmon::host::Signal;

GapResult run(const hstmon::host::LogData& fit, const hstmon::host::LogData& check,
              const hstmon::ThesisParams<double>& model = {}) {
  EXPECT_TRUE(fit.ok() && check.ok());
  GapResult r = run_gap(fit, check, model, hstmon::ThesisInputs<double>{});
  std::printf("verdict %s: %s\n", r.verdict.c_str(), r.verdict_text.c_str());
  return r;
}

hstmon::host::LogData make(char profile, double duration, double rate, const ExtendedModel& truth,
                           const SynthNoise& noise, std::uint64_t seed) {
  InputSeries u = staircase_profile(profile, duration, rate);
  u.start = StartRule::kSteady;
  return synth_log(truth, u, noise, seed, std::string(1, profile));
}

// Every pressure reading rounded to the ADC's step.
void quantise(hstmon::host::LogData& log, double step) {
  for (Signal s : {Signal::kPMi, Signal::kPMo, Signal::kPPp}) {
    for (double& v : log.values[hstmon::host::index(s)]) v = step * std::round(v / step);
  }
}

TEST(GapFloor, PerfectModelThroughCoarseAdcIsNoGap) {
  const SynthNoise fine{1e3, 0.05};  // 0.01 bar: far below the 0.1 bar step
  auto fit = make('A', 6.0, 100.0, ExtendedModel{}, fine, 41);
  auto check = make('B', 4.0, 100.0, ExtendedModel{}, fine, 42);
  quantise(fit, 1e4);
  quantise(check, 1e4);
  const GapResult r = run(fit, check);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.verdict, "no_significant_gap");
  const auto& p = r.where_check.channels[2];  // p_pp
  EXPECT_NEAR(p.adc_step, 1e4, 1.0);
  EXPECT_GE(p.noise, 1e4 / std::sqrt(12.0) - 1.0);
}

TEST(GapFloor, ParametersWithinTheirUncertaintyAreNoGap) {
  ExtendedModel truth;
  truth.nominal.Dm *= 1.012;
  truth.nominal.Rf *= 0.985;
  truth.nominal.kf *= 1.01;
  const GapResult r = run(make('A', 6.0, 200.0, truth, {}, 43), make('B', 4.0, 200.0, truth, {}, 44));
  ASSERT_TRUE(r.ok) << r.error;
  // Far above the sensor noise on its own ...
  double worst = 0;
  for (const auto& c : r.where_check.channels) {
    std::printf("rms/noise %.2f, within uncertainty %.2f\n", c.rms_w, c.rms_w_within);
    worst = std::max(worst, c.present ? c.rms_w : 0.0);
  }
  std::printf("z %.2f\n", r.where_check.uncertainty_z);
  for (const auto& [n, v] : r.where_check.parameter_moves) std::printf("  %s %+.4f\n", n.c_str(), v);
  EXPECT_GT(worst, 3.0);
  // ... and inside what ±2 % on the parameters makes.
  EXPECT_EQ(r.verdict, "no_significant_gap");
}

TEST(GapFloor, ShortLogIsInsufficientData) {
  ExtendedModel truth;
  truth.effects.push_back({Effect::kCoulombFriction, {1.5}});
  const GapResult r = run(make('A', 1.2, 200.0, truth, {}, 45), make('B', 1.2, 200.0, truth, {}, 46));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.verdict, "insufficient_data");
  EXPECT_NE(r.evidence_missing.find("steady setting"), std::string::npos) << r.evidence_missing;
  EXPECT_TRUE(r.ranking.empty());
}

}  // namespace
