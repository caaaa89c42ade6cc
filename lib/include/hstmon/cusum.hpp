#pragma once
/// @file cusum.hpp
/// Two-sided CUSUM of one residual channel, in the channel's own unit:
///   g⁺ ← clamp(g⁺ + min(x − ν, c), 0, g_max),   g⁻ ← clamp(g⁻ + min(−x − ν, c), 0, g_max),
/// with drift ν (the part of |x| that is explained by noise and model uncertainty), a
/// clip c on the increment per sample (so one outlying sample adds at most c and a
/// threshold h > c needs ⌈h/c⌉ consecutive outlying samples) and a cap g_max (so the
/// statistic drains within g_max/ν samples once the residual is back inside the drift).
/// Two scalars of state; update() is O(1), never allocates, never throws.

namespace hstmon {

template <typename T>
class TwoSidedCusum {
 public:
  /// Both statistics to zero.
  void reset() noexcept {
    up_ = T(0);
    down_ = T(0);
  }

  /// Adds one sample.
  /// @param x      residual sample [channel unit]; must be finite (the caller skips others)
  /// @param drift  ν ≥ 0 [channel unit]
  /// @param clip   c > 0, largest increment per sample [channel unit]
  /// @param cap    g_max > 0, upper bound of each statistic [channel unit]
  void update(T x, T drift, T clip, T cap) noexcept {
    up_ = clamp(up_ + min(x - drift, clip), cap);
    down_ = clamp(down_ + min(-x - drift, clip), cap);
  }

  /// Upper statistic g⁺ (evidence for a positive shift) [channel unit], in [0, cap].
  T upper() const noexcept { return up_; }
  /// Lower statistic g⁻ (evidence for a negative shift) [channel unit], in [0, cap].
  T lower() const noexcept { return down_; }

 private:
  static T min(T a, T b) noexcept { return a < b ? a : b; }
  static T clamp(T v, T hi) noexcept { return v < T(0) ? T(0) : (v > hi ? hi : v); }

  T up_ = T(0);
  T down_ = T(0);
};

}  // namespace hstmon
