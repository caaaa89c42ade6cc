#pragma once
/// @file fault_matcher.hpp
/// Progressive single-fault isolation over a fault-signature table (fault_signature.hpp),
/// fed each tick by a ResidualEvaluator (channel alarms) and a SensorCheck (raw-value
/// plausibility).
///
/// An episode starts when a channel alarms or a sensor check fails (status kDetected,
/// event "detected"). As evidence arrives, every hypothesis whose signature an observed
/// symbol contradicts is dropped:
///  - at each channel's alarm onset, its slope symbol (symbol.hpp) against the row's slope;
///  - order_window after detection, the first-deviating channels (those that alarmed in
///    the window) must include one with the row's smallest predicted order (+ order_slack);
///  - after settle_time + average_time, the magnitude symbols (window mean less the
///    pre-fault baseline, dead band k_zero·σ) against the rows' magnitudes. An observed
///    kQualZero contradicts a predicted ± only when the row's direction, scaled to the
///    observed deviation, predicts more than k_expect·σ on that channel (a small fault
///    need not show on every channel).
/// kQualAny matches everything. A channel with a sensor flag is masked, and while any
/// channel is flagged only the sensor rows of flagged channels are candidates: a
/// sensor problem is never reported as a parameter fault. A saturated channel (over
/// range, SensorCheck::saturated()) reads at most its range end, so its deviation is a
/// lower bound: every hypothesis stays; the caller gives the evaluator its residual only
/// while positive (Monitor does), so its alarm and slope can only be '+'; its magnitude
/// is recorded only when '+'; it enters the ranking with the lower bound. The saturation
/// flag alone never starts an episode. Masks hold until the episode ends.
///
/// Ranking: score = cosine between the noise-normalised deviation vector v (window mean
/// less baseline, divided by σ; before the window ends, the latest residual) and the
/// row's `direction`, over the channels without a sensor flag; a sensor row scores
/// |v_ch|/|v| on its channel. With several candidates left after the window, the status is kIsolated if
/// the best leads the second by tie_margin in angle, else kAmbiguous. With none left it
/// is kUnexplained (no single fault in the table fits). Unless a sensor is flagged, none
/// of these is decided before both the order window and the averaging window are over
/// (status kDetected until then). When no channel is in alarm and no sensor is flagged
/// for clear_hold, the episode ends (event "cleared", kNominal); time the caller marks as
/// an operating-point change's transient does not count towards it.
///
/// Storage: Capacity hypotheses in the object (7 bytes each in float) plus a queue of
/// QueueDepth events of EventCandidates candidates each (defaults 4 and 8: ≈ 200 bytes per
/// event on a 64-bit host, 108 on a 32-bit one; ≈ 1.5 KB in all for float, 64 rows, on
/// 64-bit). Firmware picks smaller sizes through the template parameters (the C API:
/// 26 rows, 2 events of 1 candidate); they change storage only, never the logic — one
/// update() raises at most 2 events, so a depth of 2 drained every tick loses none;
/// update() is O(Capacity·channels) and sorts (insertion, O(Capacity²)) only when the
/// candidate set or scores change; it never allocates and never throws. The table is
/// borrowed (typically a constexpr array in flash) and must outlive the matcher.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hstmon/fault_signature.hpp"
#include "hstmon/residual_evaluator.hpp"
#include "hstmon/status.hpp"
#include "hstmon/symbol.hpp"

