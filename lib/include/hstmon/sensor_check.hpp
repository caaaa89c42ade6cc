#pragma once
/// @file sensor_check.hpp
/// Plausibility checks on the raw measurements: a non-finite value, a value outside what
/// the channel's transmitter can report (a reading at the live zero only where the model,
/// if given, says the channel cannot be there), and a value frozen (bit-identical to the
/// previous one) for a time — where the channel's ADC step is below its noise, so that a
/// working sensor cannot repeat itself that long; with a coarser step only if the model
/// moved by more than two steps meanwhile. A channel that fails one is a sensor
/// problem, never evidence for a parameter fault (FaultMatcher masks it and keeps only
/// its sensor row). A channel reading at or just above the top of its range is
/// saturated: over range, its true value is at least range_hi — the machine may well be
/// there — so it is not a sensor problem; its reading is only a lower bound.
///
/// Ranges follow a live-zero (4–20 mA) transmitter: range_lo is the 4 mA value, and a
/// broken loop reads at or below it (0 mA; or exactly range_lo where the input card
/// clamps), so a reading ≤ range_lo is out of range. Above range_hi a transmitter
/// saturates up to 20.5 mA (NAMUR NE 43), range_hi + span/32; a reading beyond that is
/// out of range (NE 43's ≥ 21 mA failure signal, or a wrong value).
///
/// State: per channel the last value, the time its run of equal samples began (or the
/// deadline of that run), and its flags; update() is O(N), never allocates, never throws.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "hstmon/code_size.hpp"  // HSTMON_UNROLL, HSTMON_NOINLINE
#include "hstmon/status.hpp"

/// Out of line and optimised for size (GCC, Clang): the checks that run only for a channel
/// off the fast path — flagged, repeating or not sampled (flash on the Cortex-M4F).
#if defined(__GNUC__)
#define HSTMON_SENSOR_SLOW_PATH __attribute__((noinline, cold))
#else
#define HSTMON_SENSOR_SLOW_PATH
#endif

namespace hstmon {

/// Sensor flags of one channel, OR-ed into a bit set. Zero means plausible.
enum SensorFlag : std::uint8_t {
  kSensorNonFinite = 1u << 0,   ///< the value is NaN or ±Inf
  /// At or below range_lo (a 4–20 mA loop break; with a model, only where it says the channel
  /// cannot be there), or above range_hi + (range_hi − range_lo)/32.
  kSensorOutOfRange = 1u << 1,
  /// Bit-identical for stuck_time and stuck_min_samples samples, on a channel whose ADC
  /// step is below its noise or while the model moved (Config::noise).
  kSensorStuck = 1u << 2,
  /// In [range_hi, range_hi + (range_hi − range_lo)/32]: over range, not a fault (masked only).
  kSensorSaturated = 1u << 3,
  /// At or just below range_lo where the model says the channel may be there (update's
  /// model): a machine at rest, not a loop break; never stuck (a clamped value repeats).
  kSensorUnderRange = 1u << 4,
};

/// The flags that make a channel a sensor problem (all but kSensorSaturated).
constexpr std::uint8_t kSensorFaultFlags = kSensorNonFinite | kSensorOutOfRange | kSensorStuck;

/// Raw-measurement checks over N channels (N ≤ 8).
template <typename T, int N = 4>
class SensorCheck {
 public:
  static_assert(N >= 1 && N <= 8, "channel masks are 8 bits wide");
  static constexpr std::size_t kN_ = static_cast<std::size_t>(N);  ///< array extent
  static constexpr T kDefaultStuckTime = T(0.1);                      ///< Config::stuck_time's default [s]
  static constexpr std::uint8_t kDefaultStuckMinSamples = 50;          ///< Config::stuck_min_samples's default [-]

