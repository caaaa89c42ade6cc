#pragma once
/// @file residual_evaluator.hpp
/// Residual evaluation: decides per channel and per tick whether the observer residual
/// r = y − ŷ is explained by sensor noise and model (parameter) uncertainty.
///
/// Per channel i the residual is compared with the adaptive bound
///   b_i = m_i + k_drift·σ_i
/// where σ_i is the sensor noise (standard deviation) and m_i the model bound: the largest
/// steady-state output change that the parameter intervals can produce at the current
/// operating point, Σ_θ max|ŷ_i(θ ± Δθ) − ŷ_i(θ)| (see residual_bounds.hpp; an LFT-style
/// interval bound from the model's sensitivities). The excess over b_i accumulates in a
/// two-sided CUSUM (cusum.hpp) with the increment clipped at k_clip·σ_i and the statistic
/// capped at k_cap·σ_i; the channel alarms when a statistic reaches k_threshold·σ_i and
/// releases when both statistics have drained to zero.
///
/// Defaults (k_drift = 2, k_threshold = 5, k_clip = 2, k_cap = 10):
///  - no single sample can fire: at most 2σ is added per sample, so ≥ 3 consecutive
///    samples beyond b_i + 2σ are needed — a step of many σ is detected on its 3rd sample;
///  - on Gaussian noise with |bias| ≤ m_i, the average run length of one side is ≈ 7e9
///    samples (Siegmund's approximation with reference 2σ and threshold 5σ), i.e. no
///    alarm in 1e6 ticks on 4 channels with probability ≈ 0.999;
///  - after a fault disappears a statistic drains from the cap in ≤ 5 samples.
/// All state is in the object (≈ 12 scalars per channel); update() is O(N), never
/// allocates, never throws.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "hstmon/code_size.hpp"  // HSTMON_UNROLL, HSTMON_NOINLINE
#include "hstmon/cusum.hpp"
#include "hstmon/status.hpp"

namespace hstmon {

/// Residual evaluator over N channels (N ≤ 8; the thesis rig has 4: Pmi, Pmo, Ppp, ωm).
template <typename T, int N = 4>
class ResidualEvaluator {
 public:
  static_assert(N >= 1 && N <= 8, "channel masks are 8 bits wide");
  static constexpr std::size_t kN_ = static_cast<std::size_t>(N);  ///< array extent
  static constexpr int kChannels = N;

  /// Configuration; validated by configure(). Units per channel are the residual's
  /// (Pa for pressures, rad/s for speed).
  struct Config {
    /// Sensor noise σ_i [channel unit], > 0. Default: the thesis rig's assumed sensors
    /// (sensor_presets.hpp), 0.05 bar on pressures and 0.5 rpm on speed.
    T noise_sigma[kN_] = {};
    /// Model bound m_i [channel unit], ≥ 0 (0 = perfect model). See thesis_model_bound().
    T model_bound[kN_] = {};
    T k_drift = T(2);      ///< CUSUM reference beyond m_i [σ], ≥ 0
    T k_threshold = T(5);  ///< alarm threshold of a CUSUM statistic [σ], > k_clip
    T k_clip = T(2);       ///< largest increment of a statistic per sample [σ], > 0
    T k_cap = T(10);       ///< cap of a statistic [σ], ≥ k_threshold

    Config() noexcept {
      for (int i = 0; i < N; ++i) noise_sigma[i] = T(5e3);  // 0.05 bar
      if (N == 4) noise_sigma[N - 1] = T(0.5) * T(3.14159265358979323846) / T(30);  // 0.5 rpm
    }
  };

  /// The default configuration (valid by construction: no check needed), statistics clear.
  ResidualEvaluator() noexcept { derive(); }