namespace hstmon {

/// State of the matcher.
enum class MatchStatus : std::uint8_t {
  kNominal = 0,      ///< no channel in alarm, no sensor flagged
  kDetected = 1,     ///< an episode is running; evidence still arriving, > 1 candidate
  kIsolated = 2,     ///< one candidate, or the best leads by tie_margin after the window
  kAmbiguous = 3,    ///< several candidates after the window, none clearly best
  kUnexplained = 4,  ///< every hypothesis contradicted (a fault outside the table, or several)
};

/// Kind of an event in the matcher's queue.
enum class MatchEventKind : std::uint8_t {
  kDetected = 0,     ///< an episode started
  kIsolated = 1,     ///< status became kIsolated
  kAmbiguous = 2,    ///< status became kAmbiguous
  kUnexplained = 3,  ///< status became kUnexplained
  kCleared = 4,      ///< the episode ended (back to kNominal)
};

/// Lower-case name of a status ("nominal", "detected", …), for logs.
constexpr const char* to_string(MatchStatus s) noexcept {
  switch (s) {
    case MatchStatus::kNominal: return "nominal";
    case MatchStatus::kDetected: return "detected";
    case MatchStatus::kIsolated: return "isolated";
    case MatchStatus::kAmbiguous: return "ambiguous";
    case MatchStatus::kUnexplained: return "unexplained";
  }
  return "?";
}

/// Lower-case name of an event kind ("detected", "isolated", …), for logs.
constexpr const char* to_string(MatchEventKind k) noexcept {
  switch (k) {
    case MatchEventKind::kDetected: return "detected";
    case MatchEventKind::kIsolated: return "isolated";
    case MatchEventKind::kAmbiguous: return "ambiguous";
    case MatchEventKind::kUnexplained: return "unexplained";
    case MatchEventKind::kCleared: return "cleared";
  }
  return "?";
}

namespace detail {

/// cos m and sin m of a tie margin [rad] (cos = −2 for m beyond π or NaN: never a lead).
template <typename T>
struct MarginCosSin {
  T c, s;
};

/// Taylor series of cos m and sin m for m in [0, π], every term kept until it is below
/// rounding, so isolation needs no acos on the tick path; constexpr, so the default
/// margin costs no code.
template <typename T>
constexpr MarginCosSin<T> margin_cos_sin(T m) noexcept {
  const bool never = !(m <= T(3.14159265358979323846));  // a lead beyond π is impossible
  const T x = never ? T(0) : m;
  T c = T(1), s = x, tc = T(1), ts = x;
  for (int k = 1; k <= 16; ++k) {  // x^(2k)/(2k)!, x^(2k+1)/(2k+1)!: π^34/34! < 1e-19
    tc = -tc * x * x / static_cast<T>((2 * k - 1) * (2 * k));
    ts = -ts * x * x / static_cast<T>((2 * k) * (2 * k + 1));
    c += tc;
    s += ts;
  }
  return {never ? T(-2) : c, s};  // −2: s0 < −cos m always
}

}  // namespace detail

/// A ranked hypothesis.
template <typename T>
struct MatchCandidate {
  std::int16_t index = -1;    ///< row in the table
  const char* name = nullptr; ///< the row's name (points into the table)
  T score = T(0);             ///< ranking score in [−1, 1] (cosine; see the file comment) [-]
};

/// One event: what happened, when, and the candidates best first (at most MaxCandidates).
template <typename T, int MaxCandidates = 8>
struct MatchEvent {
  static_assert(MaxCandidates >= 1 && MaxCandidates <= 255, "count is stored in 8 bits");
  static constexpr int kMaxCandidates = MaxCandidates;  ///< candidates carried by an event
  MatchEventKind kind = MatchEventKind::kDetected;
  T time = T(0);                  ///< time passed to the update that raised it [s]
  std::uint8_t count = 0;         ///< entries used in candidate[] (≤ kMaxCandidates)
  std::uint8_t consistent = 0;    ///< consistent hypotheses in total (may exceed count)
  MatchCandidate<T> candidate[static_cast<std::size_t>(MaxCandidates)]{};  ///< best first; empty for kCleared
};

/// @tparam Capacity         hypotheses (table rows) the object can hold, 1 … 127
/// @tparam QueueDepth       events queued until popped (oldest dropped when full), 1 … 255
/// @tparam EventCandidates  candidates an event carries (the rest: candidate()), 1 … 255
/// @tparam Channels         measured channels of the table and the evaluator, 1 … 8
template <typename T, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8, int Channels = kFdiChannels>
class FaultMatcher {
 public:
  static_assert(Capacity >= 1 && Capacity <= 127, "hypothesis indices are stored in 8 bits");
  static_assert(QueueDepth >= 1 && QueueDepth <= 255, "queue indices are stored in 8 bits");
  static constexpr int kChannels = Channels;
  static constexpr std::size_t kCap_ = static_cast<std::size_t>(Capacity);  ///< array extent
  static constexpr std::size_t kN_ = static_cast<std::size_t>(Channels);    ///< array extent
  using Evaluator = ResidualEvaluator<T, Channels>;
  using Signature = BasicFaultSignature<Channels>;  ///< a row of the table
  using Candidate = MatchCandidate<T>;
  using Event = MatchEvent<T, EventCandidates>;
  static constexpr int kQueueDepth = QueueDepth;  ///< events held until popped
  static constexpr T kDefaultTieMargin = T(0.01);  ///< Config::tie_margin's default [rad]

