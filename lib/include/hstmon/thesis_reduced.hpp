#pragma once
/// @file thesis_reduced.hpp
/// The thesis model in the form the observer integrates: the two DCV-side pressures
/// (Pmi, Pmo), whose modes sit near −3.7e5 1/s, are taken quasi-steady and solved
/// algebraically each evaluation; Ppp and ωm are integrated. The algebraic solve inverts
/// the orifice law (ΔP = (Q/kf)·|Q/kf|), so the unbounded slope of the square root at
/// zero flow never enters the integrator. docs/numerics.md gives the analysis.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "hstmon/code_size.hpp"
#include "hstmon/signed_root.hpp"
#include "hstmon/thesis_params.hpp"

namespace hstmon {

/// Measured channels of the thesis rig, in the order of the model's output vector.
enum ThesisChannel : int {
  kChPmi = 0,  ///< motor inlet pressure Pmi [Pa]
  kChPmo = 1,  ///< motor outlet pressure Pmo [Pa]
  kChPpp = 2,  ///< loading-pump outlet pressure Ppp [Pa]
  kChWm = 3,   ///< motor speed ωm [rad/s]
};

/// Reduced thesis model: state (Ppp [Pa], ωm [rad/s]); outputs (Pmi, Pmo, Ppp, ωm).
/// Holds parameters and coefficients precomputed from them (≈ 30 scalars); no heap.
template <typename T>
class ThesisReducedModel {
 public:
  using Scalar = T;
  static constexpr int kStates = 2;   ///< Ppp, ωm
  static constexpr int kOutputs = 4;  ///< Pmi, Pmo, Ppp, ωm
  using State = Eigen::Matrix<T, kStates, 1>;
  using Output = Eigen::Matrix<T, kOutputs, 1>;
  using Inputs = ThesisInputs<T>;
  using Params = ThesisParams<T>;

  /// Fixed-point refinements of the DCV-side pressures after the leakage-free closed
  /// form. With Table 2.2 one is exact to rounding; two cover leakage 1e5× stronger.
  static constexpr int kDcvIterations = 2;

  ThesisReducedModel() noexcept { set_params(Params{}); set_inputs(Inputs{}); }
  explicit ThesisReducedModel(const Params& p) noexcept { set_params(p); set_inputs(Inputs{}); }

  /// True when every parameter is finite and strictly positive (all are physical
  /// magnitudes). A model built from invalid parameters must not be stepped.
  static bool params_valid(const Params& p) noexcept { return thesis_params_valid(p); }

  /// True when the inputs are finite and kp is non-negative.
  static bool inputs_valid(const Inputs& u) noexcept { return thesis_inputs_valid(u); }

  /// True when the model's parameters are valid (params_valid), as a circuit model's
  /// valid() says its values resolved: what settle_time() asks before a steady solve.
  bool valid() const noexcept { return params_valid(p_); }

  /// Replaces the parameters and recomputes the derived coefficients. O(1).
  void set_params(const Params& p) noexcept {
    p_ = p;
    const T inv_kf = T(1) / p.kf;
    const T g_lkg = T(1) / p.Rlkg;
    const T g_ipl = T(1) / p.Ripl;
    K_Dp_ = p.K * p.Dp;
    Dm_J_ = p.Dm / p.J;
    Dp_J_ = p.Dp / p.J;
    R_J_ = (p.Rf + p.Rbl) / p.J;
    kappa_ = inv_kf * (g_lkg + T(2) * g_ipl);
    dcv_ = DcvCoeffs(p);
    Dm_kf_ = p.Dm * inv_kf;
    jac_dcv_ = T(2) * Dm_J_ * p.Dm * inv_kf;
    set_inputs(u_);  // the input-dependent coefficients use the parameters
  }

  /// Sets the inputs held over the next evaluations (zero-order hold). O(1). Out of line:
  /// the observer calls it only when the inputs change, and firmware flash is scarce.
#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  void set_inputs(const Inputs& u) noexcept {
    u_ = u;
    K_kp_ = p_.K * u.kp;
    const T dP_sup = u.Psupl - u.Ps;
    torque_sup_ = Dm_J_ * dP_sup;
    c_in_ = u.Psupl * dcv_.g_lkg_kf + dP_sup * dcv_.g_ipl_kf;
    c_out_ = dP_sup * dcv_.g_ipl_kf - u.Ps * dcv_.g_lkg_kf;
    const T c_max = std::fabs(c_in_) > std::fabs(c_out_) ? std::fabs(c_in_) : std::fabs(c_out_);
    fast_y_min_ = T(2) * (dcv_.root_dp_t + c_max);
  }

  const Params& params() const noexcept { return p_; }
  const Inputs& inputs() const noexcept { return u_; }

