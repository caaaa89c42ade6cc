#pragma once
/// @file monitor.hpp
/// The whole monitor for the thesis rig in one object: observer (residuals), sensor
/// checks, residual evaluator (thresholds from noise and parameter uncertainty, CUSUM)
/// and the table-driven fault matcher. This is what firmware instantiates and what the
/// host replay runs, so both go through the same code.
///
/// Each step(): observer tick → sensor checks on the raw sample → evaluator on the
/// residuals (a saturated channel's only while above the model) → matcher. When the
/// inputs change, the model bound (parameter-uncertainty part of the thresholds) is
/// recomputed for the operating point they lead to: about 20 steady-state solves, so a few
/// hundred microseconds on a Cortex-M4, once per change.
/// step() never allocates or throws.

#include <cmath>
#include <cstdint>
#include <limits>

#include "hstmon/fault_matcher.hpp"
#include "hstmon/fault_signature.hpp"
#include "hstmon/observer.hpp"
#include "hstmon/residual_bounds.hpp"
#include "hstmon/residual_evaluator.hpp"
#include "hstmon/sensor_check.hpp"
#include "hstmon/status.hpp"
#include "hstmon/thesis_reduced.hpp"

#if defined(__GNUC__)
#define HSTMON_RESET_PATH __attribute__((noinline, cold))
#else
#define HSTMON_RESET_PATH
#endif

namespace hstmon {

/// @tparam Capacity, QueueDepth, EventCandidates  storage sizes of the FaultMatcher
///   (table rows, queued events, candidates per event); firmware shrinks them (the C API
///   uses 26, 2, 1), the host keeps the defaults. The logic does not depend on them.
/// @tparam UsualTick  the observer's usual tick (Observer); the C API turns it off so that
///   it computes the firmware's bits on every target
template <typename T, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8,
          bool UsualTick = ThesisReducedModel<T>::kHasUsualTick>
class Monitor {
 public:
  using Model = ThesisReducedModel<T>;
  using Obs = Observer<Model, UsualTick>;
  using Evaluator = ResidualEvaluator<T>;
  using Sensors = SensorCheck<T>;
  using Matcher = FaultMatcher<T, Capacity, QueueDepth, EventCandidates>;
  using Measurement = typename Obs::Measurement;
  using Event = typename Matcher::Event;

  /// Configuration of the parts; each validated by its own configure().
  struct Config {
    typename Obs::Config observer{};          ///< tick, substeps, injection gain
    typename Evaluator::Config evaluator{};   ///< noise σ per channel, CUSUM factors
    typename Sensors::Config sensors{};       ///< transmitter ranges, stuck window
    typename Matcher::Config matcher{};       ///< windows, tie margin, clear hold
    ThesisUncertainty<T> uncertainty{};       ///< relative parameter uncertainty behind the model bound
    /// After an input change the residuals are not accumulated for this long [s], ≥ 0.
    /// The bounds cover steady-state parameter error only; the transducer lags (10 ms on
    /// speed) and the ±2 % parameter error in the transient are not in the model, and a
    /// load step would otherwise read as a fault. 50 ms = 5 speed-sensor lags; a fault
    /// coinciding with a setting change is detected that much later.
    T input_settle_time = T(0.05);
  };

  Monitor() noexcept = default;

  /// Sets parameters, configuration and fault table, then resets at rest for the default
  /// inputs. The table is borrowed and must outlive the monitor (a constexpr table does).
  /// @return kOk, kInvalidParams, kInvalidConfig, or the bound's kNoSteadyState
  Status configure(const ThesisParams<T>& params, const Config& c, const FaultSignature* table,
                   int count) noexcept {
    if (!Model::params_valid(params)) return Status::kInvalidParams;
    if (!(std::isfinite(c.input_settle_time) && c.input_settle_time >= T(0))) return Status::kInvalidConfig;
    Status s = obs_.configure(Model(params), c.observer);
    if (s == Status::kOk) s = ev_.configure(c.evaluator);
    if (s == Status::kOk) s = sensors_.configure(c.sensors);
    if (s == Status::kOk) s = matcher_.configure(table, count, c.matcher);
    if (s != Status::kOk) return s;
    uncertainty_ = c.uncertainty;
    settle_time_ = c.input_settle_time;
    bound_valid_ = false;
    return Status::kOk;
  }

  /// New parameters, observer configuration and fault table; the evaluator, sensor checks
  /// and matcher keep their other settings, and so do the uncertainty and the settle time
  /// (on a default-constructed monitor: the defaults, i.e. configure() with Config{} but
  /// c.observer = observer). Resets like configure(), and like reset_rest() forgets the
  /// settling of the last input change. What the C API uses: no Config is
  /// built, so a whole Config and the model are never on the stack together (the create
  /// stack budget on the M4F), and no default configuration is materialised again (flash).
  /// @return kOk, kInvalidParams, or kInvalidConfig
  Status reconfigure(const ThesisParams<T>& params, const typename Obs::Config& observer, const FaultSignature* table,
                     int count) noexcept {
    Status s = obs_.configure(params, observer);
    if (s == Status::kOk) s = matcher_.set_table(table, count);
    if (s != Status::kOk) return s;
    reset_rest_of_chain();
    return Status::kOk;
  }