  /// Configuration; validated by configure(). Times in seconds, k_* in units of σ.
  struct Config {
    /// Channels that alarm within this time of detection count as deviating first [s], ≥ 0.
    /// 20 ms: twice the speed sensor's lag; sensor lags and the per-channel bounds
    /// (ωm's is 119 σ, Pmi's 5 σ at ±2 %) reorder detection within a few ms.
    T order_window = T(0.02);
    /// Integrations beyond a row's smallest predicted order still accepted as first [-].
    std::uint8_t order_slack = 0;
    /// Wait after detection before averaging [s], ≥ 0 (slowest thesis mode −153 ± 307i 1/s
    /// has decayed to 0.05 % after 50 ms).
    T settle_time = T(0.05);
    /// Averaging window for magnitudes and direction [s], > 0 (100 samples at 1 kHz:
    /// the mean's noise is σ/10).
    T average_time = T(0.1);
    T k_zero = T(3);      ///< dead band of the magnitude symbol on the baseline-relative mean [σ], ≥ 0
    T k_expect = T(6);    ///< predicted deviation above which an observed 0 contradicts ± [σ], ≥ 0
    /// Share of the evaluator's model bound added to the magnitude's dead band [-], ≥ 0;
    /// 0 = k_zero·σ alone. A fault that moves the machine's operating point (an input
    /// fault, a displacement) also moves the model error that the baseline removed, by up
    /// to the bound: 1 reads a channel that moved no further than that as unchanged, and
    /// lets a row predict that much more on a channel read as unchanged (k_expect).
    T k_zero_bound = T(0);
    T tie_margin = kDefaultTieMargin;  ///< angle lead of the best candidate needed to isolate [rad], ≥ 0
    T clear_hold = T(0.5);   ///< quiet time that ends an episode [s], ≥ 0
    /// Samples of the running mean that tracks each residual's pre-fault baseline while
    /// nominal (then an exponential average over this many samples) [-], ≥ 1.
    std::uint32_t baseline_samples = 1000;
  };

  FaultMatcher() noexcept = default;

  /// Takes a table and a configuration, and resets.
  /// @param table  count rows, borrowed (must outlive the matcher); null only if count = 0
  /// @param count  rows in the table, 0 … Capacity
  /// @return       kOk, or kInvalidConfig (matcher unchanged)
  Status configure(const Signature* table, int count, const Config& c) noexcept {
    const bool ok = table_ok(table, count) && nonneg(c.order_window) && windows_ok(c.settle_time, c.average_time) &&
                    nonneg(c.k_zero) && nonneg(c.k_expect) && nonneg(c.k_zero_bound) && nonneg(c.tie_margin) &&
                    nonneg(c.clear_hold) && c.baseline_samples >= 1;
    if (!ok) return Status::kInvalidConfig;
    cfg_ = c;
    const detail::MarginCosSin<T> m = detail::margin_cos_sin(c.tie_margin);
    cos_margin_ = m.c;
    sin_margin_ = m.s;
    return set_table(table, count);
  }

  /// Takes a table, keeps the configuration (on a default-constructed matcher: Config{}),
  /// and resets.
  /// @return kOk, or kInvalidConfig (matcher unchanged)
  Status set_table(const Signature* table, int count) noexcept {
    if (!table_ok(table, count)) return Status::kInvalidConfig;
    table_ = table;
    count_ = count;
    for (int k = 0; k < count; ++k) {
      const Signature& f = table[k];
      int ch = -1;
      for (int i = 0; i < kChannels; ++i) {
        if (f.channel[i].magnitude != kQualZero) ch = (ch == -1) ? i : -2;
      }
      sensor_ch_[k] = static_cast<std::int8_t>(f.sensor && ch >= 0 ? ch : -1);
    }
    reset();
    return Status::kOk;
  }

