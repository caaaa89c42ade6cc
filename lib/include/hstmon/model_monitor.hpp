#pragma once
/// @file model_monitor.hpp
/// The whole monitor for any model in one object: observer (residuals), sensor checks,
/// residual evaluator (thresholds from noise and parameter uncertainty, CUSUM) and the
/// table-driven fault matcher. This is what firmware instantiates and what the host
/// replay runs, so both go through the same code. The model is the thesis rig's on the
/// engine (monitor.hpp's Monitor), its hand-written specialisation (the C API's), or any
/// circuit from the engine (circuit/circuit_monitor.hpp); it satisfies model_concept.hpp and has a ModelBound
/// (model_bound.hpp), steady_state() and slowest_rate(), and its Inputs compare with ==
/// (and, for Config::input_tolerance, offer inputs_within: input_change.hpp).
///
/// Each step(): observer tick → the model's own output variation (the transient
/// allowance) → sensor checks on the raw sample → evaluator on the residuals (a saturated
/// channel's only while above the model) → matcher. When the inputs change by more than
/// Config::input_tolerance (1 %), the model bound (parameter-uncertainty part of the
/// thresholds) is recomputed for the operating point they lead to: about 20 steady-state
/// solves, so a few hundred microseconds on a Cortex-M4, once per change.
///
/// Transients are the model's business, not the sensors' (docs/fdi.md §9):
///  - reset_measured() starts the observer where the first sample says (initial_state.hpp),
///    and nothing is judged during the model's own start-up from there: a hold-off of
///    (τ_m + τ_s)·ln D, τ_m the model's slowest time constant at the steady state for the
///    inputs, τ_s the slowest transducer (Config::transducer_response), D the initial
///    distance from that steady state in noise units;
///  - each channel's bound is widened by transient_factor × the model's recent output
///    variation (a leaky total variation with time constant τ_s, which bounds what a
///    first-order transducer lag of up to τ_s can make of the model's own transient) plus
///    half the learned ADC step; in steady operation the widening is 0;
///  - optionally (Config::model_transient, on for circuit monitors) also by the envelope
///    of the model's distance from its steady state, decaying with τ_m (the slowest time
///    constant at the operating point: with bound_carry, the slower of the last input
///    change's two points', else the last reset's): the parameter uncertainty's share of a
///    long, lightly damped transient after an input step;
///  - optionally (Config::bound_carry, on for circuit monitors) by the model bound in
///    force before the last input change, held while the model is on its way and then
///    decaying with the slower of the two operating points' time
///    constants: the machine leaves the old point's model error at its own pace;
///  - optionally (Config::timing_lead, on for circuit monitors) by the model's own change
///    over the next Δ = timing_lead·ε·τ while it is on its way to a new operating point
///    (ε the largest relative parameter uncertainty, τ the slowest time constant): a ±ε
///    machine runs its transient up to that much ahead of the model, and where a valve
///    opens on the way (a check valve as a line falls below the charge pressure) its
///    outputs jump that much earlier. A copy of the model run Δ ahead gives that change.
/// step() never allocates or throws.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "hstmon/fault_matcher.hpp"
#include "hstmon/fault_signature.hpp"
#include "hstmon/initial_state.hpp"
#include "hstmon/input_change.hpp"
#include "hstmon/model_bound.hpp"
#include "hstmon/observer.hpp"
#include "hstmon/residual_evaluator.hpp"
#include "hstmon/sensor_check.hpp"
#include "hstmon/status.hpp"

#if defined(__GNUC__)
#define HSTMON_RESET_PATH __attribute__((noinline, cold))
#else
#define HSTMON_RESET_PATH
#endif