  /// Restarts at the steady state for inputs u (a log that begins in operation).
  Status reset_steady(const ThesisInputs<T>& u) noexcept {
    const Status s = obs_.reset_steady(u);
    if (s == Status::kOk) reset_rest_of_chain();
    return s;
  }

  /// Restarts at rest for inputs u.
  Status reset_rest(const ThesisInputs<T>& u) noexcept {
    const Status s = obs_.reset_rest(u);
    if (s == Status::kOk) reset_rest_of_chain();
    return s;
  }

  /// One tick.
  /// @param t  sample time [s] (for events; the model advances by the configured tick)
  /// @param u  inputs held over the tick
  /// @param m  raw measurement at t (m.valid = 0: no sample this tick, the model just advances)
  /// @return   the matcher's status after the tick
  MatchStatus step(T t, const ThesisInputs<T>& u, const Measurement& m) noexcept {
    // Three frames in turn, none nested in another: the observer tick, the bound update
    // on a tick whose inputs changed (the deepest stack of a step on the M4F), the rest.
    if (observe(t, u, m)) update_bound();
    return evaluate(t, m);
  }

  /// Oldest unread event; false when none.
  bool pop_event(Event& e) noexcept { return matcher_.pop_event(e); }

  const Obs& observer() const noexcept { return obs_; }
  const Evaluator& evaluator() const noexcept { return ev_; }
  const Sensors& sensors() const noexcept { return sensors_; }
  const Matcher& matcher() const noexcept { return matcher_; }
  /// Observer HealthFlag bits of the last tick (0 after a reset).
  std::uint32_t health() const noexcept { return obs_.last_health(); }
  /// The model bound in use, per channel [channel unit].
  const T* model_bound() const noexcept { return bound_; }

 private:
  static bool same_inputs(const ThesisInputs<T>& a, const ThesisInputs<T>& b) noexcept {
    return a.Psupl == b.Psupl && a.Ps == b.Ps && a.Pbp == b.Pbp && a.kp == b.kp;
  }

  // Out of line and cold (size-optimised): one copy for reconfigure, reset_steady and
  // reset_rest (flash); it runs once per reset.
  HSTMON_RESET_PATH void reset_rest_of_chain() noexcept {
    ev_.reset();
    sensors_.reset();
    matcher_.reset();
    bound_valid_ = false;
    settle_until_ = -std::numeric_limits<T>::infinity();
  }

  // The observer tick in its own frame (GCC, Clang), so that frame is gone when the bound
  // update runs. Returns true when the bound must be recomputed: first tick after a
  // reset, or the inputs the observer took on changed (then residuals settle first).
  HSTMON_NOINLINE bool observe(T t, const ThesisInputs<T>& u, const Measurement& m) noexcept {
    // The observer holds the last good inputs when u is invalid, so a change is what it
    // actually took on, not what was offered.
    const ThesisInputs<T> before = obs_.model().inputs();
    (void)obs_.step(u, m);
    if (bound_valid_ && same_inputs(obs_.model().inputs(), before)) return false;
    // The first inputs after a reset are no change: the observer starts consistent.
    if (bound_valid_) settle_until_ = t + settle_time_;
    return true;
  }

  // Sensor checks, residual evaluation and matching of the tick's residuals, in its own
  // frame (see step).
  HSTMON_NOINLINE MatchStatus evaluate(T t, const Measurement& m) noexcept {
    const std::uint8_t sensor_mask = sensors_.update(t, m.y.data(), m.valid);
    // A saturated reading is clipped at the range end, so the true residual is at least r:
    // r > 0 is evidence of a rise (a lower bound), r ≤ 0 none — the evaluator then holds
    // that channel (statistics and alarm) as if it were not sampled.
    const std::uint8_t saturated = sensors_.saturated();
    unsigned used = t < settle_until_ ? 0u : obs_.residual_valid();
    if (saturated != 0) {
      for (int i = 0; i < kFdiChannels; ++i) {
        if (!(obs_.residual()[i] > T(0))) used &= ~(saturated & (1u << i));
      }
    }
    ev_.update(obs_.residual().data(), static_cast<std::uint8_t>(used));
    if (m.valid == 0) return matcher_.status();
    return matcher_.update(t, ev_, sensor_mask, saturated);
  }

  // Keeps the last good bound when the changed operating point has no steady state.
  void update_bound() noexcept {
    T m[kFdiChannels];
    if (thesis_model_bound(obs_.model(), uncertainty_, m) == Status::kOk) {
      for (int i = 0; i < kFdiChannels; ++i) bound_[i] = m[i];
      (void)ev_.set_model_bound(bound_);
    }
    bound_valid_ = true;
  }

  Obs obs_{};
  Evaluator ev_{};
  Sensors sensors_{};
  Matcher matcher_{};
  ThesisUncertainty<T> uncertainty_{};
  T bound_[kFdiChannels] = {};
  T settle_time_ = T(0.05);
  T settle_until_ = -std::numeric_limits<T>::infinity();  ///< residuals ignored before this time [s]
  bool bound_valid_ = false;
};

}  // namespace hstmon