  /// New settle and averaging times, at once: an episode in progress has its window moved
  /// (call it between episodes to keep an episode's window as it was detected under). The
  /// monitor of a circuit follows the slowest time constant where the machine runs.
  /// @param settle_time   wait after a detection before averaging [s], ≥ 0
  /// @param average_time  averaging window [s], > 0
  /// @return kOk, or kInvalidConfig (windows unchanged)
  Status set_windows(T settle_time, T average_time) noexcept {
    if (!windows_ok(settle_time, average_time)) return Status::kInvalidConfig;
    cfg_.settle_time = settle_time;
    cfg_.average_time = average_time;
    return Status::kOk;
  }

  /// Restarts the baseline's running mean, the old baseline counting as one sample: the
  /// residual offset that parameter error leaves depends on the operating point, so after
  /// the inputs change the old one is stale. Only quiet samples are tracked
  /// (track_baseline), so a fault's first samples, before its CUSUM fires, are not absorbed.
  void restart_baseline() noexcept {
    for (int i = 0; i < kChannels; ++i) {
      if (base_n_[i] > 1) base_n_[i] = 1;
    }
  }

  /// Back to kNominal: episode, baseline and event queue cleared.
  void reset() noexcept {
    end_episode();
    for (int i = 0; i < kChannels; ++i) {
      base_[i] = T(0);
      base_n_[i] = 0;
    }
    ev_head_ = 0;
    ev_count_ = 0;
    ev_dropped_ = 0;
    has_latest_ = false;
  }

  /// Advances one tick.
  /// @param t            time of the evaluated sample [s], non-decreasing
  /// @param ev           the evaluator, already updated with this tick's residuals
  /// @param sensor_mask     bit i set: channel i failed a sensor check this tick (SensorCheck::mask())
  /// @param saturated_mask  bit i set: channel i is saturated this tick (SensorCheck::saturated())
  /// @param settled         false while the residuals still carry an operating-point change's
  ///                        transient: the baseline does not follow them then, and an episode
  ///                        does not end (its quiet time counts from when the transient has
  ///                        gone: the allowance for it may hide a fault that persists)
  /// @return                status() after the tick
  MatchStatus update(T t, const Evaluator& ev, std::uint8_t sensor_mask = 0, std::uint8_t saturated_mask = 0,
                     bool settled = true) noexcept {
    const unsigned all = (1u << kChannels) - 1u;
    const unsigned sensors = sensor_mask & all;
    const unsigned alarm = ev.alarm() & all;
    const bool active = (alarm | sensors) != 0;

    if (status_ == MatchStatus::kNominal) {
      if (!active) {
        if (settled) track_baseline(ev);
        return status_;
      }
      start_episode(t);
    }
    if (active || !settled) t_active_ = t;

    bool changed = false;
    // Sensor flags mask the channels and leave only their sensor rows; saturation is noted.
    const unsigned masks = (sensors | saturated_mask) & all;
    if ((masks & ~static_cast<unsigned>(masked_)) != 0 || (sensors & ~static_cast<unsigned>(faulty_)) != 0) {
      masked_ = static_cast<std::uint8_t>(masked_ | masks);
      faulty_ = static_cast<std::uint8_t>(faulty_ | sensors);
      if (window_done_) set_vector(v_);  // the window's deviation, less the channels flagged since
      changed = true;
    }
    // Alarm onsets: slope symbol and rank (channels rising on the same tick share a rank).
    unsigned rising = alarm & ~static_cast<unsigned>(faulty_) & ~static_cast<unsigned>(seen_);
    if (rising != 0) {
      ++rank_;
      for (int i = 0; i < kChannels; ++i) {
        if ((rising >> i) & 1u) {
          sym_[i].slope = ev.alarm_sign(i) > 0 ? std::int8_t{kQualPlus} : std::int8_t{kQualMinus};
          sym_[i].rank = rank_;
          if (t - t_det_ <= cfg_.order_window) first_ = static_cast<std::uint8_t>(first_ | (1u << i));
        }
      }
      seen_ = static_cast<std::uint8_t>(seen_ | rising);
      changed = true;
    }
    if (!order_done_ && t - t_det_ > cfg_.order_window) {
      order_done_ = true;
      changed = true;
    }
    // Window: mean residual per channel over [t_det + settle, t_det + settle + average),
    // held open until it has a sample: a slow logger (the thesis DAS samples every 4 s)
    // may have none in it, and an empty window would rank every row at 0.
    const T w0 = t_det_ + cfg_.settle_time;
    if (!window_done_ && t >= w0) {
      const bool open = t < w0 + cfg_.average_time;
      if (open || !window_sampled()) {
        for (int i = 0; i < kChannels; ++i) {
          if ((ev.valid() >> i) & 1u) {
            sum_[i] += ev.residual(i);
            ++n_[i];
          }
        }
      }
      if (!open && window_sampled()) {
        finish_window(ev);
        changed = true;
      }
    }
    if (!window_done_ && (changed || first_tick_)) live_vector(ev);
    if (changed || first_tick_) {
      eliminate();
      rank_candidates();
      decide(t);
    }
    first_tick_ = false;

    if (!active && t - t_active_ >= cfg_.clear_hold) {
      push_event(MatchEventKind::kCleared, t, false);
      end_episode();
    }
    return status_;
  }