  /// Quasi-steady DCV-side pressures for shaft speed w_m under the current inputs.
  /// @param w_m  motor speed [rad/s]
  /// @param Pmi  out: motor inlet pressure [Pa]
  /// @param Pmo  out: motor outlet pressure [Pa]
  void dcv_pressures(T w_m, T& Pmi, T& Pmo) const noexcept {
    T dp_in, dp_out;
    (void)dcv_drops(w_m, dp_in, dp_out);
    Pmi = u_.Psupl - dp_in;
    Pmo = u_.Ps + dp_out;
  }

  /// Time derivative of (Ppp, ωm) and, if y is given, the outputs at x (shared work).
  /// @param x  state (Ppp [Pa], ωm [rad/s])
  /// @param y  optional out: (Pmi, Pmo, Ppp [Pa], ωm [rad/s])
  /// @return   (dPpp/dt [Pa/s], dωm/dt [rad/s²])
  State derivative(const State& x, Output* y = nullptr) const noexcept {
    T dp_in, dp_out;
    (void)dcv_drops(x[1], dp_in, dp_out);
    const T dPpp = x[0] - u_.Pbp;
    if (y != nullptr) *y = output_vector(x, dp_in, dp_out);
    return rates(x, dp_in + dp_out, dPpp, signed_root(dPpp, p_.dp_t_prv));
  }