  /// Configuration; validated by configure(). Units are the channel's (Pa, rad/s).
  struct Config {
    /// Lower end of the transmitter's range (its live zero, 4 mA) [channel unit]; a reading
    /// at or below it is out of range. −∞ (the default) disables.
    T range_lo[kN_] = {};
    /// Upper end [channel unit], > range_lo; a reading from it up to the saturation band
    /// above it is saturated, beyond the band out of range. +∞ (the default) disables.
    T range_hi[kN_] = {};
    /// Time a channel must read one bit-identical value to be stuck [s], finite, ≥ 0.
    /// n equal samples at interval Δt count as n·Δt. Default 0.1 s: 100 samples at 1 kHz.
    T stuck_time = kDefaultStuckTime;
    /// Least number of equal samples that make a channel stuck, whatever the time [-]:
    /// 0 disables the stuck check, 1 is invalid. Equal successive samples are common on
    /// a coarsely quantised channel — a speed counted to 1 rpm with 0.5 rpm noise repeats
    /// its most likely code with probability ≈ 0.68, and examples/prv_blockage.csv (100 Hz)
    /// holds a run of 22 equal speed samples — so the time alone (10 samples at 100 Hz,
    /// 2 at a 4 s DAS) would call such a channel stuck. Default 50: 0.68^49 ≈ 6e-9 per
    /// sample; 0.5 s at 100 Hz, 200 s at 4 s.
    std::uint8_t stuck_min_samples = kDefaultStuckMinSamples;
    /// Sensor noise σ [channel unit], ≥ 0: a channel whose ADC step (learned: the smallest
    /// change between successive readings) is at least σ repeats its code nominally on a
    /// steady signal, so it is stuck only if the model moved meanwhile. Default as
    /// ResidualEvaluator's: 0.05 bar on pressures, 0.5 rpm on the fourth channel.
    T noise[kN_] = {};

    Config() noexcept {
      for (int i = 0; i < N; ++i) {
        range_lo[i] = -std::numeric_limits<T>::infinity();
        range_hi[i] = std::numeric_limits<T>::infinity();
        noise[i] = T(5e3);
      }
      if (N == 4) noise[N - 1] = T(0.5) * T(3.14159265358979323846) / T(30);
    }
  };

  /// The default configuration (valid: no range ends), flags clear — reset()'s state.
  SensorCheck() noexcept {
    set(Config{});
    reset();
  }

  /// Takes a configuration and resets.
  /// @return kOk, or kInvalidConfig (a range with NaN or lo ≥ hi, stuck_time not finite
  ///         or < 0, or stuck_min_samples = 1), checker unchanged
  Status configure(const Config& c) noexcept {
    if (c.stuck_min_samples == 1 || !(std::isfinite(c.stuck_time) && c.stuck_time >= T(0))) return Status::kInvalidConfig;
    for (int i = 0; i < N; ++i) {
      if (!(c.range_lo[i] < c.range_hi[i]) || !(std::isfinite(c.noise[i]) && c.noise[i] >= T(0))) {
        return Status::kInvalidConfig;
      }
    }
    set(c);
    reset();
    return Status::kOk;
  }

  /// Forgets the last values (no kHave) and clears the flags; keeps the learned ADC steps
  /// (a property of the channel, not of the run).
  void reset() noexcept {
    for (int i = 0; i < N; ++i) {
      flags_[i] = 0;
      last_[i] = std::numeric_limits<T>::quiet_NaN();  // no reading: the next is no step
    }
    sat_ = 0;
    latched_ = 0;
  }

  /// Checks one sample.
  /// @param t      sample time [s], non-decreasing (the stuck window is measured in it)
  /// @param y      N raw measurements [channel unit]
  /// @param valid  bit i set: channel i was sampled this tick (others keep their flags)
  /// @return       mask(): bit i set if channel i is a sensor problem (kSensorFaultFlags)
  std::uint8_t update(T t, const T* y, std::uint8_t valid) noexcept { return update(t, y, valid, NoModel{}); }

  /// update() with the model's say (Monitor): model(i, e, s) is called only for a channel
  /// off the fast path and sets e, the model's estimate of channel i, and s ≥ 0, the
  /// model's error allowance there [channel unit]. A reading at or below range_lo (but
  /// within the band below it, when range_hi is finite) is then a loop break only where
  /// e − range_lo > s — the physics says the channel cannot be at its live zero; elsewhere
  /// it is under range (kSensorUnderRange), a plausible reading of a machine at rest. And
  /// a coarse channel (ADC step ≥ its noise) is stuck only if e moved by more than two
  /// steps and s during the run. Without a model, every reading at or below range_lo is a
  /// loop break and a coarse channel is never stuck.
  template <typename ModelSay>
  std::uint8_t update(T t, const T* y, std::uint8_t valid, const ModelSay& model) noexcept {
    unsigned slow = 0;
    HSTMON_UNROLL
    for (int i = 0; i < N; ++i) {
      const unsigned bit = 1u << i;
      // Fast path (the nominal sample): sampled, strictly inside the range (so finite) and
      // not equal to the previous value — no flag, a run of one.
      if ((valid & bit) != 0 && y[i] > lo_[i] && y[i] < hi_[i] && y[i] != last_[i]) {
        prev_[i] = last_[i];
        last_[i] = y[i];
        since_[i] = t;
        flags_[i] = kHave;
      } else {
        slow |= bit;
      }
    }
    if (slow == 0) {
      sat_ = 0;
      return 0;
    }
    return update_slow(t, y, valid & slow, model);
  }

