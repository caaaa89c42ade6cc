#pragma once
/// @file observer.hpp
/// Fixed-tick observer: runs a plant model alongside measurements and produces one
/// residual per measured channel, r = y − ŷ, with optional output injection x += L·r.
///
/// Each tick, with inputs u_n and measurement y_n sampled at t_n:
///   1. ŷ_n = h(x_n, u_n), k1 = f(x_n, u_n) and the checks at x_n in one model evaluation;
///   2. r_n = y_n − ŷ_n on the channels marked valid and finite;
///   3. x_n += L·r_n (skipped when L = 0);
///   4. x_{n+1} = RK4 over the tick in n_sub substeps, n_sub = ⌈ρ·h / (λh)_max⌉, with ρ the
///      spectral radius of ∂f/∂x at x_n (so a stiff operating point — start from rest,
///      a restricted PRV — gets more substeps instead of a silent false fixed point);
///      with a model that gives its state envelope (the circuit engine), each substep also
///      checks the stiffness its stages met (checked_substep), and a tick whose stage
///      arguments need more than twice the substeps it was sized for is taken again, finer
///      (a relief valve that opens within the tick, where ρ at x_n saw it shut);
///      where n_sub would exceed Config::implicit_above and the model offers its Jacobian
///      (`void jacobian(const State&, StateMatrix&) const`), error-controlled linearly
///      implicit Rosenbrock steps over the tick instead (rosenbrock_tick: a mode much faster
///      than the tick, such as a line on an open check valve, is damped in one step at the
///      cost of about one RK4 substep and an n×n factorisation; usually one step a tick).
/// All state lives in the object (a few hundred bytes); step() never allocates, never
/// throws, and is O(n_sub).
///
/// Usual tick: a model may offer a fused form of steps 1 and 4 for its usual operating
/// region (Model::kHasUsualTick, usual_tick_coeffs, usual_tick, usual_plausible,
/// tick_radius; ThesisReducedModel and circuit::CompiledModel off Arm M-profile). step()
/// tries it first when every input is unchanged and there is no injection gain: one fused
/// step where one substep is known to suffice, else n fused substeps with n from the
/// general path's own ρ; and it takes the general path above when the state or a stage is
/// outside the region. The same model, RK4 and substep count, to rounding (CompiledModel:
/// bit for bit). The region's coefficients are computed when the inputs change; a region
/// centred on a state (usual_tick_coeffs(h, rho_max, x): CompiledModel's certified box) is
/// computed once the inputs have held for a tick, and re-centred where the state has left
/// it. Observer<Model, false> has no usual tick
/// (every tick on the general path, and no storage for it: the C API, and any build that
/// must compute the firmware's bits).
///
/// Model requirements (model_concept.hpp checks them; see ThesisReducedModel): Scalar, State, Output, Inputs, kStates,
/// kOutputs, set_inputs(), inputs(), static inputs_valid(), outputs(x), rest_state(),
/// steady_state(x), derivative(x) (RK4 stages), state_plausible(x) (false for any
/// non-finite x), and
///   State tick_derivative(x, rho_max, Output& y, T& rho, bool& alg_ok):
///     derivative(x) with y = outputs(x), rho = spectral radius of ∂f/∂x [1/s] (or 0 if it
///     is ≤ rho_max, NaN if x is), alg_ok = the model's algebraic solve contracts at x.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "hstmon/code_size.hpp"
#include "hstmon/initial_state.hpp"
#include "hstmon/model_concept.hpp"
#include "hstmon/rk4.hpp"
#include "hstmon/rosenbrock.hpp"
#include "hstmon/status.hpp"

/// The general tick: out of line where the usual tick is in front of it (HSTMON_USUAL_TICK,
/// hosts by default: the usual tick's frame stays small, and the general tick is one copy
/// for step() and the usual substeps), inline where it is step()'s only path (firmware by
/// default: flash and stack).
#if defined(__GNUC__) && HSTMON_USUAL_TICK
#define HSTMON_OFF_USUAL_PATH __attribute__((noinline))
#elif defined(__GNUC__)
#define HSTMON_OFF_USUAL_PATH inline __attribute__((always_inline))
#else
#define HSTMON_OFF_USUAL_PATH
#endif
/// The residuals, shared by both paths: inline on firmware (one call site, where a call
/// would cost flash and cycles); the compiler's choice on hosts (it keeps them out of line,
/// which leaves the usual tick's registers to the RK4 stages).
#if defined(__GNUC__) && HSTMON_FLASH_LEAN
#define HSTMON_TICK_PART inline __attribute__((always_inline))
#else
#define HSTMON_TICK_PART inline
#endif

/// 1 (the default): observers of models with a Jacobian take linearly implicit steps on
/// stiff ticks; 0: RK4 substeps always (see Observer::kImplicit).
#ifndef HSTMON_IMPLICIT_TICKS
#define HSTMON_IMPLICIT_TICKS 1
#endif