  /// derivative(x, &y) and the observer's per-tick checks at x in one evaluation: the
  /// Jacobian reuses the DCV flow Q/kf and the PRV's √|ΔP|, and ρ is only computed
  /// exactly (one square root) when it exceeds rho_max.
  /// @param x        state (Ppp [Pa], ωm [rad/s])
  /// @param rho_max  spectral radius below which its exact value is not needed [1/s], ≥ 0
  /// @param y        out: outputs at x, as derivative(x, &y)
  /// @param rho      out: spectral_radius(x) [1/s] if above rho_max, else 0 (NaN stays NaN)
  /// @param alg_ok   out: algebraic_ok(x)
  /// @return         derivative(x) [Pa/s, rad/s²]
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok) const noexcept {
    T dp_in, dp_out;
    const T y_m = dcv_drops(x[1], dp_in, dp_out);
    const T dPpp = x[0] - u_.Pbp;
    y = output_vector(x, dp_in, dp_out);
    State d = rates(x, dp_in + dp_out, dPpp, signed_root(dPpp, p_.dp_t_prv));  // not const: returned (moved)
    const T ay = std::fabs(y_m);
    const T adp = std::fabs(dPpp);
    if (ay >= fast_y_min_ && ay <= dcv_.one_refinement_y && adp >= p_.dp_t_prv) {
      // The usual point: both orifices turbulent and the DCV solve contracting (so
      // alg_ok). The Jacobian's diagonal is then J11 = −K·kp/(2√|ΔPpp|), J22 = −R/J −
      // jac_dcv·2|y_m|, both ≤ 0, and ρ² ≤ max(J11², J22²) + K·Dp²/J (a real pair has
      // ρ ≤ max(|J11|, |J22|), a complex one ρ² = det = J11·J22 + K·Dp²/J). So ρ ≤ rho_max
      // when both pass the tests below, squared: no square root and no division.
      const T lim = rho_max * rho_max - K_Dp_ * Dp_J_;
      const T j22 = R_J_ + jac_dcv_ * (T(2) * ay);
      const T j11_adp = T(0.5) * K_kp_;  // |J11|·√|ΔPpp|
      if (j11_adp * j11_adp <= lim * adp && j22 * j22 <= lim) {
        rho = T(0);
        alg_ok = true;
        return d;
      }
    }
    exact_checks(y_m, dPpp, rho_max, rho, alg_ok);
    return d;
  }

  /// True where this build has the fused usual tick (usual_tick): HSTMON_USUAL_TICK,
  /// everywhere but Arm M-profile by default, where flash is scarce and the observer's
  /// general tick serves (code_size.hpp).
  static constexpr bool kHasUsualTick = HSTMON_USUAL_TICK != 0;

  /// Coefficients of usual_tick for one RK4 step of h under the current inputs; from
  /// usual_tick_coeffs(), stale once the inputs change.
  ///
  /// In the usual region the rates, times h/2, are (ΔPpp = Ppp − Pbp)
  ///   gP = a·ωm − b·√ΔPpp,   gω = c − d·z·(z + c1) − e·ωm − f·ΔPpp,   z = ωm·(m1 − m2·ωm):
  /// dcv_drops' fast path is dp_in = (z + c_in)², dp_out = (z + c_out)² with z = y − κ·y²,
  /// y = Dm/kf·ωm, so dp_in + dp_out = 2·z·(z + c1) + c_in² + c_out² (c1 = c_in + c_out).
  struct UsualTick {
    T a{};   ///< h/2·K·Dp [Pa·s/rad]
    T b{};   ///< h/2·K·kp [√Pa]
    T c{};   ///< h/2·Dm/J·(Psupl − Ps − c_in² − c_out²) [rad/s]
    T d{};   ///< h·Dm/J (twice h/2·Dm/J) [rad/(s·Pa)]
    T e{};   ///< h/2·R/J [-]
    T f{};   ///< h/2·Dp/J [rad/(s·Pa)]
    T c1{};              ///< c_in + c_out [√Pa]
    T m1{}, m2{};        ///< Dm/kf [√Pa·s/rad], κ·(Dm/kf)² [√Pa·s²/rad²]
    T c_in{}, c_out{};   ///< leakage flows / kf at the supply pressures, inlet and outlet [√Pa]
    T Psupl{}, Ps{}, Pbp{};  ///< the inputs' pressures [Pa]
    /// The usual region: ωm in [w_lo, w_hi] [rad/s] (forward flow, both DCV orifices
    /// turbulent, one DCV refinement exact, ρ·h ≤ λh_max) and ΔPpp ≥ dp_lo [Pa] (PRV
    /// turbulent, ρ·h ≤ λh_max). Empty (w_lo > w_hi) where no such point exists.
    T w_lo{}, w_hi{}, dp_lo{};
    T w_max{}, P_min{};  ///< state_plausible's bounds: |ωm| ≤ w_max [rad/s], Ppp ≥ P_min [Pa]
  };

  /// usual_tick's coefficients for one RK4 step of h under the current inputs. O(1), two
  /// square roots; the observer recomputes them when the inputs or its tick change.
  /// @param h        RK4 step [s], > 0
  /// @param rho_max  largest spectral radius of ∂f/∂x one step may meet, λh_max/h [1/s];
  ///                 ∞: no stiffness bound, the region is where the fused form is valid
  UsualTick usual_tick_coeffs(T h, T rho_max) const noexcept {
    UsualTick c;
    const T half = T(0.5) * h;
    c.a = half * K_Dp_;
    c.b = half * K_kp_;
    c.c = half * (torque_sup_ - Dm_J_ * (c_in_ * c_in_ + c_out_ * c_out_));
    c.d = h * Dm_J_;
    c.e = half * R_J_;
    c.f = half * Dp_J_;
    c.c1 = c_in_ + c_out_;
    c.m1 = Dm_kf_;
    c.m2 = kappa_ * Dm_kf_ * Dm_kf_;
    c.c_in = c_in_;
    c.c_out = c_out_;
    c.Psupl = u_.Psupl;
    c.Ps = u_.Ps;
    c.Pbp = u_.Pbp;
    // tick_derivative's stiffness test solved for the state: ρ ≤ rho_max where
    // J22 = R/J + jac_dcv·2y ≤ √lim and J11² = (K·kp/2)²/ΔPpp ≤ lim, lim = rho_max² − K·Dp²/J.
    c.w_lo = T(1);
    c.w_hi = T(0);
    c.dp_lo = std::numeric_limits<T>::infinity();
    const T lim = rho_max * rho_max - K_Dp_ * Dp_J_;
    if (lim > T(0)) {
      const T y_stiff = (std::sqrt(lim) - R_J_) / (T(2) * jac_dcv_);
      const T y_hi = y_stiff < dcv_.one_refinement_y ? y_stiff : dcv_.one_refinement_y;
      const T j11_root = T(0.5) * K_kp_;  // |J11|·√ΔPpp
      const T dp_stiff = j11_root * j11_root / lim;
      c.w_lo = fast_y_min_ / Dm_kf_;
      c.w_hi = y_hi / Dm_kf_;
      c.dp_lo = dp_stiff > p_.dp_t_prv ? dp_stiff : p_.dp_t_prv;
    }
    c.w_max = T(2) * speed_bound();
    c.P_min = plausible_Ppp_min();
    return c;
  }

  /// One RK4 step of h from x in the usual region, fused: the outputs at x and the four
  /// stages from usual_tick_coeffs(h, ·) in scalar code, each stage checked to lie in the
  /// region. Same model and RK4 as tick_derivative + rk4_step (the results agree to
  /// rounding), in about a third fewer instructions: no general-case branches, h folded
  /// into the coefficients, the stiffness test a range check.
  /// @param c   usual_tick_coeffs(h, rho_max) under the current inputs
  /// @param x   state (Ppp [Pa], ωm [rad/s])
  /// @param y   out: outputs at x (Pmi, Pmo, Ppp [Pa], ωm [rad/s])
  /// @param dx  out: the RK4 increment of x over h [Pa, rad/s]
  /// @return    false (y and dx untouched) if x or a stage leaves the usual region: the
  ///            step must then be taken the general way
  bool usual_tick(const UsualTick& c, const State& x, Output& y, State& dx) const noexcept {
    const T P = x[0];
    const T w = x[1];
    const T q = P - c.Pbp;
    T z, g1q, g1w, g2q, g2w, g3q, g3w, g4q, g4w;
    if (!usual_stage(c, q, w, g1q, g1w, z)) return false;
    const T y_in = z + c.c_in;
    const T y_out = z + c.c_out;
    const T Pmi = c.Psupl - y_in * y_in;
    const T Pmo = c.Ps + y_out * y_out;
    if (!usual_stage(c, q + g1q, w + g1w, g2q, g2w, z)) return false;
    if (!usual_stage(c, q + g2q, w + g2w, g3q, g3w, z)) return false;
    if (!usual_stage(c, q + T(2) * g3q, w + T(2) * g3w, g4q, g4w, z)) return false;
    const T third = T(1) / T(3);
    // Stored last: y and dx may alias c for all the compiler knows, and stores before the
    // stages would have it keep every coefficient in registers or on the stack.
    y[kChPmi] = Pmi;
    y[kChPmo] = Pmo;
    y[kChPpp] = P;
    y[kChWm] = w;
    dx = State(third * (g1q + T(2) * (g2q + g3q) + g4q), third * (g1w + T(2) * (g2w + g3w) + g4w));
    return true;
  }

  /// The general tick's ρ at x where its quick test does not settle it: the spectral
  /// radius of ∂f/∂x [1/s], or 0 if at most rho_max — tick_derivative's rho off its usual
  /// point, bit for bit (the same arithmetic), so a caller picks the same substep count.
  T tick_radius(const State& x, T rho_max) const noexcept {
    T rho;
    bool alg_ok;
    exact_checks(x[1] * Dm_kf_, x[0] - u_.Pbp, rho_max, rho, alg_ok);
    return rho;
  }

  /// state_plausible(x) with usual_tick_coeffs' bounds (no square root, no inputs read).
  static bool usual_plausible(const UsualTick& c, const State& x) noexcept {
    return std::fabs(x[1]) <= c.w_max && x[0] >= c.P_min && x[0] <= std::numeric_limits<T>::max();
  }

  /// Outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) at state x.
  Output outputs(const State& x) const noexcept {
    T dp_in, dp_out;
    (void)dcv_drops(x[1], dp_in, dp_out);
    return output_vector(x, dp_in, dp_out);
  }

  /// Spectral radius of ∂f/∂x at x [1/s]: exact for the 2×2 Jacobian, with the DCV
  /// pressures' sensitivity to ωm included. Sets the RK4 substep count.
  T spectral_radius(const State& x) const noexcept {
    const T s_dcv = signed_square_slope(x[1] * Dm_kf_, p_.dp_t_dcv, dcv_.root_dp_t);
    return jacobian_radius(-K_kp_ * signed_root_slope(x[0] - u_.Pbp, p_.dp_t_prv), s_dcv, T(0));
  }

  /// Slowest decay rate of the linearised model at x: the smallest |Re λ| of the 2×2
  /// Jacobian ∂f/∂x [1/s] (its reciprocal is the model's slowest time constant there).
  /// 0 when the Jacobian is singular or unstable at x; NaN for a non-finite x.
  T slowest_rate(const State& x) const noexcept {
    const T s_dcv = signed_square_slope(x[1] * Dm_kf_, p_.dp_t_dcv, dcv_.root_dp_t);
    const T a = -K_kp_ * signed_root_slope(x[0] - u_.Pbp, p_.dp_t_prv);
    const T d = -R_J_ - jac_dcv_ * s_dcv;
    const T half_tr = T(-0.5) * (a + d);          // > 0 for a stable point
    const T det = a * d + K_Dp_ * Dp_J_;
    const T disc = half_tr * half_tr - det;
    const T rate = disc > T(0) ? half_tr - std::sqrt(disc) : half_tr;  // real pair: the slower one
    return rate > T(0) ? rate : (rate == rate ? T(0) : rate);
  }

  /// Output channel that measures state i (Ppp → kChPpp, ωm → kChWm): both states are
  /// measured on the thesis rig, which lets the observer start from the measurement.
  static constexpr int state_channel(int i) noexcept { return i == 0 ? kChPpp : kChWm; }

  /// Contraction factor of the DCV fixed-point iteration at speed w_m [-]. Below about
  /// 0.01 the kDcvIterations refinements are exact to rounding; at 1 or more the
  /// quasi-steady solve does not converge and the reduced model is not valid.
  T dcv_contraction(T w_m) const noexcept {
    return signed_square_slope(w_m * Dm_kf_, p_.dp_t_dcv, dcv_.root_dp_t) * kappa_;
  }

  /// True when the quasi-steady DCV solve contracts at x (see dcv_contraction).
  bool algebraic_ok(const State& x) const noexcept { return dcv_contraction(x[1]) < T(0.5); }

  /// True when ωm is within twice speed_bound() and Ppp finite and above −1 bar gauge less
  /// Pbp's magnitude: anything else, non-finite values included, is not a state this rig
  /// can reach.
  bool state_plausible(const State& x) const noexcept {
    // |ωm| ≤ 2·speed_bound() = 4·kf·√dp/Dm as |Dm·ωm/kf|² ≤ 16·dp: no square root or division.
    const T y = x[1] * Dm_kf_;
    return y * y <= T(16) * speed_bound_dp() && x[0] >= plausible_Ppp_min() && x[0] <= std::numeric_limits<T>::max();
  }

  /// The state at rest: ωm = 0, Ppp = Pbp (no flow through the PRV).
  State rest_state() const noexcept { return State(u_.Pbp, T(0)); }

  /// Bound on |ωm| reachable under the current inputs [rad/s]: the speed at which the
  /// DCV alone drops the whole supply pressure difference, with a margin.
  T speed_bound() const noexcept { return T(2) * p_.kf * std::sqrt(speed_bound_dp()) / p_.Dm; }