namespace hstmon {

/// True when ModelBound B's compute() also reports the slowest time constant over the
/// models it solves (B::kSlowestTau; circuit_bound.hpp's does).
template <class B, class = void>
struct BoundReportsTau {
  static constexpr bool value = false;
};
template <class B>
struct BoundReportsTau<B, decltype(void(B::kSlowestTau))> {
  static constexpr bool value = B::kSlowestTau;
};

/// True when ModelBound B can run on the model itself and put it back
/// (B::compute_in_place(Model&, …): circuit_bound.hpp's), so the monitor's bound copies no
/// model onto the stack.
template <class B, class = void>
struct BoundInPlace {
  static constexpr bool value = false;
};
template <class B>
struct BoundInPlace<B, std::void_t<decltype(&B::compute_in_place)>> {
  static constexpr bool value = true;
};

namespace model_monitor_detail {
/// State of Config::bound_carry and Config::timing_lead; empty (no RAM: an empty base) for
/// a model whose bound reports no time constant (the thesis rig's), whose monitor cannot
/// carry or lead.
template <class Obs, typename T, std::size_t N, bool On>
struct CarryState {
  T carry_[N] = {};         ///< model bound carried over input changes, decaying [channel unit]
  T bound_carry_ = T(0);    ///< Config::bound_carry [-]
  T carry_decay_ = T(0);    ///< e^(−tick/τ_c), τ_c the slower of the last change's two points' [-]
  T tau_here_ = T(0);       ///< slowest time constant at the current inputs' steady state [s]
  bool carry_hold_ = false; ///< y_steady_ is the steady state of the current inputs
  /// bound_ and y_steady_ were computed at bound_inputs_
  bool bound_here_ = false;
  Obs lead_{};              ///< the observer's model, lead_ticks_ ticks ahead under the held inputs
  T timing_lead_ = T(0);    ///< Config::timing_lead [-]
  int lead_ticks_ = 0;      ///< ticks lead_ runs ahead [-]; 0 = no copy running
  T settle_taus_ = T(0);    ///< Config::settle_taus [-]
  T settle_floor_ = T(0);   ///< the configured matcher settle_time, the least it is given [s]
  T average_floor_ = T(0);  ///< the configured matcher average_time, likewise [s]
  bool windows_due_ = false;  ///< the matcher's windows wait for its episode to end
};
template <class Obs, typename T, std::size_t N>
struct CarryState<Obs, T, N, false> {};

/// x (> 0, finite) rounded up to the grid 2^(k/8), k integer, with exact steps only (frexp,
/// ldexp and comparisons with constants), so every target and libm rounds alike.
template <typename T>
T ceil_to_eighth_octave(T x) noexcept {
  static constexpr T kSteps[] = {T(1.0),
                                 T(1.0905077326652577),
                                 T(1.1892071150027210),
                                 T(1.2968395546510096),
                                 T(1.4142135623730951),
                                 T(1.5422108254079407),
                                 T(1.6817928305074290),
                                 T(1.8340080864093424),
                                 T(2.0)};
  int e = 0;
  const T m = std::frexp(x, &e) * T(2);  // [1, 2), x = m·2^(e−1)
  int k = 0;
  while (k < 8 && kSteps[k] < m) ++k;
  return std::ldexp(kSteps[k], e - 1);
}

/// ModelMonitor::Config's part that only a monitor that can carry has (an empty base
/// elsewhere, so the thesis rig's configuration is as it was).
template <typename T, bool On>
struct LeadConfig {
  /// How far ahead of the model the machine may run its transient after an input
  /// change, as a share of ε·τ [-], ≥ 0; 0 = off. ε is the largest relative parameter
  /// uncertainty, τ the slowest time constant at the new operating point over the model
  /// and its bound's perturbed and corner models: a ±ε machine's rates differ by about
  /// ε, so over the transient's first time constant its events come up to ε·τ early.
  /// Where a valve opens on the way (a check valve as a main line falls below the
  /// charge pressure) the machine's outputs then jump before the model's, which the
  /// transient allowance from the model's past change cannot cover. While the model is
  /// more than 2σ from its new steady state on some channel, a copy of it runs that far
  /// ahead under the held inputs, and the transient allowance's variation is at least
  /// the copy's distance from the model (one more observer tick per tick then, and one
  /// observer of RAM); 1 allows ε·τ. Only with bound_carry > 0 (whose time constants and
  /// steady state it takes); otherwise > 0 is kInvalidConfig.
  T timing_lead = T(0);
  /// The matcher's windows in slowest time constants of the operating point the machine
  /// is at [-], ≥ 0; 0 = the configured windows throughout. At each input change the
  /// matcher's settle time becomes the larger of the configured one and settle_taus·τ
  /// (3: 5 % of the transient left), and its averaging time the larger of the configured
  /// one and τ; τ as for timing_lead. A fault table's magnitudes are steady-state ones, and
  /// the slowest mode depends on the operating point (a closed circuit idling in neutral
  /// settles over several seconds, running in about one): the first row's time constant
  /// kept a running machine's verdicts waiting for the idle machine's.
  /// An episode keeps the windows it was detected under. Only with bound_carry > 0.
  T settle_taus = T(0);
};
template <typename T>
struct LeadConfig<T, false> {};
}  // namespace model_monitor_detail

/// @tparam ModelT  the model (see the file comment); its kOutputs are the channels
/// @tparam Capacity, QueueDepth, EventCandidates  storage sizes of the FaultMatcher
///   (table rows, queued events, candidates per event); firmware shrinks them (the C API
///   uses 26, 2, 1), the host keeps the defaults. The logic does not depend on them.
/// @tparam UsualTick  the observer's usual tick (Observer); the C API turns it off so that
///   it computes the firmware's bits on every target
template <class ModelT, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8,
          bool UsualTick = observer_detail::HasUsualTick<ModelT>::value>
class ModelMonitor
    : private model_monitor_detail::CarryState<Observer<ModelT, UsualTick>, typename ModelT::Scalar,
                                               static_cast<std::size_t>(ModelT::kOutputs),
                                               BoundReportsTau<ModelBound<ModelT>>::value> {
 public:
  using Model = ModelT;
  using T = typename Model::Scalar;
  static constexpr int kChannels = Model::kOutputs;  ///< measured channels (the model's outputs)
  static constexpr std::size_t kN_ = static_cast<std::size_t>(kChannels);  ///< array extent
  using Obs = Observer<Model, UsualTick>;
  using Inputs = typename Model::Inputs;
  using Evaluator = ResidualEvaluator<T, kChannels>;
  using Sensors = SensorCheck<T, kChannels>;
  using Matcher = FaultMatcher<T, Capacity, QueueDepth, EventCandidates, kChannels>;
  using Signature = typename Matcher::Signature;  ///< a row of the fault table
  using Uncertainty = typename ModelBound<Model>::Uncertainty;
  using Measurement = typename Obs::Measurement;
  using Event = typename Matcher::Event;
  /// True when the model's bound reports time constants, so Config::bound_carry may be on.
  static constexpr bool kCanCarry = BoundReportsTau<ModelBound<Model>>::value;

  /// Configuration of the parts; each validated by its own configure(). Where kCanCarry
  /// also Config::timing_lead (model_monitor_detail::LeadConfig; an empty base elsewhere).
  struct Config : model_monitor_detail::LeadConfig<T, kCanCarry> {
    typename Obs::Config observer{};          ///< tick, substeps, injection gain
    typename Evaluator::Config evaluator{};   ///< noise σ per channel, CUSUM factors
    typename Sensors::Config sensors{};       ///< transmitter ranges, stuck window
    typename Matcher::Config matcher{};       ///< windows, tie margin, clear hold
    Uncertainty uncertainty{};                ///< relative parameter uncertainty behind the model bound
    /// Slowest transducer response the monitor must tolerate: first-order time constant
    /// [s], ≥ 0. The transient allowance decays with it, and the start-up hold-off adds
    /// it to the model's own time constant. 10 ms covers ordinary pressure transmitters
    /// and speed pick-ups; 0 assumes perfect sensors.
    T transducer_response = T(0.01);
    /// Factor on the model's recent output variation that the residual may reach in a
    /// transient [-], ≥ 1: 1 covers a first-order transducer lag exactly; the rest covers
    /// the transient's share of the parameter error (±2 % moves an overshoot's size and
    /// timing by a few per cent of the excursion) and the tick's input timing.
    T transient_factor = T(1.5);
    /// Upper limit of the start-up hold-off [s], > 0 (only reached when the model has
    /// no stable operating point at the logged inputs).
    T startup_hold_max = T(2);
    /// Share of the model's own transient that the residual may reach [-], ≥ 0; 0 = off.
    /// The transient is the model's distance from its steady state at the current inputs,
    /// held as an envelope that decays with the model's slowest time constant. The
    /// parameter uncertainty moves a lightly damped mode's frequency by about as much, so
    /// after an input step model and machine ring out of phase by δ·ω·t of the envelope;
    /// 1 covers that up to a radian. It matters where the slowest mode rings long against
    /// the sample period (a closed-circuit HST: line volumes against the motor's inertia);
    /// where transients die within milliseconds (the thesis rig) 0 loses nothing and
    /// costs no steady solve per input change.
    T model_transient = T(0);
    /// Share of the model bound in force before an input change that the residual may
    /// still reach after it, on top of the new bound [-], ≥ 0; 0 = off. The bound is a steady-state
    /// one, so at the change the residual is the old operating point's model error, and
    /// the machine leaves it for the new one at its own pace: where the step crosses a
    /// valve's opening (a relief valve cracking in the model while the ±ε machine's stays
    /// shut, or the reverse) the new bound is much smaller and the machine's side of the
    /// valve is several times slower than the model's. The carry is held while the model
    /// is more than 2σ from its new steady state (the machine follows it with the old
    /// error), then decays with the slower of the slowest time constants at the old and
    /// the new operating point, over the model and its bound's perturbed copies (one more
    /// eigenvalue problem per steady solve of the bound); 1 carries it whole. Only where
    /// kCanCarry (a circuit's monitor); elsewhere > 0 is kInvalidConfig.
    T bound_carry = T(0);
    /// Relative change of the inputs [-], ≥ 0, up to which the operating point stays the
    /// same: the model bound is recomputed, and the matcher's pre-fault baseline
    /// restarted, once some input has moved further than this from its value at the last
    /// bound (input_change.hpp). A measured input (a drive speed, a supply pressure)
    /// differs on every row by its noise: each bound is about 20 steady solves, and a
    /// baseline restarted every row never forms. A bound 1 % off its operating point is
    /// off by about 1 % of itself (of a 2 % parameter effect). 0: every change.
    T input_tolerance = T(0.01);
  };

  ModelMonitor() noexcept = default;

  /// Sets parameters, configuration and fault table, then resets at rest for the default
  /// inputs. The table is borrowed and must outlive the monitor (a constexpr table does).
  /// For a model built from its parameters alone (the thesis rig's).
  /// @return kOk, kInvalidParams, kInvalidConfig, or the bound's kNoSteadyState
  template <typename M = Model>
  Status configure(const typename M::Params& params, const Config& c, const Signature* table, int count) noexcept {
    if (!Model::params_valid(params)) return Status::kInvalidParams;
    return configure(Model(params), c, table, count);
  }

  /// configure() with a model object: its parameters and description (a circuit model's)
  /// as given; it is copied.
  Status configure(const Model& model, const Config& c, const Signature* table, int count) noexcept {
    if (!(std::isfinite(c.transducer_response) && c.transducer_response >= T(0) &&
          std::isfinite(c.transient_factor) && c.transient_factor >= T(1) && std::isfinite(c.startup_hold_max) &&
          c.startup_hold_max > T(0) && std::isfinite(c.model_transient) && c.model_transient >= T(0) &&
          std::isfinite(c.bound_carry) && c.bound_carry >= T(0) && (kCanCarry || c.bound_carry == T(0)) &&
          std::isfinite(c.input_tolerance) && c.input_tolerance >= T(0) && lead_ok(c))) {
      return Status::kInvalidConfig;
    }
    Status s = obs_.configure(model, c.observer);
    if (s == Status::kOk) s = ev_.configure(c.evaluator);
    if (s == Status::kOk) s = sensors_.configure(c.sensors);
    if (s == Status::kOk) s = matcher_.configure(table, count, c.matcher);
    if (s != Status::kOk) return s;
    uncertainty_ = c.uncertainty;
    transducer_tau_ = c.transducer_response;
    transient_factor_ = c.transient_factor;
    hold_max_ = c.startup_hold_max;
    model_transient_ = c.model_transient;
    input_tolerance_ = c.input_tolerance;
    if constexpr (kCanCarry) {
      this->bound_carry_ = c.bound_carry;
      this->timing_lead_ = c.timing_lead;
      this->settle_taus_ = c.settle_taus;
      this->settle_floor_ = c.matcher.settle_time;
      this->average_floor_ = c.matcher.average_time;
    }
    set_decay();
    reset_rest_of_chain();
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
  template <typename M = Model>
  Status reconfigure(const typename M::Params& params, const typename Obs::Config& observer, const Signature* table,
                     int count) noexcept {
    Status s = obs_.configure(params, observer);
    if (s == Status::kOk) s = matcher_.set_table(table, count);
    if (s != Status::kOk) return s;
    set_decay();
    reset_rest_of_chain();
    return Status::kOk;
  }

  /// Restarts from the first sample m under inputs u: the observer starts where the
  /// measurements say (initial_state.hpp), and detection holds off while the model's own
  /// start-up transient from there lasts (startup_hold()). The usual way to start.
  /// @param how  out, optional: how the initial state was chosen
  Status reset_measured(const Inputs& u, const Measurement& m, InitialState* how = nullptr) noexcept {
    const Status s = obs_.reset_measured(u, m, how);
    if (s == Status::kOk) reset_rest_of_chain();
    return s;
  }

  /// Restarts at the steady state for inputs u (a log known to begin in operation).
  Status reset_steady(const Inputs& u) noexcept {
    const Status s = obs_.reset_steady(u);
    if (s == Status::kOk) reset_rest_of_chain();
    return s;
  }

  /// Restarts at rest for inputs u (a machine known to be at rest).
  Status reset_rest(const Inputs& u) noexcept {
    const Status s = obs_.reset_rest(u);
    if (s == Status::kOk) reset_rest_of_chain();
    return s;
  }

  /// One tick.
  /// @param t  sample time [s] (for events; the model advances by the configured tick)
  /// @param u  inputs held over the tick
  /// @param m  raw measurement at t (m.valid = 0: no sample this tick, the model just advances)
  /// @return   the matcher's status after the tick
  MatchStatus step(T t, const Inputs& u, const Measurement& m) noexcept {
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
  /// The inputs the model bound in use was last computed for.
  const Inputs& bound_inputs() const noexcept { return bound_inputs_; }
  /// The nominal model's steady outputs at bound_inputs() [channel unit], where both they
  /// and model_bound() were computed there at the last input change; nullptr otherwise (no
  /// steady state there, or no bound: the last good bound stays in force; or a monitor
  /// that does not carry its bound, which keeps no steady outputs per input change).
  const T* steady_outputs_at_bound_inputs() const noexcept {
    if constexpr (kCanCarry) {
      return this->bound_here_ ? y_steady_ : nullptr;
    } else {
      return nullptr;
    }
  }
  /// The transient allowance of channel i at the last sample [channel unit]: the model's
  /// own recent output variation times transient_factor, plus model_transient times the
  /// envelope of the model's distance from its steady state (0 unless configured), plus
  /// half the learned ADC step, plus the carried bound (0 unless configured; see the file
  /// comment).
  T transient_allowance(int i) const noexcept {
    const T a = transient_factor_ * peak_[i] + model_transient_ * env_[i] + T(0.5) * sensors_.step(i);
    if constexpr (kCanCarry) {
      return a + this->carry_[i];
    } else {
      return a;
    }
  }
  /// The carried bound of channel i [channel unit]: Config::bound_carry times the bound
  /// before the last input change (or the carry then, if larger), held and decayed since
  /// (0 unless configured).
  T carried_bound(int i) const noexcept {
    if constexpr (kCanCarry) {
      return this->carry_[i];
    } else {
      (void)i;
      return T(0);
    }
  }
  /// Start-up hold-off after the last reset [s]: no detection for this long after the
  /// first step (see plan_startup).
  T startup_hold() const noexcept { return hold_; }

 private:
  // Out of line and cold (size-optimised): one copy for reconfigure, reset_measured,
  // reset_steady and reset_rest (flash); it runs once per reset.
  HSTMON_RESET_PATH void reset_rest_of_chain() noexcept {
    ev_.reset();
    sensors_.reset();
    matcher_.reset();
    bound_valid_ = false;
    for (int i = 0; i < kChannels; ++i) {
      yprev_[i] = obs_.estimate()[i];
      var_[i] = T(0);
      gap_[i] = T(0);
      peak_[i] = T(0);
      env_[i] = T(0);
      if constexpr (kCanCarry) this->carry_[i] = T(0);
    }
    steady_ok_ = false;
    if constexpr (kCanCarry) {
      this->carry_hold_ = false;
      this->bound_here_ = false;
      this->lead_ticks_ = 0;
      this->windows_due_ = false;
    }
    plan_startup();
    hold_until_ = std::numeric_limits<T>::quiet_NaN();  // set by the first step
    settled_from_ = -std::numeric_limits<T>::infinity();
  }

  // Config::timing_lead and settle_taus valid: finite, ≥ 0, and 0 without bound_carry (true
  // where there are none).
  static bool lead_ok(const Config& c) noexcept {
    if constexpr (kCanCarry) {
      return std::isfinite(c.timing_lead) && c.timing_lead >= T(0) && std::isfinite(c.settle_taus) &&
             c.settle_taus >= T(0) && (c.bound_carry > T(0) || (c.timing_lead == T(0) && c.settle_taus == T(0)));
    } else {
      (void)c;
      return true;
    }
  }

  // Start-up hold-off: the time the model needs to come from its initial state to the
  // steady state at the inputs to within noise. Linearised at that steady state, an
  // initial distance of D noise units decays below one in τ·ln D, τ = 1/(slowest rate);
  // a transducer of time constant τ_s behind it adds τ_s·ln D. Nothing measured can be
  // judged before: the first sample of a start from rest reads the machine before the
  // supply came on. When the inputs admit no steady state the cap applies.
  HSTMON_RESET_PATH void plan_startup() noexcept {
    const Model& model = obs_.model();
    typename Model::State xs;
    T hold = hold_max_;
    if (model.steady_state(xs)) {
      const T rate = model.slowest_rate(xs);
      T d = T(1);
      for (int i = 0; i < Model::kStates; ++i) {
        const int ch = model.state_channel(i);
        if (ch < 0) continue;  // not measured: its distance is not in noise units
        const T di = std::fabs(xs[i] - obs_.state()[i]) / ev_.sigma(ch);
        d = di > d ? di : d;
      }
      if (rate > T(0)) {
        tau_m_ = T(1) / rate;
        const T h = (tau_m_ + transducer_tau_) * std::log(d);
        hold = h < hold_max_ ? h : hold_max_;
      }
      if (model_transient_ > T(0)) set_steady_outputs(xs);
    }
    hold_ = hold;
    env_decay_ = tau_m_ > T(0) ? std::exp(-obs_.config().tick / tau_m_) : T(0);
  }

  // The model transient's reference: the outputs at the steady state xs of the current
  // inputs. Out of line, as refresh_steady_outputs: a monitor without the model transient
  // (the thesis firmware's) keeps its reset and bound frames as they were.
  HSTMON_NOINLINE void set_steady_outputs(const typename Model::State& xs) noexcept {
    const auto y = obs_.model().outputs(xs);
    for (int i = 0; i < kChannels; ++i) y_steady_[i] = y[i];
    steady_ok_ = true;
  }

  // The transient allowance's per-tick decay e^(−h/τ_s) (0 for perfect sensors).
  HSTMON_RESET_PATH void set_decay() noexcept {
    decay_ = transducer_tau_ > T(0) ? std::exp(-obs_.config().tick / transducer_tau_) : T(0);
  }

  // The observer tick in its own frame (GCC, Clang), so that frame is gone when the bound
  // update runs. Returns true when the bound must be recomputed: first tick after a
  // reset, or the inputs the observer took on moved past Config::input_tolerance from
  // the last bound's — a new operating point, at which the matcher's baseline restarts.
  HSTMON_NOINLINE bool observe(T t, const Inputs& u, const Measurement& m) noexcept {
    // The observer holds the last good inputs when u is invalid, so a change is what it
    // actually took on, not what was offered.
    const Inputs before = obs_.model().inputs();
    (void)obs_.step(u, m);
    track_variation(m.valid != 0);
    if (!(hold_until_ == hold_until_)) hold_until_ = t + hold_;
    if (bound_valid_ && obs_.model().inputs() == before) return false;
    if (bound_valid_) {
      look_ahead();  // any change: the machine may be a tick ahead of the model
      if (inputs_close(bound_inputs_, obs_.model().inputs(), input_tolerance_)) return false;
      // The pre-fault baseline restarts at the changed operating point once its
      // transient has gone: 5 time constants of the model and the transducer.
      matcher_.restart_baseline();
      settled_from_ = t + T(5) * (tau_m_ + transducer_tau_);
    }
    return true;
  }

  // The model's own output variation: per channel a leaky total variation Σ|Δŷ| with the
  // transducer's time constant (var_), and the undecayed sum since the last sample
  // (gap_). A first-order transducer of time constant ≤ τ_s reads y_s − y =
  // −∫ y'(t−s)·e^(−s/τ_s) ds, whose size var_ bounds; a sample taken after ticks without
  // one may show the machine anywhere in between, which gap_ bounds. A sample's transient
  // allowance is transient_factor times the larger of the two (peak_), plus half an ADC
  // step (the reading's rounding, whatever the noise σ configured says) — computed only
  // for a channel whose residual needs it (allowance()).
  void track_variation(bool sampled) noexcept {
    const auto& y = obs_.estimate();
    for (int i = 0; i < kChannels; ++i) {
      const T d = std::fabs(y[i] - yprev_[i]);
      yprev_[i] = y[i];
      const T v = var_[i] * decay_ + d;
      const T g = gap_[i] + d;
      var_[i] = v;
      peak_[i] = v > g ? v : g;
      gap_[i] = sampled ? T(0) : g;
    }
    if constexpr (kCanCarry) carry_decay_tick(y);
    if (model_transient_ > T(0) && steady_ok_) {
      for (int i = 0; i < kChannels; ++i) {
        const T e = env_[i] * env_decay_;
        const T d = std::fabs(y[i] - y_steady_[i]);
        env_[i] = d > e ? d : e;
      }
    }
  }

  // One tick of the carried bound's decay (Config::bound_carry) and of the lead copy
  // (Config::timing_lead).
  template <class Y>
  void carry_decay_tick(const Y& y) noexcept {
    bool any_moving = false;
    if (this->bound_carry_ > T(0) || this->lead_ticks_ > 0) {
      // Held while the model is still more than 2σ from its new steady state: until then
      // the machine follows it with the old model error; then it settles at its own pace.
      for (int i = 0; i < kChannels; ++i) {
        const bool moving = this->carry_hold_ && std::fabs(y[i] - y_steady_[i]) > T(2) * ev_.sigma(i);
        any_moving = any_moving || moving;
        if (!moving) this->carry_[i] *= this->carry_decay_;
      }
    }
    if (this->lead_ticks_ > 0) {
      if (any_moving) {
        lead_tick(y);
      } else {
        this->lead_ticks_ = 0;  // settled: the machine can no longer be ahead by much
      }
    }
  }

  // Config::timing_lead: the copy advances a tick under the model's inputs, and its
  // distance from the model is the model's own change over the lead time ahead, which a
  // machine that runs ahead may already show.
  template <class Y>
  HSTMON_NOINLINE void lead_tick(const Y& y) noexcept {
    const Measurement none{};
    (void)this->lead_.step(obs_.model().inputs(), none);
    const auto& ahead = this->lead_.estimate();
    for (int i = 0; i < kChannels; ++i) {
      const T d = std::fabs(ahead[i] - y[i]);
      peak_[i] = d > peak_[i] ? d : peak_[i];
    }
  }

  // Starts the lead copy at the model's state, timing_lead·ε·τ ahead (at least a tick)
  // under the new inputs; τ [s] the slowest time constant at the new operating point.
  // A member template for the reason carry_bound is one.
  template <bool kOn = kCanCarry>
  HSTMON_NOINLINE void start_lead(T tau) noexcept {
    static_assert(kOn, "only a monitor whose model bound reports a time constant leads");
    this->lead_ticks_ = 0;
    const T tick = obs_.config().tick;
    const T ahead = this->timing_lead_ * ModelBound<Model>::largest_uncertainty(uncertainty_) * tau;
    if (!(ahead > T(0) && tick > T(0) && this->carry_hold_)) return;
    const T n = std::ceil(ahead / tick);
    const int ticks = n < T(100000) ? static_cast<int>(n) : 100000;  // a bounded start-up cost
    this->lead_ = obs_;
    const Measurement none{};
    for (int k = 0; k < ticks; ++k) (void)this->lead_.step(obs_.model().inputs(), none);
    this->lead_ticks_ = ticks;
  }

  // On an input change the logged change happened somewhere within the last sample
  // interval, while the model takes it on from this tick: the machine may be one tick
  // ahead, so the model's next-tick change counts now.
  HSTMON_NOINLINE void look_ahead() noexcept {
    const auto y = obs_.model().outputs(obs_.state());
    for (int i = 0; i < kChannels; ++i) {
      const T d = std::fabs(y[i] - yprev_[i]);
      var_[i] += d;
      gap_[i] += d;
      peak_[i] += d;
    }
  }

  // Sensor checks, residual evaluation and matching of the tick's residuals, in its own
  // frame (see step).
  HSTMON_NOINLINE MatchStatus evaluate(T t, const Measurement& m) noexcept {
    if (m.valid == 0) return matcher_.status();
    // A reading at a transmitter's live zero is a loop break only where the model,
    // allowed its error (bound, allowance and the CUSUM threshold), says the channel
    // cannot be there; asked only for a channel off the sensor check's fast path.
    const auto model_say = [this](int i, T& e, T& s) noexcept {
      e = obs_.estimate()[i];
      s = ev_.bound(i) + transient_allowance(i) + ev_.threshold(i);
    };
    const std::uint8_t sensor_mask = sensors_.update(t, m.y.data(), m.valid, model_say);
    // Start-up: the model's transient from its initial state is still running, so
    // nothing is judged; flags that persist (a loop break, a stuck channel) are reported
    // once it is over.
    if (t < hold_until_) return matcher_.status();  // a hold of 0 judges the first sample
    // A saturated reading is clipped at the range end, so the true residual is at least r:
    // r > 0 is evidence of a rise (a lower bound), r ≤ 0 none — the evaluator then holds
    // that channel (statistics and alarm) as if it were not sampled.
    const std::uint8_t saturated = sensors_.saturated();
    unsigned used = obs_.residual_valid();
    if (saturated != 0) {
      for (int i = 0; i < kChannels; ++i) {
        if (!(obs_.residual()[i] > T(0))) used &= ~(saturated & (1u << i));
      }
    }
    ev_.update(obs_.residual().data(), static_cast<std::uint8_t>(used),
               [this](int i) noexcept { return transient_allowance(i); });
    if constexpr (kCanCarry) {
      // An episode that held the windows back has ended: before this tick may start another.
      if (this->windows_due_ && matcher_.status() == MatchStatus::kNominal) set_windows();
    }
    return matcher_.update(t, ev_, sensor_mask, saturated, t >= settled_from_);
  }

  // The model bound at the observer's inputs: in place where the bound can put the model
  // back, else on a copy. tau: the slowest time constant, where the bound reports one.
  Status compute_bound(T (&m)[kN_], T* tau) noexcept {
    using B = ModelBound<Model>;
    if constexpr (BoundInPlace<B>::value) {
      return B::compute_in_place(obs_.borrow_model(), uncertainty_, m, tau);
    } else if constexpr (kCanCarry) {
      return B::compute(obs_.model(), uncertainty_, m, tau);
    } else {
      (void)tau;
      return B::compute(obs_.model(), uncertainty_, m);
    }
  }

  // Keeps the last good bound when the changed operating point has no steady state, and
  // the last steady outputs for the model transient's envelope likewise.
  void update_bound() noexcept {
    bound_inputs_ = obs_.model().inputs();
    if constexpr (kCanCarry) {
      if (this->bound_carry_ > T(0)) {
        carry_bound();
        bound_valid_ = true;
        return;
      }
    }
    if (model_transient_ > T(0)) refresh_steady_outputs();
    T m[kN_];
    if (compute_bound(m, nullptr) == Status::kOk) {
      for (int i = 0; i < kChannels; ++i) bound_[i] = m[i];
      (void)ev_.set_model_bound(bound_);
    }
    bound_valid_ = true;
  }

  // On an input change (Config::bound_carry): the old bound carried, the new bound, and
  // the carry's decay from the slower of the old and the new operating point's
  // slowest time constants, each over the model and the bound's perturbed copies. On the
  // first tick after a reset only the new point's is taken. Out of line, and only where
  // kCanCarry: the thesis monitor keeps its bound frame and its size as they were.
  // A member template, so that an explicit instantiation of the thesis rig's monitor
  // (lib/src/instantiate.cpp) does not instantiate it.
  template <bool kOn = kCanCarry>
  HSTMON_NOINLINE void carry_bound() noexcept {
    static_assert(kOn, "only a monitor whose model bound reports a time constant carries its bound");
    this->lead_ticks_ = 0;  // restarted below under the new inputs
    // The old bound, carried on top of the new one: the residual goes from the old model
    // error (up to the old bound) to the new one (up to the new bound), which may lie on
    // the other side (a closed circuit rings: carrying only the old bound's excess over
    // the new left 24 false alarms in 10 h on closed_loop_hst.json).
    if (bound_valid_) {
      for (int i = 0; i < kChannels; ++i) {
        const T c = this->bound_carry_ * bound_[i];
        this->carry_[i] = c > this->carry_[i] ? c : this->carry_[i];
      }
    } else {
      this->tau_here_ = T(0);
    }
    // The carry is held while the model is still on its way to this steady state.
    typename Model::State xs;
    this->carry_hold_ = obs_.model().steady_state(xs);
    this->bound_here_ = false;
    if (this->carry_hold_) set_steady_outputs(xs);
    T m[kN_];
    T tau_new = T(0);
    if (compute_bound(m, &tau_new) != Status::kOk) return;  // all stay
    for (int i = 0; i < kChannels; ++i) bound_[i] = m[i];
    this->bound_here_ = this->carry_hold_;
    (void)ev_.set_model_bound(bound_);
    const T tau = tau_new > this->tau_here_ ? tau_new : this->tau_here_;
    this->tau_here_ = tau_new;
    this->carry_decay_ = tau > T(0) ? std::exp(-obs_.config().tick / tau) : T(0);
    // The model transient's envelope and the baseline's settle follow the same time
    // constant, not the last reset's: a closed circuit started at rest has seconds-long
    // modes there that a running machine has not, and an envelope decaying with them kept
    // a 3 bar sensor offset (12σ) hidden for seconds after every load step. observe() set
    // settled_from_ from the old constant on this tick.
    if (tau > T(0)) {
      settled_from_ += T(5) * (tau - tau_m_);
      tau_m_ = tau;
      env_decay_ = std::exp(-obs_.config().tick / tau);
    }
    if (this->timing_lead_ > T(0) && bound_valid_) start_lead(tau_new);
    this->windows_due_ = this->settle_taus_ > T(0) && tau_new > T(0);
    if (this->windows_due_ && matcher_.status() == MatchStatus::kNominal) set_windows();
  }

  // Config::settle_taus: the matcher's windows from the slowest time constant at the last
  // input change (tau_here_), the configured ones at least. Between episodes only, so an
  // episode keeps the window it was detected under. τ is rounded up to an eighth of an
  // octave: a float build's τ (steady solves and eigenvalues to float precision) then gives
  // the double build's windows, and the same verdict on the same tick.
  template <bool kOn = kCanCarry>
  HSTMON_NOINLINE void set_windows() noexcept {
    static_assert(kOn, "only a monitor whose model bound reports a time constant follows it");
    const T tau = model_monitor_detail::ceil_to_eighth_octave(this->tau_here_);
    const T settle = this->settle_taus_ * tau;
    (void)matcher_.set_windows(settle > this->settle_floor_ ? settle : this->settle_floor_,
                               tau > this->average_floor_ ? tau : this->average_floor_);
    this->windows_due_ = false;
  }

  // set_steady_outputs at the current inputs' steady state, if they have one.
  HSTMON_NOINLINE void refresh_steady_outputs() noexcept {
    typename Model::State xs;
    if (obs_.model().steady_state(xs)) set_steady_outputs(xs);
  }

  Obs obs_{};
  Evaluator ev_{};
  Sensors sensors_{};
  Matcher matcher_{};
  Uncertainty uncertainty_{};
  T bound_[kN_] = {};
  T yprev_[kN_] = {};  ///< ŷ of the previous tick [channel unit]
  T var_[kN_] = {};    ///< leaky total variation of ŷ [channel unit]
  T gap_[kN_] = {};    ///< total variation of ŷ since the last sample [channel unit]
  T peak_[kN_] = {};   ///< max(var_, gap_) at the last tick [channel unit]
  T y_steady_[kN_] = {};  ///< outputs at the steady state of the current inputs [channel unit]
  T env_[kN_] = {};       ///< envelope of |ŷ − y_steady_|, decaying with τ_m [channel unit]
  T transducer_tau_ = T(0.01);  ///< Config::transducer_response [s]
  T transient_factor_ = T(1.5); ///< Config::transient_factor [-]
  T hold_max_ = T(2);           ///< Config::startup_hold_max [s]
  T model_transient_ = T(0);    ///< Config::model_transient [-]
  T input_tolerance_ = T(0.01);  ///< Config::input_tolerance [-]
  Inputs bound_inputs_{};       ///< the inputs the bound in force was computed for
  T env_decay_ = T(0);          ///< e^(−tick/τ_m) [-]
  T decay_ = T(0);              ///< e^(−tick/τ_s) [-]
  T hold_ = T(0);               ///< start-up hold-off [s]
  T hold_until_ = T(0);         ///< no judgement before this time [s]; NaN until the first step
  T tau_m_ = T(0);              ///< model's slowest time constant at the operating point (module comment) [s]
  T settled_from_ = T(0);       ///< the baseline follows the residuals from this time on [s]
  bool bound_valid_ = false;
  bool steady_ok_ = false;      ///< y_steady_ holds the current inputs' steady outputs
};

}  // namespace hstmon
