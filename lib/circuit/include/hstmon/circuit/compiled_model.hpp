#pragma once
/// @file compiled_model.hpp
/// A circuit compiled at build time as the Observer's model: the hot path (quasi-steady
/// solve, rates, outputs, reduced Jacobian) is straight-line code generated for one
/// circuit's topology (`hstmon-circuit-header --compiled`, the Kernel), calling the same
/// law functions (laws.hpp) and the same solve and reduction (quasi_steady.hpp) as the
/// interpreting CircuitModel, summing in its order — so the results are the interpreter's
/// bit for bit but for the sign of a sum that is zero (a generated sum starts from its first
/// term, not from +0) — without its per-element kind switches, index loads and Ref lookups
/// (docs/circuits.md, "Compiled circuits"). Everything off the hot path (resolving the
/// values on set_params and set_inputs, rest and steady state, channels) is the
/// interpreter's, held inside: one place for the physics.
///
/// No heap, no exceptions, no RTTI. The warm start of the quasi-steady solve is state, so a
/// model must not be evaluated from two threads at once.
///
/// A Kernel (generated) provides: Cap; description() (the constexpr Circuit<Cap>); kZ
/// (nodes + shafts), kN (states), kM (stiff nodes), kU (unknowns); kStateU[kN], kStiffU[kM]
/// (rows of the unknowns' Jacobian) and kStateZ[kN], kStiffZ[kM] (full-vector entries); and,
/// templated on the engine type M, fill(m, x, z) (the states only: fixed entries are read
/// as m.fixed_value, stiff ones written by the solve), solve_stiff<kRow>(m, z, guess, G
/// [, fold]) → converged, rates<kRow>(m, z, d, G), outputs(m, z, y), unknowns_jacobian(m,
/// z, G) (nonzeros only, onto a zeroed G), schur(G, inv_mass, jr, q) (quasi_steady.hpp
/// schur_reduce, unrolled for G's structure), and kFolded with fold(m, v) (the solve's
/// input-constant subexpressions). With kRow, the solve and the rates also write the rows
/// of G from the law values they evaluate anyway, so the observer's stiffness
/// (tick_derivative's rho) costs the reduction, not a second pass over the laws.
///
/// On hosts it also has a fused usual tick (usual_tick_coeffs, usual_tick): a box of the
/// unknowns proved once to need one substep (stiffness_certificate.hpp), the four RK4
/// stages in one function with the folded constants — the general tick's arithmetic, so
/// its results bit for bit (docs/circuits.md, "The usual tick on hosts").

#include <limits>

#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/circuit/dense.hpp"
#include "hstmon/circuit/quasi_steady.hpp"
#include "hstmon/code_size.hpp"
#include "hstmon/rk4.hpp"

namespace hstmon::circuit {

template <typename T, class Kernel>
class CompiledModel {
 public:
  using Cap = typename Kernel::Cap;
  /// The interpreter this model holds for everything off the hot path.
  using Engine = CircuitModel<T, Cap>;
  using Scalar = T;
  using Description = Circuit<Cap>;
  using Params = typename Engine::Params;            ///< parameter values by index [SI]
  using Inputs = typename Engine::Inputs;            ///< input values by index [SI]
  using State = typename Engine::State;              ///< the states: node pressures [Pa], shaft speeds [rad/s]
  using Output = typename Engine::Output;            ///< the sensor channels [Pa, rad/s or m³/s]
  using StateMatrix = typename Engine::StateMatrix;  ///< ∂f/∂x [1/s in the state units]
  static constexpr int kStates = Engine::kStates;
  /// The states in use, known at compile time: the kernel's (State is padded to kStates).
  static constexpr int kUsedStates = Kernel::kN;
  static constexpr int kOutputs = Engine::kOutputs;
  /// True when the circuit has valves or a compensator (has_pressure_thresholds): the
  /// observer checks each RK4 substep's stages for a valve opening within it (model_concept.hpp).
  static constexpr bool kPressureThresholds = has_pressure_thresholds(Kernel::description());
  static_assert(Kernel::kN >= 1 && Kernel::kN <= kStates, "the kernel's states fit the capacity");
  static_assert(Kernel::kZ == Cap::kNodes + Cap::kShafts, "the kernel's full vector is the capacity's");

