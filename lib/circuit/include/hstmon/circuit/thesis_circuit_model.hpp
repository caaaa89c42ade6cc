#pragma once
/// @file thesis_circuit_model.hpp
/// The thesis rig's model on the engine: examples/circuits/thesis.json compiled
/// (generated/thesis_circuit_compiled.hpp, circuit::CompiledModel) behind the rig's own
/// vocabulary — ThesisParams (Table 2.2), ThesisInputs, channels (Pmi, Pmo, Ppp, ωm) —
/// so what was written against that vocabulary runs on the one engine unchanged. The
/// thesis rig's monitor (monitor.hpp), its parameter files, fault table, fit and reference
/// scenarios instantiate it; replay and the gap's fits do on request (thesis_impl.hpp).
/// The hand-written ThesisReducedModel (thesis_reduced.hpp) is a specialisation of the
/// same equations that tests/circuit/test_thesis_circuit.cpp proves equal to it.
///
/// The parameter and input orders are thesis.json's, which is ThesisParams' and
/// ThesisInputs' (checked by test_thesis_circuit_model against the generated names); the
/// circuit's remaining parameters (drain at 0, the DCV spool fully open, the envelope)
/// are thesis.params.json's values, fixed at generation.
///
/// No heap, no exceptions. The static steady-state functions build a model on the stack
/// (≈ 0.7 KB in float, 1.3 KB in double; the model bound calls them): fine on hosts, over a
/// 512-byte firmware stack, which is one reason the firmware C API instantiates the
/// hand-written specialisation (docs/circuits.md, "The thesis rig on the engine").

#include "hstmon/fault_signature.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"
#include "hstmon/model_bound.hpp"
#include "hstmon/residual_bounds.hpp"
#include "hstmon/status.hpp"
#include "hstmon/thesis_params.hpp"

namespace hstmon {

/// The thesis rig as the Observer's model, through the engine (see the file comment).
template <typename T>
class ThesisCircuitModel {
 public:
  /// The compiled circuit inside.
  using Compiled = generated::thesis_circuit::CompiledModel<T>;
  using Scalar = T;
  using State = typename Compiled::State;    ///< (Ppp [Pa], ωm [rad/s])
  using Output = typename Compiled::Output;  ///< (Pmi, Pmo, Ppp [Pa], ωm [rad/s])
  using Params = ThesisParams<T>;
  using Inputs = ThesisInputs<T>;
  using UsualTick = typename Compiled::UsualTick;
  static constexpr int kStates = Compiled::kStates;
  static constexpr int kOutputs = Compiled::kOutputs;
  static constexpr bool kHasUsualTick = Compiled::kHasUsualTick;
  static_assert(kStates == 2 && kOutputs == kFdiChannels, "thesis.json: states (Ppp, ωm), channels (Pmi, Pmo, Ppp, ωm)");

  /// Table 2.2 at the default inputs.
  ThesisCircuitModel() noexcept { set_params(Params{}); }
  explicit ThesisCircuitModel(const Params& p, const Inputs& u = Inputs{}) noexcept : u_(u) { set_params(p); }

