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
  static bool params_valid(const Params& p) noexcept {
    const T v[] = {p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf + p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
    for (T e : v) {
      if (!(std::isfinite(e) && e > T(0))) return false;
    }
    return std::isfinite(p.Rf) && std::isfinite(p.Rbl) && p.Rf >= T(0) && p.Rbl >= T(0);
  }

  /// True when the inputs are finite and kp is non-negative.
  static bool inputs_valid(const Inputs& u) noexcept {
    // v·0 is ±0 for finite v and NaN for ±Inf/NaN: one test for all four, no branches.
    const T z = u.Psupl * T(0) + u.Ps * T(0) + u.Pbp * T(0) + u.kp * T(0);
    return z == T(0) && u.kp >= T(0);
  }

  /// Replaces the parameters and recomputes the derived coefficients. O(1).
  void set_params(const Params& p) noexcept {
    p_ = p;
    inv_kf_ = T(1) / p.kf;
    g_lkg_ = T(1) / p.Rlkg;
    g_ipl_ = T(1) / p.Ripl;
    inv_J_ = T(1) / p.J;
    K_Dp_ = p.K * p.Dp;
    Dm_J_ = p.Dm / p.J;
    Dp_J_ = p.Dp / p.J;
    R_J_ = (p.Rf + p.Rbl) / p.J;
    Dm_4kf_ = p.Dm / (T(4) * p.kf);
    kappa_ = inv_kf_ * (g_lkg_ + T(2) * g_ipl_);
    root_dp_t_dcv_ = std::sqrt(p.dp_t_dcv);
    g_lkg_kf_ = g_lkg_ * inv_kf_;
    g_ipl_kf_ = g_ipl_ * inv_kf_;
    jac_dcv_ = T(2) * Dm_J_ * p.Dm * inv_kf_;
    K_Dp_Dp_J_ = K_Dp_ * Dp_J_;
    // Largest |Q/kf| at which one DCV refinement is exact to rounding: contraction
    // c = 2·max(|y|, √ΔP_t)·κ ≤ √ε/2 (κ = (g_lkg + 2·g_ipl)/kf). 0 if never.
    const T y_max = std::sqrt(std::numeric_limits<T>::epsilon()) / (T(4) * kappa_);
    one_refinement_y_ = (std::isfinite(y_max) && y_max >= std::sqrt(p.dp_t_dcv)) ? y_max : T(0);
  }

  /// Sets the inputs held over the next evaluations (zero-order hold). O(1).
  void set_inputs(const Inputs& u) noexcept {
    u_ = u;
    K_kp_ = p_.K * u.kp;
  }

  const Params& params() const noexcept { return p_; }
  const Inputs& inputs() const noexcept { return u_; }

  /// Quasi-steady DCV-side pressures for shaft speed w_m under the current inputs.
  /// @param w_m  motor speed [rad/s]
  /// @param Pmi  out: motor inlet pressure [Pa]
  /// @param Pmo  out: motor outlet pressure [Pa]
  void dcv_pressures(T w_m, T& Pmi, T& Pmo) const noexcept { (void)dcv_solve(w_m, Pmi, Pmo); }

  /// Time derivative of (Ppp, ωm) and, if y is given, the outputs at x (shared work).
  /// @param x  state (Ppp [Pa], ωm [rad/s])
  /// @param y  optional out: (Pmi, Pmo, Ppp [Pa], ωm [rad/s])
  /// @return   (dPpp/dt [Pa/s], dωm/dt [rad/s²])
  State derivative(const State& x, Output* y = nullptr) const noexcept {
    T Pmi, Pmo;
    (void)dcv_solve(x[1], Pmi, Pmo);
    const T dPpp = x[0] - u_.Pbp;
    return rates(x, Pmi, Pmo, dPpp, signed_root(dPpp, p_.dp_t_prv), y);
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
    T Pmi, Pmo;
    const T y_m = dcv_solve(x[1], Pmi, Pmo);
    const T dPpp = x[0] - u_.Pbp;
    T s_prv;
    const State d = rates(x, Pmi, Pmo, dPpp, signed_root(dPpp, p_.dp_t_prv, s_prv), &y);
    const T s_dcv = signed_square_slope(y_m, p_.dp_t_dcv, root_dp_t_dcv_);
    rho = jacobian_radius(-K_kp_ * s_prv, s_dcv, rho_max);
    alg_ok = s_dcv * kappa_ < T(0.5);
    return d;
  }

  /// Outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) at state x.
  Output outputs(const State& x) const noexcept {
    Output y;
    T Pmi, Pmo;
    dcv_pressures(x[1], Pmi, Pmo);
    y[kChPmi] = Pmi;
    y[kChPmo] = Pmo;
    y[kChPpp] = x[0];
    y[kChWm] = x[1];
    return y;
  }

  /// Spectral radius of ∂f/∂x at x [1/s]: exact for the 2×2 Jacobian, with the DCV
  /// pressures' sensitivity to ωm included. Sets the RK4 substep count.
  T spectral_radius(const State& x) const noexcept {
    const T s_dcv = signed_square_slope(p_.Dm * x[1] * inv_kf_, p_.dp_t_dcv, root_dp_t_dcv_);
    return jacobian_radius(-K_kp_ * signed_root_slope(x[0] - u_.Pbp, p_.dp_t_prv), s_dcv, T(0));
  }

  /// Contraction factor of the DCV fixed-point iteration at speed w_m [-]. Below about
  /// 0.01 the kDcvIterations refinements are exact to rounding; at 1 or more the
  /// quasi-steady solve does not converge and the reduced model is not valid.
  T dcv_contraction(T w_m) const noexcept {
    return signed_square_slope(p_.Dm * w_m * inv_kf_, p_.dp_t_dcv, root_dp_t_dcv_) * kappa_;
  }

  /// True when the quasi-steady DCV solve contracts at x (see dcv_contraction).
  bool algebraic_ok(const State& x) const noexcept { return dcv_contraction(x[1]) < T(0.5); }

  /// True when ωm is within twice speed_bound() and Ppp above −1 bar gauge less Pbp's
  /// magnitude: anything else is not a state this rig can reach.
  bool state_plausible(const State& x) const noexcept {
    // |ωm| ≤ 2·speed_bound() = 4·kf·√dp/Dm, squared: no square root or division per tick.
    const T a = x[1] * Dm_4kf_;
    return a * a <= speed_bound_dp() && x[0] >= -(std::fabs(u_.Pbp) + T(1e5));
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

  /// Steady state under the current inputs, by bisection safeguarded secant on the
  /// monotone torque balance. kp = 0 (PRV shut) has no steady state with ωm ≠ 0 and is
  /// refused, as is a result that is not finite or beyond the torque balance's pressure cap.
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
  /// The steady-state solve for (p, u), referred to: the coefficients it needs, computed as
  /// set_params() computes the model's (same values), the torque balance with the DCV
  /// balances solved in their general form (the tick path's dcv code may take shortcuts
  /// that agree to rounding), and the root search. 40 B in float, held by the caller.
  class SteadySolve {
   public:
    HSTMON_STEADY_PATH SteadySolve(const Params& p, const Inputs& u) noexcept
        : p_(p), u_(u), inv_kf_(T(1) / p.kf), root_dp_t_dcv_(std::sqrt(p.dp_t_dcv)), Dm_J_(p.Dm / p.J),
          Dp_J_(p.Dp / p.J), R_J_((p.Rf + p.Rbl) / p.J) {
      const T g_lkg = T(1) / p.Rlkg;
      const T g_ipl = T(1) / p.Ripl;
      g_lkg_kf_ = g_lkg * inv_kf_;
      g_ipl_kf_ = g_ipl * inv_kf_;
      const T kappa = inv_kf_ * (g_lkg + T(2) * g_ipl);
      const T y_max = std::sqrt(std::numeric_limits<T>::epsilon()) / (T(4) * kappa);
      one_refinement_y_ = (std::isfinite(y_max) && y_max >= std::sqrt(p.dp_t_dcv)) ? y_max : T(0);
    }

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
      for (int i = 0; i < 200; ++i) {
        // Secant (regula falsi, Illinois-free) step, bisection when it stalls or leaves the bracket.
        T w_new = hi - f_hi * (hi - lo) / (f_hi - f_lo);
        if (!(w_new > lo && w_new < hi) || (i % 3 == 2)) w_new = T(0.5) * (lo + hi);
        const T f = torque(w_new, Pmi, Pmo);
        if (f > T(0)) { lo = w_new; f_lo = f; } else { hi = w_new; f_hi = f; }
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

    /// steady_torque(w_m) [rad/s²], and the DCV-side pressures Pmi, Pmo [Pa] at w_m: the
    /// leakage-free closed form, then kDcvIterations fixed-point refinements with the
    /// leakage flows (one when that is exact to rounding; NaN takes all).
    HSTMON_STEADY_PATH T torque(T w_m, T& Pmi, T& Pmo) const noexcept {
      const T y_m = p_.Dm * w_m * inv_kf_;
      const T dp_m = signed_square(y_m, p_.dp_t_dcv, root_dp_t_dcv_);
      Pmi = u_.Psupl - dp_m;
      Pmo = u_.Ps + dp_m;
      const int n = std::fabs(y_m) <= one_refinement_y_ ? 1 : kDcvIterations;
      for (int i = 0; i < n; ++i) {
        // Flow balances in units of Q/kf [√Pa] (leakage conductances pre-divided by kf).
        const T y_ipl = (Pmi - Pmo) * g_ipl_kf_;
        const T y_in = y_m + Pmi * g_lkg_kf_ + y_ipl;
        const T y_out = y_m + y_ipl - Pmo * g_lkg_kf_;
        Pmi = u_.Psupl - signed_square(y_in, p_.dp_t_dcv, root_dp_t_dcv_);
        Pmo = u_.Ps + signed_square(y_out, p_.dp_t_dcv, root_dp_t_dcv_);
      }
      const T dPpp = (u_.kp > T(0)) ? signed_square(p_.Dp * w_m / u_.kp, p_.dp_t_prv) : T(0);
      return Dm_J_ * (Pmi - Pmo) - R_J_ * w_m - Dp_J_ * dPpp;
    }

   private:
    const Params& p_;
    const Inputs& u_;
    T inv_kf_, root_dp_t_dcv_, Dm_J_, Dp_J_, R_J_;
    T g_lkg_kf_{}, g_ipl_kf_{}, one_refinement_y_{};
  };

#undef HSTMON_STEADY_PATH

 private:
  /// dcv_pressures(); returns y_m = Dm·ωm/kf [√Pa] for the Jacobian.
  T dcv_solve(T w_m, T& Pmi, T& Pmo) const noexcept {
    const T q_m = p_.Dm * w_m;
    const T y_m = q_m * inv_kf_;
    const T dp_m = signed_square(y_m, p_.dp_t_dcv, root_dp_t_dcv_);
    Pmi = u_.Psupl - dp_m;
    Pmo = u_.Ps + dp_m;
    // The refinement contracts by dcv_contraction(w_m) ≤ 2·max(|y_m|, √ΔP_t)·κ; its
    // error after one step is about that squared (relative). Below
    // one_refinement_y_ it is under half an ulp, and the later steps are skipped
    // (NaN takes them all). Straight-line first step: no loop counter per evaluation.
    dcv_refine(y_m, Pmi, Pmo);
    if (!(std::fabs(y_m) <= one_refinement_y_)) {
      for (int i = 1; i < kDcvIterations; ++i) dcv_refine(y_m, Pmi, Pmo);
    }
    return y_m;
  }

  /// One fixed-point step of the DCV flow balances with the leakage flows at (Pmi, Pmo),
  /// in units of Q/kf [√Pa] (leakage conductances pre-divided by kf).
  void dcv_refine(T y_m, T& Pmi, T& Pmo) const noexcept {
    const T y_ipl = (Pmi - Pmo) * g_ipl_kf_;
    const T y_in = y_m + Pmi * g_lkg_kf_ + y_ipl;
    const T y_out = y_m + y_ipl - Pmo * g_lkg_kf_;
    Pmi = u_.Psupl - signed_square(y_in, p_.dp_t_dcv, root_dp_t_dcv_);
    Pmo = u_.Ps + signed_square(y_out, p_.dp_t_dcv, root_dp_t_dcv_);
  }

  /// (dPpp/dt, dωm/dt) from the DCV pressures and the PRV's signed_root(Ppp − Pbp); fills y if given.
  State rates(const State& x, T Pmi, T Pmo, T dPpp, T root_prv, Output* y) const noexcept {
    State d;
    d[0] = K_Dp_ * x[1] - K_kp_ * root_prv;
    d[1] = Dm_J_ * (Pmi - Pmo) - R_J_ * x[1] - Dp_J_ * dPpp;
    if (y != nullptr) {
      (*y)[kChPmi] = Pmi;
      (*y)[kChPmo] = Pmo;
      (*y)[kChPpp] = x[0];
      (*y)[kChWm] = x[1];
    }
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
    const T det = a * d + K_Dp_Dp_J_;
    const T disc = T(0.25) * tr * tr - det;
    const T half_tr = T(0.5) * std::fabs(tr);
    if (disc >= T(0)) {
      const T m = rho_max - half_tr;
      return (m >= T(0) && disc <= m * m) ? T(0) : half_tr + std::sqrt(disc);
    }
    return det <= rho_max * rho_max ? T(0) : std::sqrt(det);  // NaN: sqrt(NaN)
  }

  /// Pressure difference behind speed_bound() [Pa].
  T speed_bound_dp() const noexcept { return std::fabs(u_.Psupl - u_.Ps) + std::fabs(u_.Pbp) + p_.dp_t_dcv; }

  Params p_{};
  Inputs u_{};
  T inv_kf_{}, g_lkg_{}, g_ipl_{}, inv_J_{}, K_Dp_{}, Dm_J_{}, Dp_J_{}, R_J_{}, K_kp_{}, Dm_4kf_{}, one_refinement_y_{};
  T kappa_{};      ///< DCV contraction per unit slope, (g_lkg + 2·g_ipl)/kf [1/√Pa]
  T root_dp_t_dcv_{};  ///< √dp_t_dcv [√Pa]
  T g_lkg_kf_{}, g_ipl_kf_{};  ///< leakage conductances / kf [1/√Pa]
  T jac_dcv_{};    ///< 2·Dm²/(J·kf): ∂(dωm/dt)/∂ωm per unit DCV slope [1/(s·√Pa)]
  T K_Dp_Dp_J_{};  ///< K·Dp²/J = −J12·J21 of the Jacobian [1/s²]
};

}  // namespace hstmon