  /// Current status.
  MatchStatus status() const noexcept { return status_; }
  /// Consistent hypotheses now.
  int candidate_count() const noexcept { return n_alive_; }
  /// Consistent hypothesis of rank r (0 = best), r < candidate_count().
  Candidate candidate(int r) const noexcept { return make_candidate(order_[r]); }
  /// Symbols observed on channel i in this episode.
  const ChannelSymbol& symbol(int i) const noexcept { return sym_[i]; }
  /// Bit i set: channel i deviated first (alarmed within order_window of detection).
  std::uint8_t first_channels() const noexcept { return first_; }
  /// Bit i set: channel i had a sensor flag or was saturated in this episode.
  std::uint8_t sensor_masked() const noexcept { return masked_; }
  /// Bit i set: channel i had a sensor flag in this episode (its sensor row is a candidate).
  std::uint8_t sensor_faults() const noexcept { return faulty_; }
  /// Time the episode was detected [s] (meaningful when status() ≠ kNominal).
  T detection_time() const noexcept { return t_det_; }
  /// True once the averaging window of this episode is complete.
  bool window_done() const noexcept { return window_done_; }
  /// Noise-normalised deviation of channel i (window mean, or latest residual before the
  /// window ends, less the baseline, over σ) [-].
  T deviation(int i) const noexcept { return v_[i]; }
  /// Pre-fault residual baseline of channel i [channel unit].
  T baseline(int i) const noexcept { return base_[i]; }

  /// Removes the oldest queued event into e. @return false if the queue is empty.
  bool pop_event(Event& e) noexcept {
    if (ev_count_ == 0) return false;
    e = events_[ev_head_];
    ev_head_ = static_cast<std::uint8_t>((ev_head_ + 1) % kQueue);
    --ev_count_;
    return true;
  }
  /// The most recent event (queued or already popped); null before the first.
  /// (Its queue slot: popping copies out and leaves the slot, and only a newer event,
  /// then the latest, overwrites it.)
  const Event* latest_event() const noexcept { return has_latest_ ? &events_[latest_] : nullptr; }
  /// Events lost because the queue (QueueDepth entries) was full [-].
  std::uint32_t events_dropped() const noexcept { return ev_dropped_; }
  const Config& config() const noexcept { return cfg_; }

 private:
  static constexpr int kQueue = QueueDepth;
  static bool nonneg(T v) noexcept { return std::isfinite(v) && v >= T(0); }
  // Config::settle_time ≥ 0 and average_time > 0, both finite (configure, set_windows).
  static bool windows_ok(T settle, T average) noexcept { return nonneg(settle) && nonneg(average) && average > T(0); }
  static bool table_ok(const Signature* table, int count) noexcept {
    return count >= 0 && count <= Capacity && (table != nullptr || count == 0);
  }
  static bool responds(const ChannelSignature& s) noexcept {
    return s.magnitude != kQualZero || s.slope != kQualZero;
  }

  void end_episode() noexcept {
    status_ = MatchStatus::kNominal;
    isolated_ = -1;
    for (int i = 0; i < kChannels; ++i) {
      sym_[i] = ChannelSymbol{};
      sum_[i] = T(0);
      n_[i] = 0;
      v_[i] = T(0);
      widen_[i] = T(0);
    }
    v_norm_ = T(0);
    n_alive_ = 0;
    masked_ = faulty_ = seen_ = first_ = 0;
    rank_ = 0;
    order_done_ = window_done_ = false;
    first_tick_ = false;
  }

