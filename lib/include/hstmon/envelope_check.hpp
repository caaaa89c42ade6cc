#pragma once
/// @file envelope_check.hpp
/// Does the model describe this machine at all? A fault is a change from a machine the
/// model describes. A machine that sits far outside what the model reaches at the first
/// steady stretch of its log is another machine (or this one badly parameterised), and
/// naming a fault on it would be a guess.
///
/// The check: the first stretch of held inputs that lasts a settle (settle_taus slowest
/// time constants at its inputs, as the fault estimator waits) plus `window` seconds in
/// which the machine is steady (the mean residuals of the window's two halves agree within
/// 5 % of the tolerance and their noise; a machine still running up is tried again
/// later). Over that window, per channel, the mean residual is judged against twice the
/// matcher's own tolerance, 2·(model bound + 2σ). Beyond it on any channel: outside.
/// A detection once the machine has been seen to run within the matcher's tolerance (the
/// monitor quiet for `window` seconds after its start-up hold) is a fault: a window not
/// begun by then is given up, as it would judge the fault, not the machine. A detection
/// before that leaves the machine never seen to match the model: the check goes on to the
/// first steady stretch, and if the log ends before one, the verdict is unverified (the
/// data cannot tell a fault from a model that does not fit). A log without a steady
/// stretch and without such a detection is not checked.
///
/// Fixed-size state (a copy of the model and a few sums per channel), no heap: the same
/// check serves every model's replay on the host, and fits on a target.

#include <cmath>
#include <cstdint>

#include "hstmon/fault_estimator.hpp"
#include "hstmon/input_change.hpp"

namespace hstmon {

/// Where the check stands.
enum class EnvelopeVerdict : std::uint8_t {
  kPending = 0,  ///< no steady stretch judged yet
  kWithin = 1,   ///< judged: every channel within its tolerance
  kOutside = 2,  ///< judged: some channel beyond it (the model does not describe the machine)
  kGivenUp = 3,  ///< a fault was detected after the machine ran quiet, before a steady stretch: nothing judged
  kUnverified = 4,  ///< detected before the machine was ever seen to match the model, and no steady stretch followed
};

/// The envelope check of one log through the monitor of Model (model_concept.hpp).
template <class Model>
class EnvelopeCheck {
 public:
  using T = typename Model::Scalar;
  using Inputs = typename Model::Inputs;
  static constexpr int kChannels = Model::kOutputs;

  /// The stretch judged: the fault estimator's first window (fault_estimator.hpp).
  struct Config {
    T window = T(0.5);           ///< steady seconds judged [s]
    T settle_taus = T(3);        ///< wait after an input change, in slowest time constants [-]
    T settle_min = T(0.1);       ///< shortest wait [s]
    T settle_max = T(3);         ///< longest wait (a near-undamped mode at rest) [s]
    T input_tolerance = T(0.01); ///< relative input change that starts a new stretch [-]
  };

  /// @param model  the monitor's nominal model (copied: the check solves its steady state
  ///               for the settle time at each new stretch)
  /// @param sigma  sensor noise σ per channel [channel unit]
  void configure(const Model& model, const T* sigma, const Config& cfg = Config{}) noexcept {
    model_ = model;
    cfg_ = cfg;
    for (int ch = 0; ch < kChannels; ++ch) sigma_[ch] = sigma[ch];
    verdict_ = EnvelopeVerdict::kPending;
    holding_ = false;
    early_ = false;
    t_detected_ = T(-1);
    t_quiet_from_ = T(0);
    t_from_ = t_last_ = T(0);
    clear_sums();
  }

  /// From t [s] the monitor can detect (the log's first row plus its start-up hold): a
  /// detection within `window` of it comes before the machine was seen to match the model.
  void start(T t) noexcept { t_quiet_from_ = t; }

  /// One row.
  /// @param t      sample time [s]
  /// @param u      inputs at t
  /// @param r      residual per channel, measured − model [channel unit]
  /// @param valid  bit ch set where r[ch] is one
  /// @param bound  the model bound per channel at u [channel unit]; may be null (0)
  void add(T t, const Inputs& u, const T* r, unsigned valid, const T* bound) noexcept {
    if (verdict_ != EnvelopeVerdict::kPending) return;
    if (!holding_ || !inputs_close(u_hold_, u, cfg_.input_tolerance)) begin_hold(t, u);
    if (verdict_ != EnvelopeVerdict::kPending || t < t_from_) return;
    for (int ch = 0; ch < kChannels; ++ch) {
      if (((valid >> ch) & 1u) == 0 || !std::isfinite(r[ch])) continue;
      sum_[ch] += r[ch];
      n_[ch] += 1;
      if (t - t_from_ < T(0.5) * cfg_.window) {
        half_sum_[ch] += r[ch];
        half_n_[ch] += 1;
      }
      bound_[ch] = bound != nullptr ? std::fabs(bound[ch]) : T(0);
    }
    t_last_ = t;
    if (t - t_from_ < cfg_.window) return;
    // The machine may still be settling where the model has (a start from rest runs up
    // at the machine's own pace): an unsteady window is dropped and the next one tried.
    if (!steady()) {
      if (t_detected_ >= T(0) && !early_) {
        verdict_ = EnvelopeVerdict::kGivenUp;
        return;
      }
      t_from_ = t;
      clear_sums();
      return;
    }
    judge();
  }