// The steady-state solve runs at configuration and on input changes, never per tick: its
// parts are out of line (each frame small, stack) and size-optimised (flash).
#if defined(__GNUC__)
#define HSTMON_STEADY_PATH __attribute__((noinline, cold))
#else
#define HSTMON_STEADY_PATH
#endif

  /// Net shaft torque per inertia at speed w_m with Ppp at its quasi-steady value [rad/s²].
  /// Strictly decreasing in w_m; its root is the steady state (steady_state's arithmetic).
  T steady_torque(T w_m) const noexcept {
    T Pmi, Pmo;
    return SteadySolve(p_, u_).torque(w_m, Pmi, Pmo);
  }

  /// Steady state under the current inputs, by regula falsi (Illinois rule, bisection as
  /// a safeguard) on the monotone torque balance. kp = 0 (PRV shut) has no steady state
  /// with ωm ≠ 0 and is refused, as is a result that is not finite or beyond the torque
  /// balance's pressure cap.
  /// @param x  out: (Ppp [Pa], ωm [rad/s])
  /// @return   true on convergence; false (x untouched) if the inputs admit none
  bool steady_state(State& x) const noexcept { return SteadySolve(p_, u_).solve(&x, nullptr); }

  /// steady_state() for parameters p and inputs u, without a model object: the model bound
  /// (residual_bounds.hpp) solves ≈ 20 perturbed parameter sets, and a model for each
  /// would be most of its stack.
  /// @param p  parameters, params_valid(p)
  /// @param u  inputs
  /// @param x  out: (Ppp [Pa], ωm [rad/s])
  /// @return   true on convergence; false (x untouched) if the inputs admit none
  static bool steady_state(const Params& p, const Inputs& u, State& x) noexcept {
    return SteadySolve(p, u).solve(&x, nullptr);
  }

  /// Outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) at the steady state for p and u, with the
  /// solve's DCV arithmetic (outputs() of a model at that state agrees to rounding).
  /// @param p  parameters, params_valid(p)
  /// @param u  inputs
  /// @param y  out: the kOutputs outputs
  /// @return   true on convergence; false (y untouched) if the inputs admit none
  static bool steady_outputs(const Params& p, const Inputs& u, T (&y)[kOutputs]) noexcept {
    return SteadySolve(p, u).solve(nullptr, y);
  }

 private:
  /// The DCV's flow balances: the coefficients they need and their general solve, shared
  /// by the tick path (off the operating point) and the steady-state solve.
  struct DcvCoeffs {
    T g_lkg_kf{}, g_ipl_kf{};  ///< leakage conductances / kf, 1/(Rlkg·kf), 1/(Ripl·kf) [1/√Pa]
    T dp_t{};                  ///< laminar transition ΔP of the orifices [Pa]
    T root_dp_t{};             ///< √dp_t [√Pa]
    T one_refinement_y{};      ///< largest |Q/kf| at which one refinement is exact to rounding, or 0 [√Pa]

    DcvCoeffs() noexcept = default;
    explicit DcvCoeffs(const Params& p) noexcept : dp_t(p.dp_t_dcv), root_dp_t(std::sqrt(p.dp_t_dcv)) {
      const T inv_kf = T(1) / p.kf;
      const T g_lkg = T(1) / p.Rlkg;
      const T g_ipl = T(1) / p.Ripl;
      g_lkg_kf = g_lkg * inv_kf;
      g_ipl_kf = g_ipl * inv_kf;
      // Contraction of a refinement: c = 2·max(|y|, √ΔP_t)·κ (κ = (g_lkg + 2·g_ipl)/kf);
      // one is exact to rounding where c ≤ √ε/2.
      const T kappa = inv_kf * (g_lkg + T(2) * g_ipl);
      const T y_max = std::sqrt(std::numeric_limits<T>::epsilon()) / (T(4) * kappa);
      one_refinement_y = (std::isfinite(y_max) && y_max >= root_dp_t) ? y_max : T(0);
    }

    /// Drops across the inlet and outlet orifices [Pa] for DCV flow y_m = Dm·ωm/kf [√Pa]
    /// under supply and return pressures Psupl, Ps [Pa]: the leakage-free closed form, then
    /// kDcvIterations fixed-point refinements of the balances with the leakage flows (one
    /// when that is exact to rounding; NaN takes them all), each orifice through the
    /// regularised law. Out of line and cold: the tick path takes it only off the
    /// operating point.
#if defined(__GNUC__)
    __attribute__((noinline, cold))
#endif
    void drops(T y_m, T Psupl, T Ps, T& dp_in, T& dp_out) const noexcept {
      dp_in = signed_square(y_m, dp_t, root_dp_t);
      dp_out = dp_in;
      const int n = std::fabs(y_m) <= one_refinement_y ? 1 : kDcvIterations;
      for (int i = 0; i < n; ++i) {
        // Flows in units of Q/kf [√Pa].
        const T Pmi = Psupl - dp_in;
        const T Pmo = Ps + dp_out;
        const T y_ipl = (Pmi - Pmo) * g_ipl_kf;
        const T y_in = y_m + Pmi * g_lkg_kf + y_ipl;
        const T y_out = y_m + y_ipl - Pmo * g_lkg_kf;
        dp_in = signed_square(y_in, dp_t, root_dp_t);
        dp_out = signed_square(y_out, dp_t, root_dp_t);
      }
    }
  };

  /// The steady-state solve for (p, u), referred to: the coefficients it needs, computed as
  /// set_params() computes the model's (same values), the torque balance with the DCV
  /// balances solved in their general form (the tick path's dcv code may take shortcuts
  /// that agree to rounding), and the root search. 44 B in float, held by the caller.
  class SteadySolve {
   public:
    HSTMON_STEADY_PATH SteadySolve(const Params& p, const Inputs& u) noexcept
        : p_(p), u_(u), dcv_(p), Dm_kf_(p.Dm / p.kf), Dm_J_(p.Dm / p.J), Dp_J_(p.Dp / p.J),
          R_J_((p.Rf + p.Rbl) / p.J) {}

    /// The steady state (see steady_state()); fills x and/or y (kOutputs values) if given.
    HSTMON_STEADY_PATH bool solve(State* x, T* y) const noexcept {
      if (!(u_.kp > T(0)) || !inputs_valid(u_)) return false;
      T Pmi, Pmo;
      T lo = -speed_bound();
      T hi = -lo;
      T f_lo = torque(lo, Pmi, Pmo);
      T f_hi = torque(hi, Pmi, Pmo);
      for (int i = 0; i < 60 && f_lo < T(0); ++i) { lo *= T(2); f_lo = torque(lo, Pmi, Pmo); }
      for (int i = 0; i < 60 && f_hi > T(0); ++i) { hi *= T(2); f_hi = torque(hi, Pmi, Pmo); }
      if (!(f_lo >= T(0) && f_hi <= T(0))) return false;
      T w = T(0);
      int kept = 0;  // +1: lo was moved last (hi kept), −1: hi was moved last
      for (int i = 0; i < 200; ++i) {
        // Regula falsi with the Illinois rule: an end kept twice in a row has its torque
        // halved, so both ends close in (superlinearly; ≈ 10 torque evaluations from the
        // speed bound to a few ulps instead of ≈ 30 with a bisection every third step).
        // Bisection when the step leaves the bracket (or is NaN).
        T w_new = hi - f_hi * (hi - lo) / (f_hi - f_lo);
        if (!(w_new > lo && w_new < hi)) w_new = T(0.5) * (lo + hi);
        const T f = torque(w_new, Pmi, Pmo);
        if (f > T(0)) {
          lo = w_new;
          f_lo = f;
          if (kept == 1) f_hi *= T(0.5);
          kept = 1;
        } else {
          hi = w_new;
          f_hi = f;
          if (kept == -1) f_lo *= T(0.5);
          kept = -1;
        }
        w = w_new;
        if (f == T(0) || (hi - lo) <= T(4) * std::numeric_limits<T>::epsilon() * (std::fabs(w) + T(1))) break;
      }
      const T dPpp = signed_square(p_.Dp * w / u_.kp, p_.dp_t_prv);
      // The torque balance caps the pump pressure rise at about (Dm/Dp)·|Psupl − Ps|; with a
      // near-shut PRV (tiny kp) float rounding of Dp·ω/kp can land far beyond it, or at Inf.
      const T dp_cap =
          T(2) * (p_.Dm / p_.Dp) * (std::fabs(u_.Psupl - u_.Ps) + std::fabs(u_.Pbp) + p_.dp_t_dcv) + p_.dp_t_prv;
      if (!(std::isfinite(dPpp) && std::isfinite(w) && std::fabs(dPpp) <= dp_cap)) return false;
      if (x != nullptr) *x = State(u_.Pbp + dPpp, w);
      if (y != nullptr) {
        (void)torque(w, y[kChPmi], y[kChPmo]);  // for the DCV pressures at w
        y[kChPpp] = u_.Pbp + dPpp;
        y[kChWm] = w;
      }
      return true;
    }

    /// ThesisReducedModel::speed_bound() for (p, u) [rad/s].
    T speed_bound() const noexcept {
      return T(2) * p_.kf * std::sqrt(std::fabs(u_.Psupl - u_.Ps) + std::fabs(u_.Pbp) + p_.dp_t_dcv) / p_.Dm;
    }

    /// steady_torque(w_m) [rad/s²], and the DCV-side pressures Pmi, Pmo [Pa] at w_m from
    /// the DCV balances in their general form (DcvCoeffs::drops).
    HSTMON_STEADY_PATH T torque(T w_m, T& Pmi, T& Pmo) const noexcept {
      T dp_in, dp_out;
      dcv_.drops(w_m * Dm_kf_, u_.Psupl, u_.Ps, dp_in, dp_out);
      Pmi = u_.Psupl - dp_in;
      Pmo = u_.Ps + dp_out;
      const T dPpp = (u_.kp > T(0)) ? signed_square(p_.Dp * w_m / u_.kp, p_.dp_t_prv) : T(0);
      return Dm_J_ * (Pmi - Pmo) - R_J_ * w_m - Dp_J_ * dPpp;
    }

   private:
    const Params& p_;
    const Inputs& u_;
    DcvCoeffs dcv_;
    T Dm_kf_, Dm_J_, Dp_J_, R_J_;
  };