  void start_episode(T t) noexcept {
    end_episode();
    status_ = MatchStatus::kDetected;
    t_det_ = t;
    t_active_ = t;
    first_tick_ = true;
    for (int k = 0; k < count_; ++k) alive_[k] = true;
    detected_pending_ = true;
  }

  // Only quiet channels (both CUSUM statistics at 0): a fault's first samples, before its
  // statistic reaches the threshold, must not pull the baseline towards it.
  void track_baseline(const Evaluator& ev) noexcept {
    const unsigned valid = ev.valid() & ev.quiet();
    const std::uint32_t n_max = cfg_.baseline_samples;
    for (int i = 0; i < kChannels; ++i) {
      if (((valid >> i) & 1u) == 0) continue;
      std::uint32_t n = base_n_[i];
      if (n < n_max) base_n_[i] = ++n;
      base_[i] += (ev.residual(i) - base_[i]) / static_cast<T>(n);
    }
  }

  void set_vector(const T* dev) noexcept {
    T s = T(0);
    for (int i = 0; i < kChannels; ++i) {
      v_[i] = ((faulty_ >> i) & 1u) ? T(0) : dev[i];
      s += v_[i] * v_[i];
    }
    if (!(s <= std::numeric_limits<T>::max())) s = clamp_vector();  // Inf or NaN
    v_norm_ = std::sqrt(s);
  }

  // Deviations are in noise units: beyond 1e15 they are absurd readings, not a shape to
  // rank. Clamping them keeps |v|² finite in float (a finite 4e37 reading once gave NaN
  // scores, Inf/Inf); NaN (Inf − Inf upstream) counts as no deviation. Returns |v|².
  HSTMON_NOINLINE T clamp_vector() noexcept {
    constexpr T kMax = T(1e15);
    T s = T(0);
    for (int i = 0; i < kChannels; ++i) {
      const T d = v_[i] == v_[i] ? v_[i] : T(0);
      v_[i] = d > kMax ? kMax : (d < -kMax ? -kMax : d);
      s += v_[i] * v_[i];
    }
    return s;
  }

  void live_vector(const Evaluator& ev) noexcept {
    T d[kN_];
    for (int i = 0; i < kChannels; ++i) d[i] = (ev.residual(i) - base_[i]) / ev.sigma(i);
    set_vector(d);
  }

  bool window_sampled() const noexcept {
    std::uint32_t n = 0;
    for (int i = 0; i < kChannels; ++i) n |= n_[i];
    return n != 0;
  }

  void finish_window(const Evaluator& ev) noexcept {
    window_done_ = true;
    T d[kN_];
    for (int i = 0; i < kChannels; ++i) {
      d[i] = n_[i] > 0 ? (sum_[i] / static_cast<T>(n_[i]) - base_[i]) / ev.sigma(i) : T(0);
    }
    set_vector(d);
    for (int i = 0; i < kChannels; ++i) {
      if (n_[i] == 0 || ((faulty_ >> i) & 1u) != 0) continue;
      // Saturated: the window mean is below the truth (clipped samples, and the evaluator
      // skips those below the model), so only '+' is known.
      widen_[i] = cfg_.k_zero_bound > T(0) ? cfg_.k_zero_bound * ev.bound(i) / ev.sigma(i) : T(0);
      const std::int8_t q = qual_sign(d[i], cfg_.k_zero + widen_[i]);
      if (((masked_ >> i) & 1u) == 0 || q == kQualPlus) sym_[i].magnitude = q;
    }
  }

  /// Norm of the row's direction over the channels without a sensor flag [-].
  T dir_norm(const Signature& f) const noexcept {
    T s = T(0);
    for (int i = 0; i < kChannels; ++i) {
      if (((faulty_ >> i) & 1u) == 0) s += static_cast<T>(f.direction[i]) * static_cast<T>(f.direction[i]);
    }
    return std::sqrt(s);
  }