 private:
  /// Room for the stiff nodes' warm start (at least one entry).
  static constexpr int kGuesses = Kernel::kM > 0 ? Kernel::kM : 1;

 public:
  /// Unbound (no states, no outputs) until bind(), set_params() or the constructor below.
  CompiledModel() noexcept = default;

  /// Bound to the kernel's circuit, with values p and inputs u.
  explicit CompiledModel(const Params& p, const Inputs& u = Inputs{}) noexcept : engine_(Kernel::description(), p, u) {
    sync();
  }

  /// Binds the kernel's own circuit (the Observer's configure(d, p, cfg) calls it).
  /// @param d  must be Kernel::description(): the code was generated for that circuit
  /// @return kOk, the description's structural error, or kUnbound for another description
  CircuitError bind(const Description& d) noexcept {
    if (&d != &Kernel::description()) return CircuitError::kUnbound;
    const CircuitError e = engine_.bind(d);
    sync();
    return e;
  }

  static bool params_valid(const Params& p) noexcept { return Engine::params_valid(p); }
  static bool inputs_valid(const Inputs& u) noexcept { return Engine::inputs_valid(u); }

  /// Replaces the parameter values (CircuitModel::set_params), binding the kernel's circuit
  /// first if unbound (so Observer::configure(p, cfg) works too). O(elements).
  void set_params(const Params& p) noexcept {
    if (engine_.description() == nullptr) (void)engine_.bind(Kernel::description());
    engine_.set_params(p);
    sync();
  }
  /// Sets the inputs held over the next evaluations (CircuitModel::set_inputs); the
  /// quasi-steady solve restarts from the rest state. O(elements).
  void set_inputs(const Inputs& u) noexcept {
    engine_.set_inputs(u);
    sync();
  }

  const Params& params() const noexcept { return engine_.params(); }
  const Inputs& inputs() const noexcept { return engine_.inputs(); }
  /// The interpreter inside (resolved coefficients, envelope, bounds).
  const Engine& engine() const noexcept { return engine_; }
  /// The interpreter inside, writable: only for a caller that changes its values and puts
  /// them back bit for bit before the next evaluation (the in-place model bound,
  /// compiled_bound.hpp); anything else goes through set_params and set_inputs.
  Engine& borrow_engine() noexcept { return engine_; }
  bool valid() const noexcept { return engine_.valid(); }
  int n_states() const noexcept { return engine_.n_states(); }
  int n_stiff() const noexcept { return engine_.n_stiff(); }
  int n_outputs() const noexcept { return engine_.n_outputs(); }
  int state_channel(int s) const noexcept { return engine_.state_channel(s); }
  /// CircuitModel::state_envelope [Pa, rad/s].
  State state_envelope() const noexcept {
    State e = State::Zero();
    for (int s = 0; s < Kernel::kN; ++s) {
      e[s] = Kernel::kStateZ[s] < Cap::kNodes ? engine_.pressure_envelope() : engine_.speed_envelope();
    }
    return e;
  }

  /// CircuitModel::state_plausible with the kernel's states known at compile time (the
  /// observer asks every tick): each state within twice its envelope (false for NaN and
  /// ±Inf), any capacity beyond the kernel's states finite.
  bool state_plausible(const State& x) const noexcept {
    for (int s = 0; s < Kernel::kN; ++s) {
      const T lim = Kernel::kStateZ[s] < Cap::kNodes ? engine_.pressure_envelope() : engine_.speed_envelope();
      if (!(std::fabs(x[s]) <= T(2) * lim)) return false;
    }
    for (int s = Kernel::kN; s < kStates; ++s) {
      if (!(x[s] * T(0) == T(0))) return false;
    }
    return true;
  }
  State rest_state() const noexcept { return engine_.rest_state(); }
  /// CircuitModel::slowest_rate [1/s] (off the hot path: the monitor's start-up and bound).
  T slowest_rate(const State& x) const noexcept { return engine_.slowest_rate(x); }

  /// CircuitModel::steady_state; the quasi-steady solve then starts from it.
  bool steady_state(State& x) const noexcept {
    if (!engine_.steady_state(x)) return false;
    for (int j = 0; j < Kernel::kM; ++j) guess_[j] = engine_.warm_start(j);
    return true;
  }

