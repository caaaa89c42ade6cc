// What `hstmon gap` does not call a gap, and when it does not judge:
// - a perfect model logged at 100 Hz through a coarse (0.1 bar) ADC: the successive
//   differences read ~0, the quantisation floor step/√12 holds — no_significant_gap;
// - a perfect model logged at 4.8 kHz: the few transient rows the gap's integrator gets
//   slightly wrong make one log "significant", but the withheld log is at noise and no
//   effect shrinks it — no_significant_gap, not an effect that explains nothing;
// - a perfect model logged at 4.8 kHz with a ±0.6 bar 20 Hz ripple on every pressure (a
//   pump's or a stand's, which no model here reproduces): the successive differences read
//   a tenth of it, the scatter around the moving mean holds — no_significant_gap; the same
//   logs of a machine with Coulomb friction still show their gap;
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

// A sinusoidal ripple of amplitude `a` [Pa] at `hz` on every pressure reading.
void add_ripple(hstmon::host::LogData& log, double a, double hz) {
  const std::vector<double>& t = log.t;
  for (Signal s : {Signal::kPMi, Signal::kPMo, Signal::kPPp}) {
    std::vector<double>& y = log.values[hstmon::host::index(s)];
    for (std::size_t k = 0; k < y.size() && k < t.size(); ++k) y[k] += a * std::sin(2.0 * M_PI * hz * t[k]);
  }
}

TEST(GapFloor, PerfectModelAt4k8IsNoGap) {
  const SynthNoise fine{2e3, 0.3};  // 0.02 bar, 0.3 rpm white
  const GapResult r =
      run(make('A', 6.0, 4800.0, ExtendedModel{}, fine, 47), make('B', 4.0, 4800.0, ExtendedModel{}, fine, 48));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.verdict, "no_significant_gap");
}

TEST(GapFloor, PerfectModelWithRippleAt4k8IsNoGapAndARealGapStillShows) {
  const SynthNoise fine{2e3, 0.3};  // 0.02 bar, 0.3 rpm white
  auto fit = make('A', 6.0, 4800.0, ExtendedModel{}, fine, 47);
  auto check = make('B', 4.0, 4800.0, ExtendedModel{}, fine, 48);
  add_ripple(fit, 0.6e5, 20.0);
  add_ripple(check, 0.6e5, 20.0);
  const GapResult r = run(fit, check);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.verdict, "no_significant_gap");
  const auto& p = r.where_check.channels[2];       // p_pp
  EXPECT_LT(p.noise_white, 0.2 * p.noise_spread);  // successive differences miss the ripple
  EXPECT_GT(p.noise, 0.3e5);

  ExtendedModel truth;
  truth.effects.push_back({Effect::kCoulombFriction, {1.5}});
  auto fit_f = make('A', 6.0, 4800.0, truth, fine, 49);
  auto check_f = make('B', 4.0, 4800.0, truth, fine, 50);
  add_ripple(fit_f, 0.6e5, 20.0);
  add_ripple(check_f, 0.6e5, 20.0);
  const GapResult g = run(fit_f, check_f);
  ASSERT_TRUE(g.ok) << g.error;
  EXPECT_NE(g.verdict, "no_significant_gap");
  EXPECT_NE(g.verdict, "insufficient_data");
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