  /// The monitor detected a fault at t [s]. After the machine ran quiet (see start()), a
  /// stretch that had not begun by then would judge the fault, not the machine, so the
  /// check is given up; before that, the machine was never seen to match the model, and the
  /// check goes on (finish() then says unverified if nothing was judged).
  void detected(T t) noexcept {
    if (verdict_ != EnvelopeVerdict::kPending || t_detected_ >= T(0)) return;
    t_detected_ = t;
    early_ = t < t_quiet_from_ + cfg_.window;
    if (!early_ && (!holding_ || t < t_from_)) verdict_ = EnvelopeVerdict::kGivenUp;
  }

  /// At the end of the log: judges a stretch that is steady, however far its window got;
  /// else, after a detection before the machine was seen to match the model, unverified.
  void finish() noexcept {
    if (verdict_ == EnvelopeVerdict::kPending && holding_ && t_last_ - t_from_ >= cfg_.window && steady()) judge();
    if (verdict_ == EnvelopeVerdict::kPending && early_) verdict_ = EnvelopeVerdict::kUnverified;
  }

  EnvelopeVerdict verdict() const noexcept { return verdict_; }
  const Config& config() const noexcept { return cfg_; }
  /// The first detection [s]; < 0 before one.
  T detected_at() const noexcept { return t_detected_; }
  /// Whether that detection came before the machine was seen to match the model.
  bool early_detection() const noexcept { return early_; }
  /// The window judged (or being filled): its first and last sample times [s].
  T t0() const noexcept { return t_from_; }
  T t1() const noexcept { return t_last_; }
  /// Whether channel ch had samples in the window.
  bool judged(int ch) const noexcept { return n_[ch] > 0; }
  /// Channel ch's mean residual over the window, measured − model [channel unit].
  T mean(int ch) const noexcept { return n_[ch] > 0 ? sum_[ch] / static_cast<T>(n_[ch]) : T(0); }
  /// Channel ch's tolerance, 2·(model bound + 2σ) [channel unit].
  T tolerance(int ch) const noexcept { return T(2) * (bound_[ch] + T(2) * sigma_[ch]); }
  /// Whether channel ch lies beyond its tolerance (a judged window only).
  bool outside(int ch) const noexcept {
    const T tol = tolerance(ch);
    return n_[ch] > 0 && tol > T(0) && std::fabs(mean(ch)) > tol;
  }

 private:
  void clear_sums() noexcept {
    for (int ch = 0; ch < kChannels; ++ch) {
      sum_[ch] = half_sum_[ch] = T(0);
      n_[ch] = half_n_[ch] = 0;
    }
  }

  void begin_hold(T t, const Inputs& u) noexcept {
    // A stretch that starts after a detection would judge the fault, not the machine
    // (unless the machine was never seen to match the model before it).
    if (t_detected_ >= T(0) && !early_) {
      verdict_ = EnvelopeVerdict::kGivenUp;
      return;
    }
    holding_ = true;
    u_hold_ = u;
    t_from_ = t + settle_time(model_, u, cfg_.settle_taus, cfg_.settle_min, cfg_.settle_max);
    clear_sums();
  }

  // The halves of the window agree within 5 % of the tolerance and their noise (4σ of
  // the difference of two means).
  bool steady() const noexcept {
    for (int ch = 0; ch < kChannels; ++ch) {
      const std::uint32_t n2 = n_[ch] - half_n_[ch];
      if (half_n_[ch] == 0 || n2 == 0) continue;
      const T first = half_sum_[ch] / static_cast<T>(half_n_[ch]);
      const T second = (sum_[ch] - half_sum_[ch]) / static_cast<T>(n2);
      const T noise =
          T(4) * sigma_[ch] * std::sqrt(T(1) / static_cast<T>(half_n_[ch]) + T(1) / static_cast<T>(n2));
      if (std::fabs(second - first) > T(0.05) * tolerance(ch) + noise) return false;
    }
    return true;
  }

  void judge() noexcept {
    verdict_ = EnvelopeVerdict::kWithin;
    for (int ch = 0; ch < kChannels; ++ch) {
      if (outside(ch)) verdict_ = EnvelopeVerdict::kOutside;
    }
  }

  Model model_{};
  Config cfg_{};
  EnvelopeVerdict verdict_ = EnvelopeVerdict::kPending;
  Inputs u_hold_{};
  bool holding_ = false;
  bool early_ = false;    ///< the first detection came before the machine was seen to match the model
  T t_quiet_from_ = T(0); ///< the monitor can detect from here [s]
  T t_from_ = T(0);      ///< the window starts here (after the settle) [s]
  T t_last_ = T(0);      ///< its last sample so far [s]
  T t_detected_ = T(-1); ///< the first detection [s]; < 0 before it
  static constexpr unsigned kSize = static_cast<unsigned>(kChannels);
  T sigma_[kSize] = {};
  T bound_[kSize] = {};     ///< the model bound at the window's last sample
  T sum_[kSize] = {};       ///< the window's residual sum
  T half_sum_[kSize] = {};  ///< its first half's
  std::uint32_t n_[kSize] = {};
  std::uint32_t half_n_[kSize] = {};
};

}  // namespace hstmon