  /// Takes a configuration and resets. O(N).
  /// @return kOk, or kInvalidConfig (σ not finite and > 0, m < 0, or factors out of range)
  ///         with the evaluator unchanged
  Status configure(const Config& c) noexcept {
    bool ok = finite_nonneg(c.k_drift) && finite_nonneg(c.k_clip) && c.k_clip > T(0) &&
              finite_nonneg(c.k_threshold) && c.k_threshold > c.k_clip && finite_nonneg(c.k_cap) &&
              c.k_cap >= c.k_threshold;
    for (int i = 0; i < N; ++i) ok = ok && finite_nonneg(c.noise_sigma[i]) && c.noise_sigma[i] > T(0);
    for (int i = 0; i < N; ++i) ok = ok && finite_nonneg(c.model_bound[i]);
    if (!ok) return Status::kInvalidConfig;
    cfg_ = c;
    derive();
    reset();
    return Status::kOk;
  }

  /// Replaces the model bounds m_i (e.g. after the operating point changed) without
  /// resetting the statistics. O(N).
  /// @param m  N bounds [channel unit], each finite and ≥ 0
  /// @return   kOk, or kInvalidConfig (bounds unchanged)
  Status set_model_bound(const T* m) noexcept {
    for (int i = 0; i < N; ++i) {
      if (!finite_nonneg(m[i])) return Status::kInvalidConfig;
    }
    for (int i = 0; i < N; ++i) cfg_.model_bound[i] = m[i];
    derive();
    return Status::kOk;
  }

  /// Clears the statistics and alarms.
  void reset() noexcept {
    for (int i = 0; i < N; ++i) {
      cusum_[i].reset();
      sign_[i] = 0;
      r_[i] = T(0);
    }
    alarm_ = 0;
    rising_ = 0;
    valid_ = 0;
    for (int i = 0; i < N; ++i) set_quiet(i, 0u);
  }

  /// Evaluates one tick of residuals.
  /// @param r      N residuals [channel unit] (e.g. Observer::residual().data())
  /// @param valid  bit i set: r[i] was computed this tick; other channels (and non-finite
  ///               r[i]) keep their statistics and alarm unchanged
  /// @return       alarm() after the update
  std::uint8_t update(const T* r, std::uint8_t valid) noexcept {
    return update(r, valid, [](int) noexcept { return T(0); });
  }

  /// update() with an extra allowance per channel: allow(i) returns a_i ≥ 0 [channel
  /// unit] and the bound is b_i + a_i (Monitor: the model's transient allowance). It is
  /// asked only for a channel whose residual exceeds b_i, so a costly allowance costs
  /// nothing in steady operation.
  template <typename Allow>
  std::uint8_t update(const T* r, std::uint8_t valid, const Allow& allow) noexcept {
    unsigned alarm = alarm_;
    unsigned used = 0;
    // Fast path (the nominal tick): a quiet channel (quiet_: not in alarm, both statistics
    // 0, b_i finite, threshold > 0) with |r_i| ≤ b_i keeps exactly its state — both
    // increments are ≤ 0, so both statistics stay 0 < threshold, and a channel not in
    // alarm has sign 0. A NaN fails |r_i| ≤ b_i and takes the full path.
    const unsigned quiet = quiet_;
    HSTMON_UNROLL
    for (int i = 0; i < N; ++i) {
      const unsigned bit = 1u << i;
      if ((valid & bit) == 0) continue;
      const T a = std::fabs(r[i]);
      if ((quiet & bit) != 0 && a <= drift_[i]) {
        used |= bit;
        r_[i] = r[i];
        continue;
      }
      const T b = drift_[i] + allow(i);
      if ((quiet & bit) != 0 && a <= b) {
        used |= bit;
        r_[i] = r[i];
      } else if (update_channel(i, r[i], b, alarm)) {
        used |= bit;
      }
    }
    rising_ = static_cast<std::uint8_t>(alarm & ~static_cast<unsigned>(alarm_));
    alarm_ = static_cast<std::uint8_t>(alarm);
    valid_ = static_cast<std::uint8_t>(used);
    return alarm_;
  }