  /// Time derivative of the states [Pa/s, rad/s²] and, if y is given, the outputs.
  State derivative(const State& x, Output* y = nullptr) const noexcept {
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    (void)solve(z);
    if (y != nullptr) *y = outputs_at(z);
    return rates(z);
  }

  /// CircuitModel::tick_derivative, compiled: rho from the reduced Jacobian's bound
  /// (dense.hpp radius_bound_fixed, radius_bound's bits: its first, cheapest bound decides
  /// when it is ≤ rho_max).
  /// The Jacobian's rows come from the evaluations the solve and the rates make anyway:
  /// a closed-form stiff node's row from its own root (the orifice's slope c0/(2·root)),
  /// a Newton node's from its balance's last evaluation, at most 8ε (Newton's step test)
  /// and 16ε (the sweep's) relative from z — the interpreter's unknowns_jacobian at z to
  /// rounding, which is all a substep count needs.
  /// rho_stiff: radius_bound's (the observer's: above it a tick is implicit anyway).
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok,
                        T rho_stiff = std::numeric_limits<T>::infinity()) const noexcept {
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    T G[kExtent<Kernel::kU>][kExtent<Kernel::kU>];  // every row captured; schur assigns its fill-ins
    bool conv = true;
    if constexpr (Kernel::kM > 0) conv = Kernel::template solve_stiff<true>(engine_, z, guess_, G);
    y = outputs_at(z);
    State d = State::Zero();
    Kernel::template rates<true>(engine_, z, d, G);
    T jr[kExtent<kStates>][kExtent<kStates>];
    T q = T(0);
    Kernel::schur(G, inv_mass_, jr, q);
    rho = radius_bound_fixed<Kernel::kN>(jr, rho_max, rho_stiff);
    alg_ok = conv && q < T(0.5);
    return d;
  }

  /// True where this build has the fused usual tick (usual_tick): HSTMON_USUAL_TICK,
  /// everywhere but Arm M-profile by default, where flash is scarce and the observer's
  /// general tick serves (code_size.hpp).
  static constexpr bool kHasUsualTick = HSTMON_USUAL_TICK != 0;

  /// What usual_tick needs for one RK4 step of h: the step's factors and a box of the
  /// unknowns certified around a state (stiffness_certificate.hpp) — everywhere in it the
  /// general tick takes one substep and finds the quasi-steady solve contracting.
  struct UsualTick {
    Rk4Step<T> step{};                           ///< h, h/2, h/6 [s], as the general tick's
    T x_lo[kExtent<Kernel::kN>]{};               ///< the box on the states [Pa, rad/s]
    T x_hi[kExtent<Kernel::kN>]{};
    T a_lo[kExtent<kGuesses>]{};                 ///< the box on the stiff nodes' pressures [Pa]
    T a_hi[kExtent<kGuesses>]{};
    T lim[kExtent<Kernel::kN>]{};                ///< state_plausible's |x_s| ≤ lim_s [Pa, rad/s]
    Folded<T, Kernel::kFolded> fold{};           ///< the solves' input-constant values (Kernel::fold)
    bool certified = false;                      ///< false: no box (usual_tick declines)
  };