namespace hstmon {

namespace observer_detail {
/// Model::kHasUsualTick, false for models without it.
template <typename M, typename = void>
struct HasUsualTick : std::false_type {};
template <typename M>
struct HasUsualTick<M, std::void_t<decltype(M::kHasUsualTick)>> : std::bool_constant<M::kHasUsualTick> {};

/// True when M::usual_tick_coeffs takes the state its region is centred on (h, rho_max,
/// x): the region then moves with the state, and is re-centred when the state leaves it.
template <typename M, typename = void>
struct UsualTickCentred : std::false_type {};
template <typename M>
struct UsualTickCentred<M, std::void_t<decltype(std::declval<const M&>().usual_tick_coeffs(
                               typename M::Scalar(), typename M::Scalar(), std::declval<const typename M::State&>()))>>
    : std::true_type {};

/// The observer's usual-tick coefficients, and nothing for an observer without a usual tick.
template <typename M, bool>
struct UsualTickState {
  typename M::UsualTick c{};   ///< Model::usual_tick_coeffs for one step of the tick (stiffness box)
  typename M::UsualTick cn{};  ///< the same for a substep of tick/n, validity box only (n ≥ 2)
  std::uint64_t ticks = 0;     ///< ticks since the last reset that took the usual tick
  std::uint64_t recentre_at = 0;  ///< centred regions: the first tick that may re-centre c
  int n = 0;                   ///< the substep count cn is for; 0: none yet (inputs changed)
  bool stale = true;           ///< centred regions: c is not for the current inputs and state yet
  bool on = false;             ///< no injection gain
};
template <typename M>
struct UsualTickState<M, false> {};

/// True when M offers `void jacobian(const State&, StateMatrix&) const` (∂f/∂x): its stiff
/// ticks can take the linearly implicit step.
template <typename M, typename = void>
struct HasJacobian : std::false_type {};
template <typename M>
struct HasJacobian<M, std::void_t<decltype(std::declval<const M&>().jacobian(
                          std::declval<const typename M::State&>(), std::declval<typename M::StateMatrix&>()))>>
    : std::true_type {};

/// True when M's tick_derivative takes a sixth argument rho_stiff (the radius above which
/// the observer only needs to know the radius is above it: circuit models).
template <typename M, typename = void>
struct HasStiffCut : std::false_type {};
template <typename M>
struct HasStiffCut<
    M, std::void_t<decltype(std::declval<const M&>().tick_derivative(
           std::declval<const typename M::State&>(), typename M::Scalar(), std::declval<typename M::Output&>(),
           std::declval<typename M::Scalar&>(), std::declval<bool&>(), typename M::Scalar()))>> : std::true_type {};

/// The linearly implicit ticks' settings (Observer::Config's), and nothing for a model
/// without a Jacobian (an empty base: no bytes).
template <typename T, bool>
struct ImplicitConfig {
  /// A tick that would need more RK4 substeps than this is integrated by Rosenbrock steps
  /// instead (rosenbrock_tick) [-]; 0: RK4 substeps always.
  std::uint16_t implicit_above = 4;
  /// Finest Rosenbrock step: tick/2^implicit_max_level [-], 0 … 15.
  std::uint8_t implicit_max_level = 8;
  /// Error accepted per Rosenbrock step, relative to each state's running peak |x| [-].
  T implicit_rtol = T(1e-3);
};
template <typename T>
struct ImplicitConfig<T, false> {};

/// The linearly implicit ticks' state (an empty base without a Jacobian: no bytes).
template <typename M, bool>
struct ImplicitState {
  typename M::State implicit_peak = M::State::Zero();  ///< running peak |x| since reset: the steps' error scale
  std::uint64_t implicit_count = 0;  ///< ticks since the last reset that were implicit
  int implicit_level = 0;            ///< the last implicit tick's step level (step tick/2^level)
  bool implicit_last = false;        ///< the last tick was implicit
};
template <typename M>
struct ImplicitState<M, false> {};

/// The stage check's weights (Observer::kStageCheck), and nothing without the check (an
/// empty base: no bytes).
template <typename M, bool>
struct StageCheckState {
  typename M::State stage_weight = M::State::Zero();  ///< 1/state envelope [1/state unit], 0 for unused states
};
template <typename M>
struct StageCheckState<M, false> {};

/// True when Observer<M> checks its substeps' stages (Observer::kStageCheck).
template <typename M>
constexpr bool kChecksStages = (model_detail::HasStateEnvelope<M>::value && model_detail::PressureThresholds<M>::value);
}  // namespace observer_detail

/// One sample of a model's measured channels, for Observer::step.
template <typename Output>
struct ChannelSample {
  Output y = Output::Zero();  ///< values in the model's output units (SI)
  std::uint8_t valid = 0;     ///< bit i set: channel i was measured this tick
};

/// @tparam UsualTick  take the model's usual tick (see the file comment); by default
///   wherever the model has one
template <typename Model, bool UsualTick = observer_detail::HasUsualTick<Model>::value>
class Observer
    : private observer_detail::ImplicitState<Model, HSTMON_IMPLICIT_TICKS && observer_detail::HasJacobian<Model>::value>,
      private observer_detail::StageCheckState<Model, observer_detail::kChecksStages<Model>> {
 public:
  using T = typename Model::Scalar;
  using State = typename Model::State;
  using Output = typename Model::Output;
  using Inputs = typename Model::Inputs;
  static constexpr int kStates = Model::kStates;
  static constexpr int kOutputs = Model::kOutputs;
  /// True when the model offers a fused usual tick (see the file comment).
  static constexpr bool kUsualTick = UsualTick;
  /// True when the model offers its Jacobian, so stiff ticks can be linearly implicit, and
  /// the build has not compiled that out (HSTMON_IMPLICIT_TICKS=0: about 0.8 KiB of flash on
  /// a Cortex-M4F, for a circuit whose stiff ticks are start-ups that RK4 substeps cover).
  static constexpr bool kImplicit = HSTMON_IMPLICIT_TICKS && observer_detail::HasJacobian<Model>::value;
  /// True when stiff ticks skip refining the radius bound (kImplicit and a model whose
  /// tick_derivative takes rho_stiff).
  static constexpr bool kStiffCut = kImplicit && observer_detail::HasStiffCut<Model>::value;
  /// True when each RK4 substep also checks how stiff the model was along its stages
  /// (checked_substep), and a tick whose stages met more than it was sized for is taken
  /// again, finer: models that give their states' envelopes (the circuit engine) and have
  /// valves, which change the stiffness within a step (model_detail::PressureThresholds).
  static constexpr bool kStageCheck = observer_detail::kChecksStages<Model>;
  static_assert(ObserverModelParts<Model>::kTypes,
                "model: needs Scalar, State, Output, Inputs, kStates, kOutputs (model_concept.hpp)");
  static_assert(ObserverModelParts<Model>::kInputs, "model: needs inputs_valid, set_inputs, inputs (model_concept.hpp)");
  static_assert(ObserverModelParts<Model>::kStates,
                "model: needs outputs, rest_state, steady_state, state_plausible, state_channel (model_concept.hpp)");
  static_assert(ObserverModelParts<Model>::kDerivatives,
                "model: needs derivative and tick_derivative (model_concept.hpp)");
  static_assert(!UsualTick || observer_detail::HasUsualTick<Model>::value, "the model has no usual tick");
  static_assert(kOutputs <= 8, "channel masks are 8 bits wide");
  /// Output-injection gain L [state unit per channel unit], applied once per tick.
  using Gain = Eigen::Matrix<T, kStates, kOutputs>;

  /// Observer configuration; validated by configure(). With a model that has a Jacobian,
  /// also implicit_above, implicit_max_level, implicit_rtol (observer_detail::ImplicitConfig).
  struct Config : observer_detail::ImplicitConfig<T, kImplicit> {
    T tick = T(1e-3);                   ///< tick h [s], > 0
    T lambda_h_max = T(0.8);            ///< largest |λ|·h_sub per RK4 substep [-], in (0, 2.5]
    std::uint16_t max_substeps = 256;   ///< substep cap per tick [-], ≥ 1
    Gain gain = Gain::Zero();           ///< output injection L; zero = pure parallel model
  };

  /// One sample of the measured channels (the same type with and without the usual tick).
  using Measurement = ChannelSample<Output>;

  Observer() noexcept = default;

  /// Takes a model (parameters set) and a configuration, and resets to the model's
  /// rest state. O(1).
  /// @return kOk, or kInvalidConfig with the observer left unchanged
  Status configure(const Model& model, const Config& cfg) noexcept {
    if (!config_ok(cfg)) return Status::kInvalidConfig;
    model_ = model;
    apply(cfg);
    return Status::kOk;
  }

  /// configure(Model(p), cfg) without building and copying a model: the observer's own
  /// model takes the parameters in place and default inputs (firmware: no block copy).
  /// Needs Model::set_params and Model::params_valid (a template, so only models that
  /// have them are asked for them).
  /// @return kOk, kInvalidParams or kInvalidConfig, with the observer left unchanged
  template <typename M = Model>
  Status configure(const typename M::Params& p, const Config& cfg) noexcept {
    if (!M::params_valid(p)) return Status::kInvalidParams;
    if (!config_ok(cfg)) return Status::kInvalidConfig;
    model_.set_params(p);
    model_.set_inputs(Inputs{});
    apply(cfg);
    return Status::kOk;
  }

  /// configure(Model(d, p), cfg) for a model bound to a description (the circuit
  /// engine): the observer's own model binds d and takes p in place, so firmware builds no
  /// model on its stack. d is kept by pointer and must outlive the observer (flash).
  /// Needs Model::bind, set_params and valid() (a template: asked only of such models).
  /// @return kOk, kInvalidParams (d rejected, or values not physical) or kInvalidConfig;
  ///         on kInvalidParams the observer's model is left unbound
  template <typename M = Model>
  Status configure(const typename M::Description& d, const typename M::Params& p, const Config& cfg) noexcept {
    if (!M::params_valid(p)) return Status::kInvalidParams;
    if (!config_ok(cfg)) return Status::kInvalidConfig;
    model_.set_inputs(Inputs{});
    model_.set_params(p);
    // bind's error type value-initialised is its kOk.
    if (model_.bind(d) != decltype(model_.bind(d)){} || !model_.valid()) return Status::kInvalidParams;
    apply(cfg);
    return Status::kOk;
  }

  /// Restarts from state x0 at t = 0 with the latched health cleared.
  void reset(const State& x0) noexcept {
    s_.reset(x0);
    yhat_ = model_.outputs(x0);
    r_.setZero();
    r_valid_ = 0;
    ticks_ = 0;
    if constexpr (kUsualTick) {
      usual_.ticks = 0;
      usual_.recentre_at = 0;
      // A region centred on the old state is of no use at x0.
      if (observer_detail::UsualTickCentred<Model>::value) inputs_changed();
    }
    substeps_ = 0;
    if constexpr (kImplicit) {
      this->implicit_count = 0;
      this->implicit_level = 0;
      this->implicit_last = false;
      this->implicit_peak = x0.cwiseAbs();
      if constexpr (model_detail::HasStateEnvelope<Model>::value) {
        // A state that starts at 0 (a shaft at rest) is judged against a small part of its
        // envelope, not against its own vanishing magnitude.
        this->implicit_peak = this->implicit_peak.cwiseMax(kImplicitFloor * model_.state_envelope());
      }
    }
    health_ = 0;
    last_health_ = 0;
  }

  /// Restarts at the steady state for inputs u (for logs that begin in operation).
  /// @return kOk, kInvalidInputs, or kNoSteadyState (observer unchanged)
  Status reset_steady(const Inputs& u) noexcept {
    if (!Model::inputs_valid(u)) return Status::kInvalidInputs;
    // The model's inputs are restored on failure rather than the model copied (132 B):
    // set_inputs is a function of the inputs alone.
    const Inputs held = model_.inputs();
    model_.set_inputs(u);
    State x;
    if (!model_.steady_state(x)) {
      model_.set_inputs(held);
      return Status::kNoSteadyState;
    }
    inputs_changed();
    reset(x);
    return Status::kOk;
  }

  /// Restarts at rest for inputs u.
  Status reset_rest(const Inputs& u) noexcept {
    if (!Model::inputs_valid(u)) return Status::kInvalidInputs;
    model_.set_inputs(u);
    inputs_changed();
    reset(model_.rest_state());
    return Status::kOk;
  }

  /// Restarts from the first sample m under inputs u, by choose_initial_state
  /// (initial_state.hpp): from the measured states when all are measured, else at rest or
  /// at the steady state, whichever the measurements say.
  /// @param how  out, optional: how the state was chosen
  /// @return kOk or kInvalidInputs (observer unchanged)
  Status reset_measured(const Inputs& u, const Measurement& m, InitialState* how = nullptr) noexcept {
    if (!Model::inputs_valid(u)) return Status::kInvalidInputs;
    model_.set_inputs(u);
    inputs_changed();
    State x;
    const InitialState k = choose_initial_state(model_, m.y, m.valid, x);
    if (how != nullptr) *how = k;
    reset(x);
    return Status::kOk;
  }

  /// Advances one tick (see the file comment).
  /// @param u  inputs held over the tick; invalid inputs are replaced by the last good ones
  /// @param m  measurement at the start of the tick; m.valid = 0 just advances the model
  /// @return   this tick's HealthFlag bits (also OR-ed into health())
  std::uint32_t step(const Inputs& u, const Measurement& m) noexcept {
    if constexpr (kUsualTick) {
      // Inputs are usually held for many ticks: when they are the bytes the model already
      // has (only valid inputs are ever stored), neither their check nor the model's
      // input-dependent coefficients need redoing.
      if (usual_.on && same_bytes(u, model_.inputs())) {
        if constexpr (observer_detail::UsualTickCentred<Model>::value) {
          if (usual_.stale) refresh_usual();
        }
        State dx;
        if (model_.usual_tick(usual_.c, s_.x, yhat_, dx)) {
          const State x_before = s_.x;
          s_.add(dx);
          return finish_usual(m, x_before, 1, usual_.c);
        }
        return usual_substeps(u, m);
      }
    }
    return general_step(u, m);
  }

  /// Residuals r = y − ŷ of the last tick, in output units; 0 where not valid.
  const Output& residual() const noexcept { return r_; }
  /// Bit i set: residual i was computed in the last tick.
  std::uint8_t residual_valid() const noexcept { return r_valid_; }
  /// Model outputs ŷ at the start of the last tick (before injection), output units.
  const Output& estimate() const noexcept { return yhat_; }
  /// Current model state (after the last tick), state units.
  const State& state() const noexcept { return s_.x; }
  /// Time since the last reset [s] (ticks × h, so it does not accumulate rounding).
  T time() const noexcept { return static_cast<T>(ticks_) * cfg_.tick; }
  /// Ticks since the last reset.
  std::uint64_t ticks() const noexcept { return ticks_; }
  /// Ticks since the last reset that took the model's fused usual tick (0 without one).
  std::uint64_t usual_ticks() const noexcept {
    if constexpr (kUsualTick) {
      return usual_.ticks;
    } else {
      return 0;
    }
  }
  /// Steps the last tick took: RK4 substeps, or Rosenbrock steps tried on an implicit tick.
  std::uint16_t substeps() const noexcept { return substeps_; }
  /// True when the last tick was linearly implicit.
  bool implicit() const noexcept {
    if constexpr (kImplicit) {
      return this->implicit_last;
    } else {
      return false;
    }
  }
  /// Ticks since the last reset that were linearly implicit (0 without a Jacobian).
  std::uint64_t implicit_ticks() const noexcept {
    if constexpr (kImplicit) {
      return this->implicit_count;
    } else {
      return 0;
    }
  }
  /// HealthFlag bits of the last tick.
  std::uint32_t last_health() const noexcept { return last_health_; }
  /// HealthFlag bits OR-ed over all ticks since reset (latched).
  std::uint32_t health() const noexcept { return health_; }
  const Config& config() const noexcept { return cfg_; }
  const Model& model() const noexcept { return model_; }
  /// The model, writable: only for a caller that changes it and puts it back bit for bit
  /// before the next step (the monitor's in-place model bound); anything else goes through
  /// configure and the inputs of step.
  Model& borrow_model() noexcept { return model_; }

 private:
  /// The usual tick in n ≥ 2 substeps (a PLC scan, a stiffer point): n from the general
  /// tick's own ρ at x (Model::tick_radius, bit for bit), then n fused steps of tick/n, each
  /// stage checked against the model's validity box; the general tick if n = 1 here, n is
  /// over the cap, or a stage leaves the box (the state is only committed at the end).
  HSTMON_OFF_USUAL_PATH std::uint32_t usual_substeps(const Inputs& u, const Measurement& m) noexcept {
    if constexpr (kUsualTick) {
      const T rho = model_.tick_radius(s_.x, rho_one_);
      const int n = rho > T(0) ? substep_count(rho) : 0;
      if (rho == T(0) && observer_detail::UsualTickCentred<Model>::value && ticks_ >= usual_.recentre_at) {
        // One substep suffices here but the state has left the region c was centred on:
        // centre it here for the ticks that follow (at most every kRecentreTicks ticks, so
        // that a transient does not pay for a certificate every tick).
        usual_.recentre_at = ticks_ + kRecentreTicks;
        refresh_usual();
      }
      if (n > 0 && !takes_implicit(n)) {
        if (n != usual_.n) {
          usual_.cn = usual_coeffs(cfg_.tick / static_cast<T>(n), std::numeric_limits<T>::infinity());
          usual_.n = n;
        }
        CompensatedState<State> s = s_;
        Output y;
        Output y_sub;
        int i = 0;
        for (; i < n; ++i) {
          State dx;
          if (!model_.usual_tick(usual_.cn, s.x, i == 0 ? y : y_sub, dx)) break;
          s.add(dx);
        }
        if (i == n) {
          yhat_ = y;
          const State x_before = s_.x;
          s_ = s;
          return finish_usual(m, x_before, n, usual_.cn);
        }
        if (observer_detail::UsualTickCentred<Model>::value) usual_.n = 0;  // re-centred next time
      }
    }
    return general_step(u, m);
  }

  /// step() on the general path: any state, inputs, measurement mask and gain.
  HSTMON_OFF_USUAL_PATH std::uint32_t general_step(const Inputs& u, const Measurement& m) noexcept {
    std::uint32_t flags = 0;
    // As in step(): inputs are only checked and set when their bytes change.
    if (!same_bytes(u, model_.inputs())) {
      if (Model::inputs_valid(u)) {
        model_.set_inputs(u);
        inputs_changed();
      } else {
        flags |= kHealthInputNonFinite;
      }
    }

    const State x_before = s_.x;  // finite: every tick ends on a finite state
    T rho;
    bool alg_ok;
    State k1 = first_derivative(rho, alg_ok);
    flags |= take_residuals(m);
    if (has_gain_ && r_valid_ != 0) {
      s_.add(cfg_.gain * r_);  // masked channels carry r = 0
      Output y_injected;      // ŷ stays the pre-injection estimate
      k1 = model_.tick_derivative(s_.x, rho_one_, y_injected, rho, alg_ok);
    }

    if (!alg_ok) flags |= kHealthAlgebraicDiverged;
    // Substeps from the local stiffness: |λ|·h_sub ≤ lambda_h_max keeps RK4 both stable
    // and accurate (its stability limit on the negative real axis is ≈ 2.79).
    // Common case first: ρ ≤ rho_one_ needs one substep and the model then reports ρ = 0
    // (without computing it), so there is no ceil and no division. NaN compares false and
    // also gets one substep (the state check below flags it).
    int n = 1;
    Rk4Step<T> h = one_step_;
    if constexpr (kImplicit) this->implicit_last = false;
    if (rho > T(0)) {
      n = substep_count(rho);
      if (takes_implicit(n)) {
        if (implicit_step(k1, flags)) return finish_implicit(x_before, flags);
        // Explicit after all: the substeps need the full bound where the stiff cut gave a
        // looser one (the derivative is recomputed, as it would be, and then discarded).
        if (kStiffCut && rho > stiff_cut()) n = substep_count(full_radius());
      }
      if (n == 0) {
        n = cfg_.max_substeps;
        flags |= kHealthSubstepsClipped;
      }
      h = Rk4Step<T>(cfg_.tick / static_cast<T>(n));
    }
    // One RK4 call site: one copy of the RK4 stages in the image (firmware flash).
    [[maybe_unused]] const CompensatedState<State> start = s_;  // kStageCheck's restart point
    for (int i = 0;;) {
      [[maybe_unused]] const int need = checked_substep(h, k1, n);
      if constexpr (kStageCheck) {
        if (need != 0) {
          // A stage argument needs more substeps than n (a valve that opens within the
          // substep): its result may be a false fixed point of the RK4 map, stable and
          // wrong (a line held a few bar below a relief's cracking pressure). The tick again
          // from its start, in at least twice as many substeps.
          const int cap = static_cast<int>(cfg_.max_substeps);
          n = need < 0 ? cap : std::min(std::max(need, 2 * n), cap);
          if (need < 0) flags |= kHealthSubstepsClipped;
          k1 = restart_tick(start, rho, alg_ok);
          if (takes_implicit(n) && implicit_step(k1, flags)) return finish_implicit(x_before, flags);
          h = Rk4Step<T>(cfg_.tick / static_cast<T>(n));
          i = 0;
          continue;
        }
      }
      if (++i >= n) break;
      // Later substeps' k1 (stiff ticks only) from the same out-of-line evaluation as the
      // first, rather than a further inlined copy of derivative().
      Output y_sub;
      k1 = model_.tick_derivative(s_.x, rho_one_, y_sub, rho, alg_ok);
    }
    substeps_ = static_cast<std::uint16_t>(n);

    // state_plausible is false for non-finite states too: one test in the usual case.
    if (!model_.state_plausible(s_.x)) flags |= check_state(x_before);
    return finish(flags);
  }

  /// The tick's first model evaluation: k1 = f(s_.x), yhat_, rho and alg_ok; where the
  /// model takes a stiff cut, radius bounds above stiff_cut() (a tick implicit whatever the
  /// radius) are not refined (dense.hpp radius_bound).
  HSTMON_TICK_PART State first_derivative(T& rho, bool& alg_ok) noexcept {
    if constexpr (kStiffCut) {
      return model_.tick_derivative(s_.x, rho_one_, yhat_, rho, alg_ok, stiff_cut());
    } else {
      return model_.tick_derivative(s_.x, rho_one_, yhat_, rho, alg_ok);
    }
  }

  /// A radius bound above this needs no refining: the tick is implicit (first_derivative)
  /// [1/s]: one substep's radius above that at which takes_implicit holds (a margin of
  /// 1/implicit_above over the rounding of substep_count and of the bound's
  /// iterations, a few ε); +∞ where ticks are never implicit.
  /// Computed per tick rather than stored (the observer's size is the C API's storage).
  T stiff_cut() const noexcept {
    if constexpr (kImplicit) {
      return cfg_.implicit_above > 0 ? (static_cast<T>(cfg_.implicit_above) + T(1)) * rho_one_
                                     : std::numeric_limits<T>::infinity();
    } else {
      return std::numeric_limits<T>::infinity();
    }
  }

  /// The full radius bound at s_.x (the rare explicit tick after a refused implicit one).
  HSTMON_COLD T full_radius() noexcept {
    Output y;
    T rho;
    bool ok;
    (void)model_.tick_derivative(s_.x, rho_one_, y, rho, ok);
    return rho;
  }

  /// One RK4 substep from s_.x with k1 = f(s_.x), rk4_step's arithmetic, that first checks
  /// its stage arguments x₂, x₃, x₄ where the model's stiffness changed along them (kStageCheck).
  /// The test that runs on every substep is cheap: Shampine's stiffness estimate, h times
  /// the larger secant ‖k₃ − k₂‖/‖x₃ − x₂‖, ‖k₄ − k₃‖/‖x₄ − x₃‖ in the max-norm weighted by
  /// 1/envelope (the displacements from the stages, not from rounded arguments; a pair
  /// closer than kStageFloor counts 0, its secant being rounding). Where that exceeds
  /// kStageMargin·lambda_h_max, the model's own radius at each stage argument decides
  /// (stage_need): a secant in a norm may overstate the radius of a well-resolved
  /// oscillation, which then costs three evaluations and changes nothing.
  /// @param n  the substeps this tick is taken in (≥ 1; at max_substeps no check)
  /// @return 0 with s_ advanced; else s_ untouched and the substeps a stage argument needs
  ///         (> n), or −1 beyond max_substeps
  HSTMON_TICK_PART int checked_substep(const Rk4Step<T>& h, const State& k1, int n) noexcept {
    if constexpr (kStageCheck) {
      const State& x = s_.x;
      const State k2 = model_.derivative(x + h.half * k1);
      const State k3 = model_.derivative(x + h.half * k2);
      const State k4 = model_.derivative(x + h.h * k3);
      const auto& w = this->stage_weight.array();
      const T dx23 = (w * (h.half * (k2 - k1)).array().abs()).maxCoeff();
      const T dx34 = (w * (h.h * k3 - h.half * k2).array().abs()).maxCoeff();
      const T limit = stage_limit();
      const bool steep23 = dx23 > kStageFloor && h.h * (w * (k3 - k2).array().abs()).maxCoeff() > limit * dx23;
      const bool steep34 = dx34 > kStageFloor && h.h * (w * (k4 - k3).array().abs()).maxCoeff() > limit * dx34;
      if ((steep23 || steep34) && n < static_cast<int>(cfg_.max_substeps)) {
        const int need = stage_need(x, h, k1, k2, k3, n);
        if (need != 0) return need;
      }
      s_.add(h.sixth * (k1 + T(2) * (k2 + k3) + k4));
      return 0;
    } else {
      rk4_step(model_, s_, h, k1);
      static_cast<void>(n);
      return 0;
    }
  }

  /// The substeps per tick that the stage arguments x + (h/2)·k1, x + (h/2)·k2 and
  /// x + h·k3 need by the model's largest radius ρ there: 0 if n substeps keep
  /// ρ·h/n ≤ kStageMargin·lambda_h_max, else ⌈ρ·h/lambda_h_max⌉, −1 beyond max_substeps.
  HSTMON_COLD int stage_need(const State& x, const Rk4Step<T>& h, const State& k1, const State& k2, const State& k3,
                             int n) noexcept {
    T rho_max = T(0);
    for (const State& a : {State(x + h.half * k1), State(x + h.half * k2), State(x + h.h * k3)}) {
      Output y;
      T rho;
      bool ok;
      (void)model_.tick_derivative(a, rho_one_, y, rho, ok);
      if (!(rho <= rho_max)) rho_max = rho;  // NaN too: a stage off the model needs the cap
    }
    if (!(rho_max == rho_max)) return -1;
    if (rho_max == T(0)) return 0;
    if (rho_max * cfg_.tick <= stage_limit() * static_cast<T>(n)) return 0;
    const int need = substep_count(rho_max);
    return need == 0 ? -1 : need;
  }

  /// Largest |λ|·h_sub a stage argument may show in a substep before the tick is taken
  /// again [-]: kStageMargin·lambda_h_max, and at most 2.5, inside RK4's real stability
  /// limit of 2.79.
  T stage_limit() const noexcept {
    const T m = kStageMargin * cfg_.lambda_h_max;
    return m < T(2.5) ? m : T(2.5);
  }

  /// Back to the tick's start (the stage check's retry): s_ = start, and f there with its
  /// radius and algebraic check. Out of line: rare, and one more inlined copy of the model.
  HSTMON_COLD State restart_tick(const CompensatedState<State>& start, T& rho, bool& alg_ok) noexcept {
    s_ = start;
    Output y;
    return model_.tick_derivative(s_.x, rho_one_, y, rho, alg_ok);
  }

  /// r_ = m.y − ŷ and r_valid_ on the channels marked valid and finite; r = 0 elsewhere.
  /// @return kHealthMeasNonFinite if a channel marked valid was not finite, else 0
  HSTMON_TICK_PART std::uint32_t take_residuals(const Measurement& m) noexcept {
    const unsigned wanted = m.valid & kAllChannels;
    unsigned used = wanted;
    std::uint32_t flags = 0;
    Output r;
    if (wanted == kAllChannels && all_finite(m.y)) {
      r = m.y - yhat_;  // the usual tick: every channel, no per-channel branches
    } else {
      // Locals, not members, inside the loop: r_valid_ is a char type and may alias
      // anything, so updating it per channel would force reloads of m and yhat_.
      used = 0;
      for (int i = 0; i < kOutputs; ++i) {
        const bool use = (((wanted >> i) & 1u) != 0) & std::isfinite(m.y[i]);
        r[i] = use ? m.y[i] - yhat_[i] : T(0);
        used |= static_cast<unsigned>(use) << i;
      }
      if (used != wanted) flags |= kHealthMeasNonFinite;
    }
    r_ = r;
    r_valid_ = static_cast<std::uint8_t>(used);
    return flags;
  }

  /// For a tick that ended on a state that is not plausible: back to x_before (finite)
  /// if the state is not finite.
  /// @return kHealthStateNonFinite and/or kHealthStateOutOfBounds
  std::uint32_t check_state(const State& x_before) noexcept {
    std::uint32_t flags = 0;
    if (!all_finite(s_.x)) {
      flags |= kHealthStateNonFinite;
      s_.reset(x_before);
    }
    if (!model_.state_plausible(s_.x)) flags |= kHealthStateOutOfBounds;
    return flags;
  }

  /// True when a tick that needs n RK4 substeps (0: beyond max_substeps) is taken
  /// linearly implicit instead.
  bool takes_implicit(int n) const noexcept {
    if constexpr (kImplicit) {
      return cfg_.implicit_above > 0 && (n == 0 || n > static_cast<int>(cfg_.implicit_above));
    } else {
      static_cast<void>(n);
      return false;
    }
  }

  /// The tick from s_.x by error-controlled Rosenbrock steps (rosenbrock_tick), with
  /// f(s_.x) = k1; adds kHealthSubstepsClipped to flags where the finest step missed the
  /// tolerance.
  /// @return false (state untouched) if the tick could not be taken that way
  bool implicit_step(const State& k1, std::uint32_t& flags) noexcept {
    if constexpr (kImplicit) {
      const int used = used_states(model_);
      const RosenbrockTick r = rosenbrock_tick(model_, s_, cfg_.tick, k1, this->implicit_peak, cfg_.implicit_rtol,
                                               static_cast<int>(cfg_.implicit_max_level), this->implicit_level, used);
      if (!r.ok) return false;
      if (r.clipped) flags |= kHealthSubstepsClipped;
      substeps_ = static_cast<std::uint16_t>(r.steps);
      this->implicit_peak = this->implicit_peak.cwiseMax(s_.x.cwiseAbs());
      this->implicit_last = true;
      ++this->implicit_count;
      return true;
    } else {
      static_cast<void>(k1);
      static_cast<void>(flags);
      return false;
    }
  }

  /// Ends a linearly implicit tick: the state check.
  std::uint32_t finish_implicit(const State& x_before, std::uint32_t flags) noexcept {
    if (!model_.state_plausible(s_.x)) flags |= check_state(x_before);
    return finish(flags);
  }

  /// Substeps for spectral radius rho [1/s] > 0: ⌈ρ·h/λh_max⌉, or 0 beyond max_substeps.
  int substep_count(T rho) const noexcept {
    const T want = rho * cfg_.tick / cfg_.lambda_h_max;
    return want <= static_cast<T>(cfg_.max_substeps) ? static_cast<int>(std::ceil(want)) : 0;
  }

  /// Ends a usual tick whose state update is done (x_before: the state before it): the
  /// residuals against yhat_, n substeps, the state check with c's bounds.
  template <typename C>
  std::uint32_t finish_usual(const Measurement& m, const State& x_before, int n, const C& c) noexcept {
    std::uint32_t flags = take_residuals(m);
    substeps_ = static_cast<std::uint16_t>(n);
    if constexpr (kImplicit) this->implicit_last = false;
    ++usual_.ticks;
    if (!Model::usual_plausible(c, s_.x)) flags |= check_state(x_before);
    return finish(flags);
  }

  /// Ends a tick with its HealthFlags.
  std::uint32_t finish(std::uint32_t flags) noexcept {
    ++ticks_;
    last_health_ = flags;
    health_ |= flags;
    return flags;
  }

  static bool config_ok(const Config& cfg) noexcept {
    return std::isfinite(cfg.tick) && cfg.tick > T(0) && std::isfinite(cfg.lambda_h_max) && cfg.lambda_h_max > T(0) &&
           cfg.lambda_h_max <= T(2.5) && cfg.max_substeps >= 1 && cfg.gain.allFinite() && implicit_config_ok(cfg);
  }

  /// Brings what depends on the model's inputs up to date: the usual tick's coefficients —
  /// at once where they are a few operations (a region that does not move), else once the
  /// inputs have held for a tick (a centred region's certificate: refresh_usual, from
  /// step), so that inputs logged with noise, different every tick, never pay for it.
  void inputs_changed() noexcept {
    if constexpr (kUsualTick) {
      usual_.n = 0;
      if constexpr (observer_detail::UsualTickCentred<Model>::value) {
        usual_.stale = true;
      } else {
        refresh_usual();
      }
    }
  }

  /// The usual tick's coefficients for one step of the tick, at the current state.
  HSTMON_OFF_USUAL_PATH void refresh_usual() noexcept {
    if constexpr (kUsualTick) {
      usual_.c = usual_coeffs(cfg_.tick, rho_one_);
      usual_.stale = false;
    }
  }

  /// Model::usual_tick_coeffs for a step of h [s] and spectral radius bound rho_max [1/s],
  /// centred on the current state where the model's region is.
  /// (A template: only observers with a usual tick ask it of their model.)
  template <typename M = Model>
  typename M::UsualTick usual_coeffs(T h, T rho_max) const noexcept {
    if constexpr (observer_detail::UsualTickCentred<M>::value) {
      return model_.usual_tick_coeffs(h, rho_max, s_.x);
    } else {
      return model_.usual_tick_coeffs(h, rho_max);
    }
  }

  static bool implicit_config_ok(const Config& cfg) noexcept {
    if constexpr (kImplicit) {
      return std::isfinite(cfg.implicit_rtol) && cfg.implicit_rtol > T(0) && cfg.implicit_max_level <= 15;
    } else {
      static_cast<void>(cfg);
      return true;
    }
  }

  /// Takes a valid configuration and resets to the model's rest state.
  void apply(const Config& cfg) noexcept {
    cfg_ = cfg;
    one_step_ = Rk4Step<T>(cfg.tick);
    rho_one_ = cfg.lambda_h_max / cfg.tick;
    has_gain_ = !cfg.gain.isZero(T(0));
    if constexpr (kStageCheck) {
      const State env = model_.state_envelope();
      for (int i = 0; i < kStates; ++i) this->stage_weight[i] = env[i] > T(0) ? T(1) / env[i] : T(0);
    }
    if constexpr (kUsualTick) usual_.on = !has_gain_;
    inputs_changed();
    reset(model_.rest_state());
  }

  /// True when a and b hold the same bytes (compared a machine word at a time, 64 or 32
  /// bits; a padded type may compare unequal, which only costs a redundant update).
  /// Unrolled at compile time on 32-bit targets, where a loop costs the Cortex-M4 twice the
  /// instructions; a loop on 64-bit ones, which GCC vectorises.
  template <typename S>
  static bool same_bytes(const S& a, const S& b) noexcept {
    using Word = std::conditional_t<sizeof(void*) >= 8 && sizeof(S) % 8 == 0, std::uint64_t, std::uint32_t>;
    static_assert(sizeof(S) % sizeof(Word) == 0, "compared in whole words");
    const auto* pa = reinterpret_cast<const unsigned char*>(&a);
    const auto* pb = reinterpret_cast<const unsigned char*>(&b);
    if constexpr (sizeof(void*) < 8) {
      return word_diff<Word>(pa, pb, std::make_index_sequence<sizeof(S) / sizeof(Word)>{}) == 0;
    } else {
      Word diff = 0;
      for (std::size_t i = 0; i < sizeof(S); i += sizeof(Word)) {
        Word wa, wb;
        std::memcpy(&wa, pa + i, sizeof wa);
        std::memcpy(&wb, pb + i, sizeof wb);
        diff |= wa ^ wb;
      }
      return diff == 0;
    }
  }

  /// OR of the XORs of the words at pa and pb, word i for each i in I.
  template <typename Word, std::size_t... I>
  static Word word_diff(const unsigned char* pa, const unsigned char* pb, std::index_sequence<I...>) noexcept {
    const auto word = [](const unsigned char* p, std::size_t i) noexcept {
      Word w;
      std::memcpy(&w, p + i * sizeof(Word), sizeof w);
      return w;
    };
    return (Word(0) | ... | (word(pa, I) ^ word(pb, I)));
  }

  /// True when every element of v is finite, in one reduction: v·0 is ±0 for finite
  /// elements and NaN for ±Inf/NaN ones (IEEE; hence never -ffast-math).
  template <typename V>
  static bool all_finite(const V& v) noexcept {
    return (v * T(0)).sum() == T(0);
  }

  Model model_{};
  Config cfg_{};
  /// Ticks between two re-centrings of a centred usual-tick region (usual_substeps).
  static constexpr std::uint64_t kRecentreTicks = 8;
  static constexpr unsigned kAllChannels = (1u << kOutputs) - 1u;
  T rho_one_ = T(0.8) / T(1e-3);            ///< largest ρ that one substep covers [1/s]
  Rk4Step<T> one_step_{T(1e-3)};            ///< RK4 factors of one substep per tick
  CompensatedState<State> s_{};
  Output yhat_ = Output::Zero();
  Output r_ = Output::Zero();
  std::uint64_t ticks_ = 0;
  std::uint32_t health_ = 0;
  std::uint32_t last_health_ = 0;
  /// A tick is taken again when a stage argument's stiffness gives |λ|·h_sub above this many
  /// times lambda_h_max [-] (stage_limit): twice, so that the usual growth of ρ within a
  /// substep sized at its start does not trigger it.
  static constexpr T kStageMargin = T(2);
  /// Least stage displacement, as a fraction of the state's envelope, for a stage secant to
  /// count (checked_substep) [-]: float rounding of f is below 1e-3 of it there.
  static constexpr T kStageFloor = T(1e-5);
  /// Least error scale of a state, as a fraction of its envelope (model's state_envelope) [-].
  static constexpr T kImplicitFloor = T(1e-2);
  std::uint16_t substeps_ = 0;
  std::uint8_t r_valid_ = 0;
  bool has_gain_ = false;
  observer_detail::UsualTickState<Model, UsualTick> usual_{};
};

}  // namespace hstmon

#undef HSTMON_OFF_USUAL_PATH
#undef HSTMON_TICK_PART