  /// The model argument of update() when there is none.
  struct NoModel {
    void operator()(int, T&, T&) const noexcept {}  ///< says nothing
  };

  /// SensorFlag bits of channel i from its last sample.
  std::uint8_t flags(int i) const noexcept { return static_cast<std::uint8_t>(flags_[i] & ~(kHave | kRun)); }
  /// Bit i set: channel i is a sensor problem now (a kSensorFaultFlags flag).
  std::uint8_t mask() const noexcept {
    unsigned m = 0;
    for (int i = 0; i < N; ++i) m |= (flags_[i] & kSensorFaultFlags) != 0 ? 1u << i : 0u;
    return static_cast<std::uint8_t>(m);
  }
  /// Bit i set: channel i is saturated now (kSensorSaturated; not a sensor problem).
  std::uint8_t saturated() const noexcept { return sat_; }
  /// Learned ADC step of channel i: the smallest change between successive readings seen
  /// (a multiple of the true step at worst) [channel unit]; 0 before any change.
  T step(int i) const noexcept { return step_[i]; }
  /// Bit i set: channel i was a sensor problem at some sample since reset.
  std::uint8_t latched() const noexcept { return latched_; }
  /// The configuration in use.
  Config config() const noexcept {
    Config c;
    for (int i = 0; i < N; ++i) {
      c.range_lo[i] = lo_[i];
      c.range_hi[i] = hi_[i];
    }
    c.stuck_time = stuck_time_;
    c.stuck_min_samples = min_samples_;
    for (int i = 0; i < N; ++i) c.noise[i] = noise_[i];
    return c;
  }

 private:
  /// Internal flags: last_ holds a finite sample; since_ holds the deadline of the run.
  static constexpr std::uint8_t kHave = 1u << 6, kRun = 1u << 7;

  void set(const Config& c) noexcept {
    for (int i = 0; i < N; ++i) {
      lo_[i] = c.range_lo[i];
      hi_[i] = c.range_hi[i];
    }
    stuck_time_ = c.stuck_time;
    min_samples_ = c.stuck_min_samples;
    for (int i = 0; i < N; ++i) {
      noise_[i] = c.noise[i];
      step_[i] = T(0);
      runs_[i] = 0;
    }
  }

  template <typename ModelSay>
  static constexpr bool has_model() noexcept {
    if constexpr (std::is_same_v<ModelSay, NoModel>) {
      return false;
    } else {
      return true;
    }
  }

  /// Learns channel i's ADC step from the change into the current run of equal readings
  /// (prev_ → last_), when a run begins: the smallest change seen is the step or a
  /// multiple of it. Runs are where the step matters, and this keeps the fast path to a
  /// store (the instruction budget per tick on the Cortex-M4F).
  void learn_step(int i) noexcept {
    const T d = std::fabs(last_[i] - prev_[i]);
    if (!(d > T(0))) return;
    if (step_[i] == T(0) || d < step_[i]) step_[i] = d;
    if (runs_[i] < 255) ++runs_[i];
  }

  /// True when channel i's step is known to be below its noise, or not known: one run
  /// says nothing (the jump into a frozen reading is no ADC step), two runs do.
  bool dithers(int i) const noexcept { return runs_[i] < 2 || !(step_[i] >= noise_[i]); }

  /// The channels off the fast path: full checks of the `sampled` ones, and the masks.
  template <typename ModelSay>
  HSTMON_SENSOR_SLOW_PATH std::uint8_t update_slow(T t, const T* y, unsigned sampled, const ModelSay& model) noexcept {
    unsigned fault = 0, sat = 0;
    for (int i = 0; i < N; ++i) {
      if (((sampled >> i) & 1u) != 0) {
        T e = T(0), s = T(0);
        model(i, e, s);
        const bool have = has_model<ModelSay>();
        check_channel(i, y[i], t, have && !(e - lo_[i] > s), e, s, have);
      }
      fault |= (flags_[i] & kSensorFaultFlags) != 0 ? 1u << i : 0u;
      sat |= (flags_[i] & kSensorSaturated) != 0 ? 1u << i : 0u;
    }
    sat_ = static_cast<std::uint8_t>(sat);
    latched_ = static_cast<std::uint8_t>(latched_ | fault);
    return static_cast<std::uint8_t>(fault);
  }