#undef HSTMON_STEADY_PATH

 private:
  /// Pressure drops across the DCV's inlet and outlet orifices at speed w_m [Pa]
  /// (Pmi = Psupl − dp_in, Pmo = Ps + dp_out); returns y_m = Dm·ωm/kf [√Pa] for the Jacobian.
  HSTMON_LEAN_NOINLINE T dcv_drops(T w_m, T& dp_in, T& dp_out) const noexcept {
    const T y_m = w_m * Dm_kf_;
    const T ay = std::fabs(y_m);
    if (ay >= fast_y_min_ && ay <= dcv_.one_refinement_y) {
      // The usual case: one refinement is exact to rounding (|y_m| ≤ dcv_.one_refinement_y)
      // and both orifices stay turbulent with y_m's sign (|y_m| ≥ fast_y_min_, see
      // set_inputs). The leakage flows at the closed-form pressures (Psupl − dp, Ps + dp)
      // are then c_in, c_out − κ·dp: DcvCoeffs::drops' refinement in five operations.
      const T z = y_m - kappa_ * (y_m * ay);
      const T y_in = z + c_in_;
      const T y_out = z + c_out_;
      dp_in = y_in * std::fabs(y_in);
      dp_out = y_out * std::fabs(y_out);
    } else {
      dcv_.drops(y_m, u_.Psupl, u_.Ps, dp_in, dp_out);
    }
    return y_m;
  }

  /// usual_tick's rates times h/2 at (ΔPpp = q [Pa], ωm = w [rad/s]), and z [√Pa] for the
  /// DCV drops; false outside the usual region.
  static bool usual_stage(const UsualTick& c, T q, T w, T& gq, T& gw, T& z) noexcept {
    if (!(w >= c.w_lo && w <= c.w_hi && q >= c.dp_lo)) return false;
    z = w * (c.m1 - c.m2 * w);
    gq = c.a * w - c.b * std::sqrt(q);
    gw = c.c - c.d * (z * (z + c.c1)) - c.e * w - c.f * q;
    return true;
  }

  /// tick_derivative's checks off the usual point (start from rest, laminar orifices, a
  /// stiff operating point): ρ if above rho_max (else 0) and the DCV solve's contraction.
  /// Out of line: rare, and it keeps firmware flash down.