  bool consistent(int k) const noexcept {
    const Signature& f = table_[k];
    if (faulty_ != 0) return sensor_ch_[k] >= 0 && ((faulty_ >> sensor_ch_[k]) & 1u) != 0;
    const T dn = dir_norm(f);
    for (int i = 0; i < kChannels; ++i) {
      const ChannelSignature& p = f.channel[i];
      if (!qual_consistent(p.slope, sym_[i].slope)) return false;
      if (!qual_consistent(p.magnitude, sym_[i].magnitude)) {
        // Observed 0 where ± is predicted: a contradiction only if the row, scaled to
        // the observed deviation, predicts a visible change on this channel.
        const bool soft = sym_[i].magnitude == kQualZero && dn > T(0) &&
                          std::fabs(static_cast<T>(f.direction[i])) / dn * v_norm_ <= cfg_.k_expect + widen_[i];
        if (!soft) return false;
      }
    }
    if (order_done_) {
      // Smallest predicted order among the channels that have alarmed in this episode: a
      // fast channel whose threshold the fault never reaches (ωm's bound is ~20× Pmi's)
      // says nothing about which channel should have moved first.
      int omin = 255;
      for (int i = 0; i < kChannels; ++i) {
        if (responds(f.channel[i]) && ((seen_ >> i) & 1u) != 0 && f.channel[i].order < omin) omin = f.channel[i].order;
      }
      if (omin != 255) {
        bool found = false;
        for (int i = 0; i < kChannels; ++i) {
          found = found || (((first_ >> i) & 1u) != 0 && responds(f.channel[i]) &&
                            f.channel[i].order <= omin + cfg_.order_slack);
        }
        if (!found && first_ != 0) return false;
      }
    }
    return true;
  }

  T score(int k) const noexcept {
    if (!(v_norm_ > T(0))) return T(0);
    const int s = sensor_ch_[k];
    if (s >= 0) return ((faulty_ >> s) & 1u) ? T(1) : std::fabs(v_[s]) / v_norm_;
    const Signature& f = table_[k];
    const T dn = dir_norm(f);
    if (!(dn > T(0))) return T(0);
    T dot = T(0);
    for (int i = 0; i < kChannels; ++i) {
      if (((faulty_ >> i) & 1u) == 0) dot += static_cast<T>(f.direction[i]) * v_[i];
    }
    return dot / (dn * v_norm_);
  }

  void eliminate() noexcept {
    int n = 0;
    for (int k = 0; k < count_; ++k) {
      if (alive_[k] || faulty_ != 0) alive_[k] = consistent(k);
      if (alive_[k]) order_[n++] = static_cast<std::int8_t>(k);
    }
    n_alive_ = n;
  }

  void rank_candidates() noexcept {
    for (int j = 0; j < n_alive_; ++j) score_[order_[j]] = score(order_[j]);
    for (int j = 1; j < n_alive_; ++j) {  // insertion sort, best first, stable
      const std::int8_t k = order_[j];
      int i = j - 1;
      while (i >= 0 && score_[order_[i]] < score_[k]) {
        order_[i + 1] = order_[i];
        --i;
      }
      order_[i + 1] = k;
    }
  }

  static T clamp_unit(T c) noexcept { return c > T(1) ? T(1) : (c < T(-1) ? T(-1) : c); }

  /// acos(s1) − acos(s0) ≥ tie_margin for the best two scores s0 ≥ s1 (clamped to
  /// [−1, 1]), without acos: with a0 = acos(s0) and m the margin, the lead holds iff
  /// a0 + m ≤ π (s0 ≥ −cos m) and s1 ≤ cos(a0 + m) = s0·cos m − sin a0·sin m, cos being
  /// decreasing on [0, π]. sin a0 = √((1 − s0)(1 + s0)) (no cancellation near s0 = ±1).
  bool leads_by_margin(T s0, T s1) const noexcept {
    s0 = clamp_unit(s0);
    s1 = clamp_unit(s1);
    if (s0 < -cos_margin_) return false;
    const T sin_a0 = std::sqrt((T(1) - s0) * (T(1) + s0));
    return s1 <= s0 * cos_margin_ - sin_a0 * sin_margin_;
  }

