#pragma once
/// @file noise_floor.hpp
/// A channel's noise as the analysis judges "at noise" against (docs/gap.md, "Noise"): the
/// largest of three estimates on the steady stretches of a log, where the true signal holds
/// and data − model is the reading's own scatter:
///  - white noise: 1.4826·median|Δy|/√2 from successive differences;
///  - quantisation: q/√12, q the ADC step read off the data's value grid — the successive
///    differences read ~0 when most successive samples are equal, yet every reading is off
///    by up to q/2;
///  - coloured noise and ripple the model cannot reproduce: the robust scatter of y around
///    its centred moving mean over ±0.5 s (held to the stretch; over half a shorter
///    stretch), which successive differences miss when the ripple is slow.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace hstmon::gap::detail {

struct NoiseEstimate {
  double white = 0;    ///< from successive differences
  double step = 0;     ///< ADC step found on the value grid (0: none)
  double spread = 0;   ///< scatter around the ±0.5 s moving mean
  double noise() const { return std::max({white, step / std::sqrt(12.0), spread}); }
};

inline double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// The ADC step of non-zero successive differences d (absolute values): the smallest one,
/// when at least 90 % of them are whole multiples of it; else 0 (continuous data).
inline double adc_step(const std::vector<double>& d) {
  double q = 0;
  double scale = 0;
  for (double v : d) scale = std::max(scale, v);
  const double tiny = 1e-9 * scale;
  for (double v : d) {
    if (v > tiny && (q == 0 || v < q)) q = v;
  }
  if (!(q > 0)) return 0.0;
  std::size_t nonzero = 0, on_grid = 0;
  for (double v : d) {
    if (v <= tiny) continue;
    ++nonzero;
    const double m = v / q;
    if (std::fabs(m - std::round(m)) < 0.02) ++on_grid;
  }
  // Continuous data puts only ~4 % of m within 0.02 of a whole number.
  return nonzero >= 5 && static_cast<double>(on_grid) >= 0.9 * static_cast<double>(nonzero) ? q : 0.0;
}

/// The noise of y over its steady stretches [a, b) (row ranges), sample period dt [s].
inline NoiseEstimate estimate_noise(const std::vector<double>& y, const std::vector<std::pair<std::size_t, std::size_t>>& stretches,
                                    double dt) {
  NoiseEstimate e;
  std::vector<double> diff, dev;
  const std::size_t half = dt > 0 ? static_cast<std::size_t>(std::floor(0.5 / dt)) : 0;
  for (const auto& [a, b] : stretches) {
    for (std::size_t k = a + 1; k < b; ++k) diff.push_back(std::fabs(y[k] - y[k - 1]));
    // A stretch shorter than the window is smoothed over half its length: a 20 Hz ripple
    // on a 0.4 s setting logged at 4.8 kHz is still averaged over four periods.
    const std::size_t h = b - a >= 2 * half + 1 ? half : (b - a - 1) / 2;
    if (h < 2) continue;  // too few samples to smooth
    std::vector<double> cum(b - a + 1, 0.0);
    for (std::size_t k = a; k < b; ++k) cum[k - a + 1] = cum[k - a] + y[k];
    for (std::size_t k = a; k < b; ++k) {
      const std::size_t lo = k >= a + h ? k - h : a, hi = std::min(b, k + h + 1);
      dev.push_back(std::fabs(y[k] - (cum[hi - a] - cum[lo - a]) / static_cast<double>(hi - lo)));
    }
  }
  e.white = 1.4826 * median_of(diff) / std::sqrt(2.0);
  e.step = adc_step(diff);
  e.spread = 1.4826 * median_of(dev);
  return e;
}

}  // namespace hstmon::gap::detail
