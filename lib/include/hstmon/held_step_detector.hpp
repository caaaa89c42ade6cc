#pragma once
/// @file held_step_detector.hpp
/// A step in the readings while the inputs hold still. The monitor's threshold on a
/// residual is the model bound: the largest steady error that the parameters' uncertainty
/// can make at the operating point. On a rig whose curve parameters are uncertain (a
/// compensator's pressures) that bound is wide, and a fault of half of it raises nothing.
/// But the model's error at one operating point is a constant: it cannot change while the
/// inputs hold still. A step in a reading at held inputs is therefore evidence of a change
/// in the machine, measured against the noise, not against the bound.
///
/// The readings are averaged in blocks (Config::block). Over the latest span of
/// ref_blocks + gap_blocks + recent_blocks blocks, a straight line through the reference
/// blocks' means (the oldest ones) predicts the recent blocks' mean; the channel steps when
/// the recent mean misses the prediction by more than k_step standard errors AND by more
/// than k_bound × the model bound. The line lets a slow drift (the oil warming) pass; the
/// standard error comes from the scatter of the block means about the line (coloured noise,
/// ripple), at least the stated σ over a block's samples; the share of the bound keeps the
/// last of a settling mismatch between model and machine out. A reference whose line moves
/// by more than that share of the bound up to the recent blocks is not steady (a start from
/// rest still settling): it judges nothing. The gap skips the step's rise. Feed it residuals
/// (measured − model): they hold still at held inputs once the model has settled.
/// Nothing here allocates or throws; add() is O(N) per sample, O(N·span) per block.

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace hstmon {

/// @tparam T      float or double
/// @tparam N      channels
/// @tparam MaxSpan blocks kept (≥ ref_blocks + gap_blocks + recent_blocks)
template <typename T, int N, int MaxSpan = 16>
class HeldStepDetector {
 public:
  static_assert(N >= 1 && N <= 32, "channel masks are 32 bits wide");
  static constexpr int kChannels = N;

  /// Settings; times in s, k_* dimensionless.
  struct Config {
    T block = T(0.1);       ///< block length [s], > 0
    int ref_blocks = 10;    ///< reference blocks, the oldest of the span [-], ≥ 3
    int gap_blocks = 2;     ///< blocks skipped between reference and recent [-], ≥ 0
    int recent_blocks = 2;  ///< recent blocks compared with the reference's line [-], ≥ 1
    T k_step = T(8);        ///< miss beyond which a channel steps, in standard errors [-]
    T k_bound = T(0.1);     ///< … and in shares of the model bound [-]
  };

  /// @param sigma    stated noise σ per channel [channel unit] (≤ 0: from the data alone)
  /// @param measured bit i: channel i is read
  /// @return false on a bad configuration (then add() never fires)
  bool configure(const T* sigma, unsigned measured, const Config& c) noexcept {
    if (!(c.block > T(0)) || c.ref_blocks < 3 || c.gap_blocks < 0 || c.recent_blocks < 1 ||
        c.ref_blocks + c.gap_blocks + c.recent_blocks > MaxSpan || !(c.k_step > T(0)) || !(c.k_bound >= T(0))) {
      ok_ = false;
      return false;
    }
    for (int i = 0; i < N; ++i) sigma_[i] = sigma[i] > T(0) ? sigma[i] : T(0);
    measured_ = measured;
    cfg_ = c;
    ok_ = true;
    hold(T(0));
    return true;
  }

  /// The inputs changed (or an episode ended): forget the blocks; samples count from t_from
  /// on (after the model has settled at the new point) [s].
  void hold(T t_from) noexcept {
    t_from_ = t_from;
    started_ = false;
    count_ = 0;
    fired_ = false;
    step_ = 0;
    clear_block();
  }

  /// Feeds one sample. @param y readings [channel unit]; valid bit i: y[i] read;
  /// bound: the model bound per channel at the held point [channel unit]
  /// @return true once per hold, at the block that shows a step (step_mask() says where)
  bool add(T t, const T* y, unsigned valid, const T* bound) noexcept {
    if (!ok_ || fired_ || t < t_from_) return false;
    if (!started_) {
      started_ = true;
      t_block_ = t;
    }
    if (t - t_block_ >= cfg_.block) {
      push_block();
      t_block_ += cfg_.block * std::floor((t - t_block_) / cfg_.block);
      if (count_ >= span() && test(bound)) {
        fired_ = true;
        return true;
      }
    }
    for (int i = 0; i < N; ++i) {
      if ((((valid & measured_) >> i) & 1u) == 0 || !std::isfinite(y[i])) continue;
      sum_[i] += y[i];
      n_[i] += 1;
    }
    return false;
  }

  /// Channels that stepped (bit i), after add() returned true.
  std::uint32_t step_mask() const noexcept { return step_; }

  /// The settings configure() took.
  const Config& config() const noexcept { return cfg_; }

  /// How long after a step the detector has read when it fires: its recent blocks [s].
  T recent_span() const noexcept { return static_cast<T>(cfg_.recent_blocks) * cfg_.block; }

  /// The reference before the latest test: mean reading per channel [channel unit] and the
  /// variance of that mean [channel unit²]; bit i of the result: channel i has one. 0 when
  /// no full span has been seen in this hold.
  std::uint32_t reference(T* mean, T* var) const noexcept {
    if (!ok_ || count_ < span()) return 0;
    std::uint32_t have = 0;
    for (int i = 0; i < N; ++i) {
      Line l;
      if (!fit_reference(i, l)) continue;
      mean[i] = l.mean;
      var[i] = l.s2 / static_cast<T>(cfg_.ref_blocks);
      have |= std::uint32_t(1) << i;
    }
    return have;
  }

 private:
  static constexpr std::size_t kNz = static_cast<std::size_t>(N);
  static constexpr std::size_t kSz = static_cast<std::size_t>(MaxSpan);

  struct Line {
    T mean = T(0), slope = T(0), xbar = T(0), sxx = T(0), s2 = T(0);
  };

  int span() const noexcept { return cfg_.ref_blocks + cfg_.gap_blocks + cfg_.recent_blocks; }

  void clear_block() noexcept {
    for (int i = 0; i < N; ++i) {
      sum_[i] = T(0);
      n_[i] = 0;
    }
  }

  void push_block() noexcept {
    // Shift the ring down by one (MaxSpan is small): block 0 is the oldest.
    for (int b = 0; b + 1 < MaxSpan; ++b) {
      for (int i = 0; i < N; ++i) {
        mean_[b][i] = mean_[b + 1][i];
        nb_[b][i] = nb_[b + 1][i];
      }
    }
    for (int i = 0; i < N; ++i) {
      nb_[MaxSpan - 1][i] = n_[i];
      mean_[MaxSpan - 1][i] = n_[i] > 0 ? sum_[i] / static_cast<T>(n_[i]) : T(0);
    }
    if (count_ < MaxSpan) ++count_;
    clear_block();
  }

  // Block b of the latest span (0 = its oldest).
  int slot(int b) const noexcept { return MaxSpan - span() + b; }

  // Line through channel i's reference block means; its residual variance, at least the
  // stated σ² over a block's samples. False when a block has no sample.
  bool fit_reference(int i, Line& l) const noexcept {
    const int m = cfg_.ref_blocks;
    T sx = T(0), sy = T(0);
    std::uint32_t n_min = 0xffffffffu;
    for (int b = 0; b < m; ++b) {
      const std::uint32_t nb = nb_[slot(b)][i];
      if (nb == 0) return false;
      n_min = nb < n_min ? nb : n_min;
      sx += static_cast<T>(b);
      sy += mean_[slot(b)][i];
    }
    l.xbar = sx / static_cast<T>(m);
    l.mean = sy / static_cast<T>(m);
    T sxy = T(0);
    l.sxx = T(0);
    for (int b = 0; b < m; ++b) {
      const T dx = static_cast<T>(b) - l.xbar;
      l.sxx += dx * dx;
      sxy += dx * (mean_[slot(b)][i] - l.mean);
    }
    l.slope = sxy / l.sxx;
    T ss = T(0);
    for (int b = 0; b < m; ++b) {
      const T e = mean_[slot(b)][i] - (l.mean + l.slope * (static_cast<T>(b) - l.xbar));
      ss += e * e;
    }
    const T floor = sigma_[i] * sigma_[i] / static_cast<T>(n_min);
    l.s2 = std::fmax(ss / static_cast<T>(m - 2), floor);
    return l.s2 > T(0);
  }

  bool test(const T* bound) noexcept {
    step_ = 0;
    const int m = cfg_.ref_blocks, k = cfg_.recent_blocks;
    const int first_recent = m + cfg_.gap_blocks;
    for (int i = 0; i < N; ++i) {
      if (((measured_ >> i) & 1u) == 0) continue;
      Line l;
      if (!fit_reference(i, l)) continue;
      T recent = T(0), x = T(0);
      bool full = true;
      for (int b = first_recent; b < first_recent + k; ++b) {
        full = full && nb_[slot(b)][i] > 0;
        recent += mean_[slot(b)][i];
        x += static_cast<T>(b);
      }
      if (!full) continue;
      recent /= static_cast<T>(k);
      x /= static_cast<T>(k);
      const T predicted = l.mean + l.slope * (x - l.xbar);
      const T se = std::sqrt(l.s2 * (T(1) / static_cast<T>(m) + (x - l.xbar) * (x - l.xbar) / l.sxx +
                                     T(1) / static_cast<T>(k)));
      const T miss = std::fabs(recent - predicted);
      const T floor = cfg_.k_bound * (bound != nullptr && std::isfinite(bound[i]) ? std::fabs(bound[i]) : T(0));
      const bool steady = std::fabs(l.slope * (x - l.xbar)) <= floor;
      if (steady && miss > cfg_.k_step * se && miss > floor) step_ |= std::uint32_t(1) << i;
    }
    return step_ != 0;
  }

  Config cfg_{};
  bool ok_ = false;
  T sigma_[kNz] = {};
  unsigned measured_ = 0;
  T t_from_ = T(0), t_block_ = T(0);
  bool started_ = false, fired_ = false;
  int count_ = 0;
  std::uint32_t step_ = 0;
  T sum_[kNz] = {};
  std::uint32_t n_[kNz] = {};
  T mean_[kSz][kNz] = {};
  std::uint32_t nb_[kSz][kNz] = {};
};

}  // namespace hstmon
