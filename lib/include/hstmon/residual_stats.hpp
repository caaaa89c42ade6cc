#pragma once
/// @file residual_stats.hpp
/// Running statistics of one channel's residuals over a replay: what `hstmon replay`
/// prints per channel and what the firmware replays print the same way. Fixed size, no
/// heap; O(1) per sample.

#include <cmath>
#include <cstddef>

namespace hstmon {

/// Residual statistics of one channel, in the channel's unit (SI on the replays).
/// @tparam T  accumulator type; the replays use double on every target so that their
///            printed figures agree
template <typename T>
struct ResidualStats {
  std::size_t n = 0;       ///< residuals counted
  T sum = 0;               ///< Σ r
  T sumsq = 0;             ///< Σ r²
  T max_abs = 0;           ///< max |r|
  T max_signed = 0;        ///< r at the max |r| (sign kept)
  T t_max = 0;             ///< log time of the max |r| [s]
  std::size_t row_max = 0; ///< 0-based data row of the max |r|
  std::size_t n_diff = 0;  ///< successive residual pairs counted
  T sumsq_diff = 0;        ///< Σ (r_k − r_{k−1})² over successive rows
  T last = 0;              ///< previous residual (for the differences)

  /// Counts residual r of data row `row` at log time t [s].
  void add(T r, T t, std::size_t row = 0) noexcept {
    if (n > 0) {
      sumsq_diff += (r - last) * (r - last);
      ++n_diff;
    }
    last = r;
    ++n;
    sum += r;
    sumsq += r * r;
    if (std::fabs(r) > max_abs) {
      max_abs = std::fabs(r);
      max_signed = r;
      t_max = t;
      row_max = row;
    }
  }
  /// Σ r / n (0 when n = 0).
  T mean() const noexcept { return n ? sum / static_cast<T>(n) : T(0); }
  /// √(Σ r² / n) (0 when n = 0).
  T rms() const noexcept { return n ? std::sqrt(sumsq / static_cast<T>(n)) : T(0); }
  /// Noise level estimated from successive differences, √(Σ Δr² / 2(n−1)): white sensor
  /// noise shows up in full, slow model errors hardly at all, so RMS ≫ noise means the
  /// model and the machine disagree beyond what the sensors scatter. 0 for n < 2.
  T noise() const noexcept { return n_diff ? std::sqrt(sumsq_diff / (T(2) * static_cast<T>(n_diff))) : T(0); }
};

}  // namespace hstmon