#if defined(__GNUC__)
  __attribute__((noinline, cold))
#endif
  void exact_checks(T y_m, T dPpp, T rho_max, T& rho, bool& alg_ok) const noexcept {
    const T s_dcv = signed_square_slope(y_m, p_.dp_t_dcv, dcv_.root_dp_t);
    rho = jacobian_radius(-K_kp_ * signed_root_slope(dPpp, p_.dp_t_prv), s_dcv, rho_max);
    alg_ok = s_dcv * kappa_ < T(0.5);
  }

  /// Outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) from the state and the DCV drops [Pa].
  Output output_vector(const State& x, T dp_in, T dp_out) const noexcept {
    Output y;
    y[kChPmi] = u_.Psupl - dp_in;
    y[kChPmo] = u_.Ps + dp_out;
    y[kChPpp] = x[0];
    y[kChWm] = x[1];
    return y;
  }

  /// (dPpp/dt, dωm/dt) from the sum of the DCV drops [Pa] and the PRV's
  /// signed_root(Ppp − Pbp) [√Pa]; Dm/J·(Pmi − Pmo) = torque_sup_ − Dm/J·(dp_in + dp_out).
  State rates(const State& x, T dp_dcv, T dPpp, T root_prv) const noexcept {
    State d;
    d[0] = K_Dp_ * x[1] - K_kp_ * root_prv;
    d[1] = torque_sup_ - Dm_J_ * dp_dcv - R_J_ * x[1] - Dp_J_ * dPpp;
    return d;
  }

  /// Spectral radius of the 2×2 Jacobian [[a, K·Dp], [−Dp/J, d]] [1/s], exact, or 0 when
  /// it is at most rho_max (then no square root: a complex pair has ρ² = det; a real
  /// pair has ρ = |tr|/2 + √disc ≤ rho_max ⟺ m = rho_max − |tr|/2 ≥ 0 and disc ≤ m²).
  /// @param a      ∂(dPpp/dt)/∂Ppp = −K·kp·(PRV slope) [1/s]
  /// @param s_dcv  signed_square_slope at the DCV flow Q/kf [√Pa]; leakage neglected
  ///               (its effect is < 1e-8 relative)
  T jacobian_radius(T a, T s_dcv, T rho_max) const noexcept {
    const T d = -R_J_ - jac_dcv_ * s_dcv;
    const T tr = a + d;
    const T det = a * d + K_Dp_ * Dp_J_;  // K·Dp²/J = −J12·J21
    const T disc = T(0.25) * tr * tr - det;
    const T half_tr = T(0.5) * std::fabs(tr);
    if (disc >= T(0)) {
      const T m = rho_max - half_tr;
      return (m >= T(0) && disc <= m * m) ? T(0) : half_tr + std::sqrt(disc);
    }
    return det <= rho_max * rho_max ? T(0) : std::sqrt(det);  // NaN: sqrt(NaN)
  }

  /// Lowest plausible Ppp [Pa]: −1 bar gauge less Pbp's magnitude (state_plausible).
  T plausible_Ppp_min() const noexcept { return -(std::fabs(u_.Pbp) + T(1e5)); }

  /// Pressure difference behind speed_bound() [Pa].
  T speed_bound_dp() const noexcept { return std::fabs(u_.Psupl - u_.Ps) + std::fabs(u_.Pbp) + p_.dp_t_dcv; }

  Params p_{};
  Inputs u_{};
  T K_Dp_{}, Dm_J_{}, Dp_J_{}, R_J_{}, K_kp_{};
  DcvCoeffs dcv_{};  ///< DCV balance coefficients (leakage, laminar transition)
  T kappa_{};      ///< DCV contraction per unit slope, (g_lkg + 2·g_ipl)/kf [1/√Pa]
  T jac_dcv_{};    ///< 2·Dm²/(J·kf): ∂(dωm/dt)/∂ωm per unit DCV slope [1/(s·√Pa)]
  T Dm_kf_{};      ///< Dm/kf: DCV flow Q/kf per unit speed [√Pa·s/rad]
  // Input-dependent, set by set_inputs:
  T torque_sup_{};  ///< Dm/J·(Psupl − Ps) [rad/s²]
  T c_in_{}, c_out_{};  ///< leakage flows / kf at the supply pressures, inlet and outlet [√Pa]
  T fast_y_min_{};  ///< smallest |Q/kf| of dcv_drops' one-refinement path [√Pa]
};

}  // namespace hstmon
