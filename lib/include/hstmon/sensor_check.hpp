#pragma once
/// @file sensor_check.hpp
/// Plausibility checks on the raw measurements, independent of the model: a non-finite
/// value, a value outside the channel's physical range, and a value frozen (exactly equal
/// to the previous one) for a number of consecutive samples. A channel that fails one is
/// a sensor problem, never evidence for a parameter fault (FaultMatcher masks it).
/// State: a counter and the last value per channel; update() is O(N), never allocates,
/// never throws.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hstmon/status.hpp"

/// Out of line (GCC, Clang): the rare per-channel path, so the nominal loop stays small
/// enough to unroll (HSTMON_UNROLL, GCC: the per-channel loop overhead is ~1/4 of the
/// nominal tick outside the observer on the Cortex-M4F).
#ifndef HSTMON_NOINLINE
#if defined(__GNUC__)
#define HSTMON_NOINLINE __attribute__((noinline))
#else
#define HSTMON_NOINLINE
#endif
#endif
#ifndef HSTMON_UNROLL
#if defined(__GNUC__) && !defined(__clang__)
#define HSTMON_UNROLL _Pragma("GCC unroll 8")
#else
#define HSTMON_UNROLL
#endif
#endif

namespace hstmon {

/// Sensor flags of one channel, OR-ed into a bit set. Zero means plausible.
enum SensorFlag : std::uint8_t {
  kSensorNonFinite = 1u << 0,   ///< the value is NaN or ±Inf
  kSensorOutOfRange = 1u << 1,  ///< the value is strictly outside [range_lo, range_hi]
  kSensorStuck = 1u << 2,       ///< the value has not changed for stuck_samples samples
};

/// Raw-measurement checks over N channels (N ≤ 8).
template <typename T, int N = 4>
class SensorCheck {
 public:
  static_assert(N >= 1 && N <= 8, "channel masks are 8 bits wide");
  static constexpr std::size_t kN_ = static_cast<std::size_t>(N);  ///< array extent

  /// Configuration; validated by configure(). Units are the channel's (Pa, rad/s).
  struct Config {
    /// Lower end of the physically possible range [channel unit]; −∞ disables.
    T range_lo[kN_] = {};
    /// Upper end [channel unit], > range_lo; +∞ disables. A transmitter that saturates
    /// at its range end reads exactly the end, which is not out of range.
    T range_hi[kN_] = {};
    /// Consecutive bit-identical samples that make a channel stuck [-], ≥ 2; 0 disables.
    /// Default 100 (0.1 s at 1 kHz): with σ = 0.05 bar noise and a 16-bit ADC two equal
    /// successive codes have probability ≈ 0.02, with a 12-bit ADC ≈ 0.5 (0.5^99 ≈ 2e-30).
    std::uint32_t stuck_samples = 100;

    Config() noexcept {
      for (int i = 0; i < N; ++i) {
        range_lo[i] = -std::numeric_limits<T>::infinity();
        range_hi[i] = std::numeric_limits<T>::infinity();
      }
    }
  };

  /// The default configuration (valid), flags clear: the member initializers are reset()'s state.
  SensorCheck() noexcept = default;

  /// Takes a configuration and resets.
  /// @return kOk, or kInvalidConfig (a range with NaN or lo ≥ hi, or stuck_samples = 1),
  ///         checker unchanged
  Status configure(const Config& c) noexcept {
    if (c.stuck_samples == 1) return Status::kInvalidConfig;
    for (int i = 0; i < N; ++i) {
      if (!(c.range_lo[i] < c.range_hi[i])) return Status::kInvalidConfig;
    }
    cfg_ = c;
    ranged_ = 0;
    for (int i = 0; i < N; ++i) {
      const T inf = std::numeric_limits<T>::infinity();
      if (c.range_lo[i] != -inf || c.range_hi[i] != inf) ranged_ = static_cast<std::uint8_t>(ranged_ | (1u << i));
    }
    reset();
    return Status::kOk;
  }

  /// Forgets the last values and clears the flags.
  void reset() noexcept {
    for (int i = 0; i < N; ++i) {
      flags_[i] = 0;
      same_[i] = 0;
      last_[i] = T(0);
    }
    mask_ = 0;
    latched_ = 0;
    have_last_ = 0;
  }

  /// Checks one sample.
  /// @param y      N raw measurements [channel unit]
  /// @param valid  bit i set: channel i was sampled this tick (others keep their flags)
  /// @return       mask(): bit i set if channel i has any flag
  std::uint8_t update(const T* y, std::uint8_t valid) noexcept {
    unsigned mask = 0;
    // Fast path (the nominal sample): a finite value that differs from the channel's
    // previous one, on a channel without a finite range end (ranged_): no flag, no repeat.
    const unsigned fast = static_cast<unsigned>(have_last_) & ~static_cast<unsigned>(ranged_);
    HSTMON_UNROLL
    for (int i = 0; i < N; ++i) {
      const unsigned bit = 1u << i;
      if ((valid & bit) == 0) {
        mask |= flags_[i] != 0 ? bit : 0u;
        continue;
      }
      const T v = y[i];
      if ((fast & bit) != 0 && std::fabs(v) <= std::numeric_limits<T>::max() && v != last_[i]) {
        same_[i] = 0;
        last_[i] = v;
        flags_[i] = 0;
      } else if (check_channel(i, v) != 0) {
        mask |= bit;
      }
    }
    mask_ = static_cast<std::uint8_t>(mask);
    latched_ = static_cast<std::uint8_t>(latched_ | mask_);
    return mask_;
  }

  /// SensorFlag bits of channel i from its last sample.
  std::uint8_t flags(int i) const noexcept { return flags_[i]; }
  /// Bit i set: channel i has a flag now.
  std::uint8_t mask() const noexcept { return mask_; }
  /// Bit i set: channel i had a flag at some sample since reset.
  std::uint8_t latched() const noexcept { return latched_; }
  const Config& config() const noexcept { return cfg_; }

 private:
  /// The full check of sampled channel i with value v. @return its flags
  HSTMON_NOINLINE std::uint8_t check_channel(int i, T v) noexcept {
    const unsigned bit = 1u << i;
    std::uint8_t f = 0;
    if (!std::isfinite(v)) {
      f |= kSensorNonFinite;
      same_[i] = 0;
      have_last_ = static_cast<std::uint8_t>(have_last_ & ~bit);
    } else {
      if (v < cfg_.range_lo[i] || v > cfg_.range_hi[i]) f |= kSensorOutOfRange;
      if ((have_last_ & bit) != 0 && v == last_[i]) {
        if (same_[i] < 0xFFFFFFFFu) ++same_[i];
      } else {
        same_[i] = 0;
      }
      last_[i] = v;
      have_last_ = static_cast<std::uint8_t>(have_last_ | bit);
      // same_ counts repeats, so stuck_samples equal samples are stuck_samples − 1 repeats.
      if (cfg_.stuck_samples != 0 && same_[i] + 1u >= cfg_.stuck_samples) f |= kSensorStuck;
    }
    flags_[i] = f;
    return f;
  }

  Config cfg_{};
  T last_[kN_] = {};
  std::uint32_t same_[kN_] = {};
  std::uint8_t flags_[kN_] = {};
  std::uint8_t mask_ = 0;
  std::uint8_t latched_ = 0;
  std::uint8_t have_last_ = 0;
  std::uint8_t ranged_ = 0;  ///< bit i: channel i's range has a finite end (the default has none; update()'s fast path)
};

}  // namespace hstmon