  /// The engine's parameter vector for p: ThesisParams in thesis.json's order, then the
  /// circuit's fixed values (thesis.params.json).
  static typename Compiled::Params engine_params(const Params& p) noexcept {
    typename Compiled::Params e;
    for (int k = 0; k < Compiled::Cap::kParams; ++k) e.v[k] = T(generated::thesis_circuit::kParams[k]);
    const T v[] = {p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf, p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
    for (int k = 0; k < kThesisParams; ++k) e.v[k] = v[k];
    return e;
  }
  /// The engine's input vector for u (thesis.json's order: Psupl, Ps, Pbp, kp).
  static typename Compiled::Inputs engine_inputs(const Inputs& u) noexcept {
    typename Compiled::Inputs e;
    e.v[0] = u.Psupl;
    e.v[1] = u.Ps;
    e.v[2] = u.Pbp;
    e.v[3] = u.kp;
    return e;
  }
  /// How many of the circuit's parameters are ThesisParams' (the rest are fixed).
  static constexpr int kThesisParams = 11;

  /// thesis_params_valid(p): values the engine resolves (capacitance, inertia, transitions
  /// and resistances > 0; test_circuit_thesis_model samples it), so no model is built to check.
  static bool params_valid(const Params& p) noexcept { return thesis_params_valid(p); }
  /// True when the inputs are finite and kp (an orifice coefficient) is not negative.
  static bool inputs_valid(const Inputs& u) noexcept { return thesis_inputs_valid(u); }
  /// True when the circuit's values resolved for the parameters (settle_time() asks).
  bool valid() const noexcept { return m_.valid(); }

  /// Replaces the parameters (and re-resolves the circuit's values). O(elements).
  void set_params(const Params& p) noexcept {
    p_ = p;
    m_.set_params(engine_params(p));
    m_.set_inputs(engine_inputs(u_));
  }
  /// Sets the inputs held over the next evaluations. O(elements).
  void set_inputs(const Inputs& u) noexcept {
    u_ = u;
    m_.set_inputs(engine_inputs(u));
  }
  const Params& params() const noexcept { return p_; }
  const Inputs& inputs() const noexcept { return u_; }
  /// The compiled circuit (its engine, envelope, warm start).
  const Compiled& compiled() const noexcept { return m_; }

  /// Time derivative (dPpp/dt [Pa/s], dωm/dt [rad/s²]) and, if y is given, the outputs.
  State derivative(const State& x, Output* y = nullptr) const noexcept { return m_.derivative(x, y); }
  /// The Observer's per-tick derivative (model_concept.hpp).
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok) const noexcept {
    return m_.tick_derivative(x, rho_max, y, rho, alg_ok);
  }
  /// Outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) at x.
  Output outputs(const State& x) const noexcept { return m_.outputs(x); }
  /// Spectral radius of ∂f/∂x at x [1/s] (exact for the two states).
  T spectral_radius(const State& x) const noexcept { return m_.spectral_radius(x); }
  /// Slowest decay rate of the linearised model at x [1/s]; 0 if some mode does not decay.
  T slowest_rate(const State& x) const noexcept { return m_.engine().slowest_rate(x); }
  /// Quasi-steady DCV pressures (Pmi, Pmo [Pa]) at shaft speed w_m [rad/s].
  void dcv_pressures(T w_m, T& Pmi, T& Pmo) const noexcept {
    const Output y = m_.outputs(State(u_.Pbp, w_m));
    Pmi = y[kChPmi];
    Pmo = y[kChPmo];
  }

  /// Output channel that measures state i (Ppp → kChPpp, ωm → kChWm).
  int state_channel(int i) const noexcept { return m_.state_channel(i); }
  /// True for a finite state within twice the circuit's envelope.
  bool state_plausible(const State& x) const noexcept { return m_.state_plausible(x); }
  /// At rest: ωm = 0, Ppp = Pbp.
  State rest_state() const noexcept { return m_.rest_state(); }
  /// Steady state under the current inputs (the engine's solve on the full circuit; with
  /// the PRV shut, kp = 0, the stall ωm = 0).
  /// @return false (x untouched) if the solve finds none
  bool steady_state(State& x) const noexcept { return m_.steady_state(x); }

  /// steady_state() for parameters p and inputs u (a model on the stack).
  static bool steady_state(const Params& p, const Inputs& u, State& x) noexcept {
    const Compiled m(engine_params(p), engine_inputs(u));
    return m.valid() && m.steady_state(x);
  }
  /// Outputs at the steady state for p and u.
  /// @param y  out: (Pmi, Pmo, Ppp [Pa], ωm [rad/s]); untouched on failure
  static bool steady_outputs(const Params& p, const Inputs& u, T (&y)[kFdiChannels]) noexcept {
    const Compiled m(engine_params(p), engine_inputs(u));
    State x;
    if (!m.valid() || !m.steady_state(x)) return false;
    const Output o = m.outputs(x);
    for (int i = 0; i < kOutputs; ++i) y[i] = o[i];
    return true;
  }

  // The usual tick on hosts, forwarded (CompiledModel documents each).
  /// Coefficients of one RK4 step of h [s] in a certified box centred on x [Pa, rad/s].
  UsualTick usual_tick_coeffs(T h, T rho_max, const State& x) const noexcept { return m_.usual_tick_coeffs(h, rho_max, x); }
  /// One fused RK4 step inside c's box: outputs y at x, increment dx; false outside it.
  bool usual_tick(const UsualTick& c, const State& x, Output& y, State& dx) const noexcept {
    return m_.usual_tick(c, x, y, dx);
  }
  /// tick_derivative's rho at x [1/s], the warm start left as it was.
  T tick_radius(const State& x, T rho_max) const noexcept { return m_.tick_radius(x, rho_max); }
  /// state_plausible(x) with c's bounds.
  static bool usual_plausible(const UsualTick& c, const State& x) noexcept { return Compiled::usual_plausible(c, x); }

 private:
  Params p_{};
  Inputs u_{};
  Compiled m_{};
};

/// The thesis rig's model bound on the engine: residual_bounds.hpp's rule (ThesisUncertainty,
/// one steady-state solve per side and perturbed quantity) with the engine's steady states.
template <typename T>
struct ModelBound<ThesisCircuitModel<T>> : ThesisModelBound<ThesisCircuitModel<T>> {};

}  // namespace hstmon