  void decide(T t) noexcept {
    if (detected_pending_) {
      detected_pending_ = false;
      push_event(MatchEventKind::kDetected, t, true);
    }
    MatchStatus s;
    if (faulty_ == 0 && !(order_done_ && window_done_)) {
      // Without a sensor flag, nothing is decided before the channels' order and the
      // window's directions are known: a transient's first symbols can mislead.
      s = MatchStatus::kDetected;
    } else if (n_alive_ == 0) {
      s = MatchStatus::kUnexplained;
    } else if (n_alive_ == 1) {
      s = MatchStatus::kIsolated;
    } else {
      s = leads_by_margin(score_[order_[0]], score_[order_[1]]) ? MatchStatus::kIsolated : MatchStatus::kAmbiguous;
    }
    // A change of the isolated candidate is news too (a loop break during an isolated
    // blockage leaves only sensor_p_pp): it raises a further "isolated" event.
    const std::int8_t best = s == MatchStatus::kIsolated ? order_[0] : std::int8_t{-1};
    if (s != status_ || best != isolated_) {
      status_ = s;
      isolated_ = best;
      if (s == MatchStatus::kIsolated) push_event(MatchEventKind::kIsolated, t, true);
      if (s == MatchStatus::kAmbiguous) push_event(MatchEventKind::kAmbiguous, t, true);
      if (s == MatchStatus::kUnexplained) push_event(MatchEventKind::kUnexplained, t, true);
    }
  }

  Candidate make_candidate(int k) const noexcept {
    Candidate c;
    c.index = static_cast<std::int16_t>(k);
    c.name = table_[k].name;
    c.score = score_[k];
    return c;
  }

  // Out of line: called from five places, at most twice per tick, only on a change.
  HSTMON_NOINLINE void push_event(MatchEventKind kind, T t, bool with_candidates) noexcept {
    Event e;
    e.kind = kind;
    e.time = t;
    if (with_candidates) {
      const int n = n_alive_ < Event::kMaxCandidates ? n_alive_ : Event::kMaxCandidates;
      for (int j = 0; j < n; ++j) e.candidate[j] = make_candidate(order_[j]);
      e.count = static_cast<std::uint8_t>(n);
      e.consistent = static_cast<std::uint8_t>(n_alive_);
    }
    if (ev_count_ == kQueue) {  // full: drop the oldest
      ev_head_ = static_cast<std::uint8_t>((ev_head_ + 1) % kQueue);
      --ev_count_;
      ++ev_dropped_;
    }
    latest_ = static_cast<std::uint8_t>((ev_head_ + ev_count_) % kQueue);
    events_[latest_] = e;
    has_latest_ = true;
    ++ev_count_;
  }

  const Signature* table_ = nullptr;
  int count_ = 0;
  Config cfg_{};
  static constexpr detail::MarginCosSin<T> kDefaultCosSin = detail::margin_cos_sin(kDefaultTieMargin);
  T cos_margin_ = kDefaultCosSin.c;  ///< cos of cfg_.tie_margin (−2: beyond π) [-]
  T sin_margin_ = kDefaultCosSin.s;  ///< sin of cfg_.tie_margin [-]
  MatchStatus status_ = MatchStatus::kNominal;
  bool alive_[kCap_] = {};
  std::uint8_t faulty_ = 0;  ///< channels with a sensor flag in this episode (⊆ masked_); after alive_, in its padding
  std::int8_t isolated_ = -1;  ///< row of the isolated candidate, −1 when not isolated; in the same padding
  T score_[kCap_] = {};
  std::int8_t order_[kCap_] = {};   ///< consistent rows, best first
  std::int8_t sensor_ch_[kCap_] = {};  ///< channel of a sensor row, −1 for others
  int n_alive_ = 0;
  ChannelSymbol sym_[kN_]{};
  T base_[kN_] = {};   ///< residual baseline [channel unit]
  std::uint32_t base_n_[kN_] = {};
  T sum_[kN_] = {};    ///< window sum [channel unit]
  std::uint32_t n_[kN_] = {};
  T v_[kN_] = {};      ///< normalised deviation [-]
  T widen_[kN_] = {};  ///< Config::k_zero_bound × model bound / σ: the window's widening of k_zero and k_expect [σ]
  T v_norm_ = T(0);
  T t_det_ = T(0);           ///< [s]
  T t_active_ = T(0);        ///< last time a channel was in alarm or flagged [s]
  std::uint8_t masked_ = 0, seen_ = 0, first_ = 0, rank_ = 0;
  bool order_done_ = false, window_done_ = false, first_tick_ = false, detected_pending_ = false;
  Event events_[static_cast<std::size_t>(QueueDepth)]{};
  std::uint8_t ev_head_ = 0, ev_count_ = 0, latest_ = 0;
  bool has_latest_ = false;
  std::uint32_t ev_dropped_ = 0;
};

}  // namespace hstmon