  /// usual_tick's coefficients for one RK4 step of h under the current inputs, the box
  /// centred on x: the states and the stiff pressures solved at x, ± α of the envelope
  /// (pressure or speed), for the largest α in 1/8, 1/32, …, 1/2048 that certify_box
  /// proves. Uncertified where none does (a stiff point: start from rest, a shut valve)
  /// or the solve fails at x. O(5·(elements + unknowns³)); the observer asks once the
  /// inputs have held for a tick, and again when the state has left the box.
  /// @param h        RK4 step [s], > 0
  /// @param rho_max  the spectral radius one step covers, λh_max/h [1/s]; +∞: the solve's
  ///                 contraction only (the observer's substeps, whose count it chose)
  /// @param x        the state to centre the box on [Pa, rad/s]
  UsualTick usual_tick_coeffs(T h, T rho_max, const State& x) const noexcept {
    UsualTick c;
    c.step = Rk4Step<T>(h);
    Kernel::fold(engine_, c.fold.v);
    for (int s = 0; s < Kernel::kN; ++s) {
      c.lim[s] = T(2) * (Kernel::kStateZ[s] < Cap::kNodes ? engine_.pressure_envelope() : engine_.speed_envelope());
    }
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    T guess[kExtent<kGuesses>];
    for (int j = 0; j < kGuesses; ++j) guess[j] = guess_[j];
    NoRows none;
    if constexpr (Kernel::kM > 0) {
      if (!Kernel::template solve_stiff<false>(engine_, z, guess, none)) return c;
    }
    T lo[kExtent<Kernel::kZ>], hi[kExtent<Kernel::kZ>];
    for (int k = 0; k < Kernel::kZ; ++k) lo[k] = hi[k] = engine_.fixed_value(k);
    for (T alpha = T(0.125); alpha >= T(1.0 / 2048.0); alpha *= T(0.25)) {
      const T dp = alpha * engine_.pressure_envelope();
      const T dw = alpha * engine_.speed_envelope();
      const auto widen = [&](int k) {
        const T d = k < Cap::kNodes ? dp : dw;
        lo[k] = z[k] - d;
        hi[k] = z[k] + d;
      };
      for (int s = 0; s < Kernel::kN; ++s) widen(Kernel::kStateZ[s]);
      for (int j = 0; j < Kernel::kM; ++j) widen(Kernel::kStiffZ[j]);
      if (engine_.certify_box(lo, hi, rho_max)) {
        for (int s = 0; s < Kernel::kN; ++s) {
          c.x_lo[s] = lo[Kernel::kStateZ[s]];
          c.x_hi[s] = hi[Kernel::kStateZ[s]];
        }
        for (int j = 0; j < Kernel::kM; ++j) {
          c.a_lo[j] = lo[Kernel::kStiffZ[j]];
          c.a_hi[j] = hi[Kernel::kStiffZ[j]];
        }
        c.certified = true;
        return c;
      }
    }
    return c;
  }

  /// One RK4 step of h from x inside c's box, fused: the outputs at x and the four stages
  /// as one straight-line function, with no reduction and no spectral radius (c's box
  /// certifies them). The general tick's arithmetic (tick_derivative's k1, rk4_step's
  /// stages and sum, the same warm starts), so its results bit for bit.
  /// @param c   usual_tick_coeffs(h, rho_max, ·) under the current inputs
  /// @param x   state [Pa, rad/s]
  /// @param y   out: outputs at x, SI
  /// @param dx  out: the RK4 increment over h [Pa, rad/s]
  /// @return    false (nothing written, the warm start unchanged) when c is uncertified,
  ///            x or its stiff pressures lie outside the box, or the solve at x fails
  HSTMON_CIRCUIT_FLATTEN bool usual_tick(const UsualTick& c, const State& x, Output& y, State& dx) const noexcept {
    if (!c.certified) return false;
    for (int s = 0; s < Kernel::kN; ++s) {
      if (!(x[s] >= c.x_lo[s] && x[s] <= c.x_hi[s])) return false;  // NaN too
    }
    // The warm start in a local: stores to a member the compiler cannot tell from the
    // engine's coefficients would make it reload them at every stage.
    T guess[kExtent<kGuesses>];
    for (int j = 0; j < kGuesses; ++j) guess[j] = guess_[j];
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    NoRows none;
    if constexpr (Kernel::kM > 0) {
      if (!Kernel::template solve_stiff<false>(engine_, z, guess, none, c.fold)) return false;
      for (int j = 0; j < Kernel::kM; ++j) {
        const T p = z[Kernel::kStiffZ[j]];
        if (!(p >= c.a_lo[j] && p <= c.a_hi[j])) return false;
      }
    }
    Output y1 = Output::Zero();
    Kernel::outputs(engine_, z, y1);
    State k1 = State::Zero();
    Kernel::template rates<false>(engine_, z, k1, none);
    const State k2 = stage(x + c.step.half * k1, guess, c.fold);
    const State k3 = stage(x + c.step.half * k2, guess, c.fold);
    const State k4 = stage(x + c.step.h * k3, guess, c.fold);
    for (int j = 0; j < kGuesses; ++j) guess_[j] = guess[j];
    y = y1;
    dx = c.step.sixth * (k1 + T(2) * (k2 + k3) + k4);
    return true;
  }