  /// Bit i set: channel i is in alarm.
  std::uint8_t alarm() const noexcept { return alarm_; }
  /// Bit i set: channel i went into alarm in the last update.
  std::uint8_t rising() const noexcept { return rising_; }
  /// Bit i set: channel i is quiet — not in alarm and both CUSUM statistics at 0.
  std::uint8_t quiet() const noexcept { return quiet_; }
  /// Bit i set: channel i had a finite residual in the last update.
  std::uint8_t valid() const noexcept { return valid_; }
  /// Side that raised channel i's alarm: +1 (residual above), −1 (below), 0 (no alarm).
  std::int8_t alarm_sign(int i) const noexcept { return sign_[i]; }
  /// Last finite residual of channel i [channel unit].
  T residual(int i) const noexcept { return r_[i]; }
  /// Adaptive bound b_i = m_i + k_drift·σ_i [channel unit]: |r_i| beyond it is unexplained.
  T bound(int i) const noexcept { return drift_[i]; }
  /// CUSUM alarm threshold k_threshold·σ_i [channel unit].
  T threshold(int i) const noexcept { return thresh_[i]; }
  /// Noise σ_i [channel unit].
  T sigma(int i) const noexcept { return cfg_.noise_sigma[i]; }
  /// CUSUM statistics of channel i [channel unit].
  const TwoSidedCusum<T>& cusum(int i) const noexcept { return cusum_[i]; }
  const Config& config() const noexcept { return cfg_; }

 private:
  static bool finite_nonneg(T v) noexcept { return std::isfinite(v) && v >= T(0); }

  /// The full update of channel i against bound b (alarm: the alarm bits being built).
  /// @return false if r is not finite (channel unchanged)
  HSTMON_NOINLINE bool update_channel(int i, T r, T b, unsigned& alarm) noexcept {
    if (!std::isfinite(r)) return false;
    const unsigned bit = 1u << i;
    r_[i] = r;
    cusum_[i].update(r, b, clip_[i], cap_[i]);
    const T up = cusum_[i].upper();
    const T down = cusum_[i].lower();
    if (up >= thresh_[i] || down >= thresh_[i]) {
      if ((alarm & bit) == 0) sign_[i] = static_cast<std::int8_t>(up >= down ? 1 : -1);
      alarm |= bit;
    } else if (up <= T(0) && down <= T(0)) {
      alarm &= ~bit;
      sign_[i] = 0;
    }
    set_quiet(i, alarm);
    return true;
  }

  /// quiet_ bit i from channel i's state and the alarm bits.
  void set_quiet(int i, unsigned alarm) noexcept {
    const unsigned bit = 1u << i;
    const bool q = (alarm & bit) == 0 && cusum_[i].upper() == T(0) && cusum_[i].lower() == T(0) &&
                   std::isfinite(drift_[i]) && thresh_[i] > T(0);
    quiet_ = static_cast<std::uint8_t>(q ? (quiet_ | bit) : (quiet_ & ~bit));
  }

  void derive() noexcept {
    for (int i = 0; i < N; ++i) {
      const T s = cfg_.noise_sigma[i];
      drift_[i] = cfg_.model_bound[i] + cfg_.k_drift * s;
      clip_[i] = cfg_.k_clip * s;
      cap_[i] = cfg_.k_cap * s;
      thresh_[i] = cfg_.k_threshold * s;
      set_quiet(i, alarm_);
    }
  }

  Config cfg_{};
  TwoSidedCusum<T> cusum_[kN_]{};
  T drift_[kN_] = {};   ///< b_i [channel unit]
  T clip_[kN_] = {};    ///< [channel unit]
  T cap_[kN_] = {};     ///< [channel unit]
  T thresh_[kN_] = {};  ///< [channel unit]
  T r_[kN_] = {};       ///< last finite residual [channel unit]
  std::int8_t sign_[kN_] = {};
  std::uint8_t alarm_ = 0;
  std::uint8_t rising_ = 0;
  std::uint8_t valid_ = 0;
  /// Bit i: channel i is quiet — not in alarm, both statistics 0, b_i finite and
  /// threshold > 0 (update()'s fast path; kept by update_channel, derive and reset).
  std::uint8_t quiet_ = 0;
};

}  // namespace hstmon