  /// The full check of sampled channel i with value v at time t: sets flags_[i].
  /// may_be_low: the model allows channel i at its live zero (see update's model).
  /// With a model (have_model), e and s are its estimate and allowance for channel i.
  HSTMON_SENSOR_SLOW_PATH void check_channel(int i, T v, T t, bool may_be_low, T e, T s, bool have_model) noexcept {
    if (!std::isfinite(v)) {
      flags_[i] = kSensorNonFinite;  // no kHave: the next finite sample starts a run
      return;
    }
    const T lo = lo_[i], hi = hi_[i];
    const T band = (hi - lo) * T(0.03125);  // NE 43's 0.5 mA of 16 mA; +∞ without a high end
    const unsigned before = flags_[i];
    unsigned f = kHave;
    if (v > hi + band || (v <= lo && !(may_be_low && v >= lo - band))) {
      f |= kSensorOutOfRange;
    } else if (v >= hi) {
      f |= kSensorSaturated;  // a clamped reading repeats by nature: never stuck
    } else if (v <= lo) {
      f |= kSensorUnderRange;  // clamped at the live zero, as a machine at rest reads
    }
    if ((before & kHave) == 0 || v != last_[i]) {  // a different value starts a run
      prev_[i] = (before & kHave) != 0 ? last_[i] : v;
      last_[i] = v;
      since_[i] = t;
    } else if (f == kHave && min_samples_ != 0) {
      if ((before & kRun) == 0) {
        // The run's second sample: Δt is this channel's sample interval, and n samples
        // count as n·Δt, so the run is stuck once t ≥ start + max(stuck_time,
        // min_samples·Δt) − Δt (less Δt/2 against rounding of the times).
        const T dt = t - since_[i];
        const T floor = static_cast<T>(min_samples_) * dt;
        since_[i] += (stuck_time_ > floor ? stuck_time_ : floor) - T(1.5) * dt;
        emin_[i] = emax_[i] = e;
        learn_step(i);
      }
      emin_[i] = e < emin_[i] ? e : emin_[i];
      emax_[i] = e > emax_[i] ? e : emax_[i];
      f |= kRun;
      // A step below the noise dithers: a long run is impossible for a working sensor. A
      // coarser one repeats on a steady signal: stuck only if the model moved by more
      // than two steps and its allowance while the reading stood still.
      const bool fine = dithers(i);
      const bool moved = have_model && emax_[i] - emin_[i] > T(2) * step_[i] + s;
      if (t >= since_[i] && (fine || moved)) f |= kSensorStuck;
    }
    flags_[i] = static_cast<std::uint8_t>(f);
  }

  T lo_[kN_] = {};      ///< Config::range_lo [channel unit]
  T noise_[kN_] = {};   ///< Config::noise [channel unit]
  T step_[kN_] = {};    ///< learned ADC step (learn_step) [channel unit]; 0: none seen
  T prev_[kN_] = {};    ///< the reading before last_ (with kHave) [channel unit]
  T emin_[kN_] = {};    ///< smallest model estimate during the current run [channel unit]
  T emax_[kN_] = {};    ///< largest model estimate during the current run [channel unit]
  T hi_[kN_] = {};      ///< Config::range_hi [channel unit]
  T stuck_time_ = kDefaultStuckTime;  ///< Config::stuck_time [s]
  T last_[kN_] = {};    ///< last finite sample (with kHave) [channel unit]
  /// Time of the first sample of the current run of equal values; with kRun, the time the
  /// run becomes stuck [s].
  T since_[kN_] = {};
  std::uint8_t flags_[kN_] = {};  ///< SensorFlag bits, kHave and kRun
  std::uint8_t runs_[kN_] = {};   ///< runs whose start taught the step (saturates at 255) [-]
  std::uint8_t sat_ = 0;          ///< saturated() of the last update
  std::uint8_t latched_ = 0;      ///< latched()
  std::uint8_t min_samples_ = kDefaultStuckMinSamples;  ///< Config::stuck_min_samples [-]
};

}  // namespace hstmon
