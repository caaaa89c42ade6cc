#pragma once
/// @file evidence.hpp
/// The least a log must hold before `gap` gives a verdict (docs/gap.md, "Evidence"): at
/// least kMinSettings steady settings of at least kMinSamples samples each, whose inputs
/// span at least kMinSpan of their largest value on some input. Fewer settings cannot
/// tell an effect's shape over the operating range from a parameter's or an offset's;
/// fewer samples leave a setting's mean to a few readings of the noise.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace hstmon::gap::detail {

constexpr std::size_t kMinSettings = 3;
constexpr std::size_t kMinSamples = 5;
constexpr double kMinSpan = 0.05;

struct SettingEvidence {
  std::size_t samples = 0;      ///< steady samples
  std::vector<double> inputs;   ///< the held inputs
};

/// What `which` log lacks, or "" when it has enough.
inline std::string missing_evidence(const std::string& which, const std::vector<SettingEvidence>& settings) {
  std::size_t used = 0;
  std::vector<double> lo, hi, big;
  for (const auto& s : settings) {
    if (s.samples < kMinSamples) continue;
    ++used;
    lo.resize(s.inputs.size(), HUGE_VAL);
    hi.resize(s.inputs.size(), -HUGE_VAL);
    big.resize(s.inputs.size(), 0.0);
    for (std::size_t i = 0; i < s.inputs.size(); ++i) {
      lo[i] = std::min(lo[i], s.inputs[i]);
      hi[i] = std::max(hi[i], s.inputs[i]);
      big[i] = std::max(big[i], std::fabs(s.inputs[i]));
    }
  }
  char b[320];
  if (used < kMinSettings) {
    std::snprintf(b, sizeof b,
                  "the %s log has %zu steady setting(s) of at least %zu samples (%zu held-input stretches in all); "
                  "at least %zu are needed",
                  which.c_str(), used, kMinSamples, settings.size(), kMinSettings);
    return b;
  }
  double span = 0;
  for (std::size_t i = 0; i < lo.size(); ++i) {
    if (big[i] > 0) span = std::max(span, (hi[i] - lo[i]) / big[i]);
  }
  if (span < kMinSpan) {
    std::snprintf(b, sizeof b,
                  "the %s log's steady settings span %.1f %% of their inputs' values; at least %.0f %% on some input "
                  "is needed",
                  which.c_str(), 100.0 * span, 100.0 * kMinSpan);
    return b;
  }
  return {};
}

}  // namespace hstmon::gap::detail