  /// tick_derivative's rho at x, bit for bit, without its side effect on the warm start
  /// (so the general tick that may follow starts where it would have) [1/s].
  T tick_radius(const State& x, T rho_max) const noexcept {
    T saved[kExtent<kGuesses>];
    for (int j = 0; j < kGuesses; ++j) saved[j] = guess_[j];
    Output y;
    T rho;
    bool ok;
    (void)tick_derivative(x, rho_max, y, rho, ok);
    for (int j = 0; j < kGuesses; ++j) guess_[j] = saved[j];
    return rho;
  }

  /// state_plausible(x) with usual_tick_coeffs' bounds (no engine read).
  static bool usual_plausible(const UsualTick& c, const State& x) noexcept {
    bool ok = true;
    for (int s = 0; s < Kernel::kN; ++s) ok = ok & (std::fabs(x[s]) <= c.lim[s]);
    for (int s = Kernel::kN; s < kStates; ++s) ok = ok & (x[s] * T(0) == T(0));
    return ok;
  }

  /// Outputs at x: what each channel measures, in SI units.
  HSTMON_CIRCUIT_NOINLINE Output outputs(const State& x) const noexcept {
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    (void)solve(z);
    return outputs_at(z);
  }

  /// Jacobian ∂f/∂x at x (CircuitModel::jacobian) [1/s in state units].
  void jacobian(const State& x, StateMatrix& J) const noexcept {
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    (void)solve(z);
    // Zeroed: GCC at -O1 cannot see that reduced_jacobian writes every used entry.
    T jr[kExtent<kStates>][kExtent<kStates>] = {};
    T q;
    reduced_jacobian(z, jr, q);
    J.setZero();
    for (int r = 0; r < Kernel::kN; ++r) {
      for (int c = 0; c < Kernel::kN; ++c) J(r, c) = jr[r][c];
    }
  }

  /// Spectral radius of ∂f/∂x at x (tick_derivative's rho with rho_max = 0) [1/s].
  T spectral_radius(const State& x) const noexcept { return tick_spectral_radius(*this, x); }

 private:
  /// The warm start and the states' inverse masses from the engine (after it resolved).
  void sync() noexcept {
    for (int j = 0; j < Kernel::kM; ++j) guess_[j] = engine_.warm_start(j);
    for (int r = 0; r < Kernel::kN; ++r) inv_mass_[r] = engine_.node_stiffness(Kernel::kStateZ[r]);
  }

  bool solve(T (&z)[kExtent<Kernel::kZ>]) const noexcept {
    if constexpr (Kernel::kM == 0) {
      return true;
    } else {
      NoRows none;
      return Kernel::template solve_stiff<false>(engine_, z, guess_, none);
    }
  }

  State rates(const T (&z)[kExtent<Kernel::kZ>]) const noexcept {
    State d = State::Zero();
    NoRows none;
    Kernel::template rates<false>(engine_, z, d, none);
    return d;
  }

  Output outputs_at(const T (&z)[kExtent<Kernel::kZ>]) const noexcept {
    Output y = Output::Zero();
    Kernel::outputs(engine_, z, y);
    return y;
  }

  void reduced_jacobian(const T (&z)[kExtent<Kernel::kZ>], T (&jr)[kExtent<kStates>][kExtent<kStates>], T& q) const noexcept {
    T G[kExtent<Kernel::kU>][kExtent<Kernel::kU>] = {};
    Kernel::unknowns_jacobian(engine_, z, G);
    Kernel::schur(G, inv_mass_, jr, q);
  }

  /// What the kernel's solve and rates take for G when they capture no rows.
  struct NoRows {};

  /// derivative(x) with the warm start in guess and the folded constants (usual_tick's
  /// stages 2–4).
  HSTMON_CIRCUIT_INLINE State stage(const State& x, T (&guess)[kExtent<kGuesses>],
                                    const Folded<T, Kernel::kFolded>& fold) const noexcept {
    T z[kExtent<Kernel::kZ>];
    Kernel::fill(engine_, x, z);
    NoRows none;
    if constexpr (Kernel::kM > 0) (void)Kernel::template solve_stiff<false>(engine_, z, guess, none, fold);
    State d = State::Zero();
    Kernel::template rates<false>(engine_, z, d, none);
    return d;
  }

  Engine engine_{};
  T inv_mass_[kExtent<Kernel::kN>]{};  ///< K [Pa/m³] or 1/J of each state
  mutable T guess_[kExtent<kGuesses>]{};  ///< last quasi-steady pressures [Pa]
};

}  // namespace hstmon::circuit
