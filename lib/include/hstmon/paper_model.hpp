#pragma once
/// @file paper_model.hpp
/// The paper's HST (seed 001, equations 1–8): pressure-compensated pump B at speed ωs →
/// proportional DCV → motor D → coupled loading pump E → PRV to tank. States are the
/// pump-B pressure Ps, motor inlet Pmi, loading-pump outlet Ppp (gauge, Pa) and ωm:
///   dPs/dt  = Kpmp·( Q_B(Ps) − Qdcv )                         eq. 1, 6
///   dPmi/dt = Kpm ·( Qdcv − Dm·ωm − Pmi/Rmlkg )                eq. 2, 7
///   J·dωm/dt = Dm·Pmi − Rfric·ωm − Dp·Ppp                      eq. 3, 5
///   dPpp/dt = Kpp ·( Dp·ωm − Ppp/Rplkg − Qprv )                eq. 4, 8
///   Qdcv = Cd·Adcv·√(2/ρ)·sq(Ps − Pmi),  Qprv = Cd·Aprv·√(2/ρ)·sq(Ppp − Ptank)
/// Q_B is the 3-region curve of pump_curve.hpp (it already includes pump-B leakage).
/// The motor outlet returns to tank. With Table I the modes are slow (|λ| ≲ 1e3 1/s),
/// so the full model is integrated directly.

#include <Eigen/Core>
#include <cmath>

#include "hstmon/pump_curve.hpp"
#include "hstmon/signed_root.hpp"

namespace hstmon {

/// Parameters of the paper model; defaults from Table I (Cd assumed, see docs).
template <typename T>
struct PaperParams {
  PumpCurveParams<T> pump{};  ///< pump B characteristic (Q0 = ωs·Dmp = 150 rad/s × 1.33e-6 m³/rad)
  T Kpmp = T(1e11);           ///< bulk stiffness at pump-B plenum [Pa/m³]
  T Kpm = T(1e11);            ///< bulk stiffness at motor inlet [Pa/m³]
  T Kpp = T(1e11);            ///< bulk stiffness at pump-E outlet [Pa/m³]
  T Dm = T(6.74e-7);          ///< motor D displacement [m³/rad]
  T Dp = T(6.12e-7);          ///< loading pump E displacement [m³/rad]
  T Rmlkg = T(6e11);          ///< motor leakage resistance [Pa·s/m³]
  T Rplkg = T(6e11);          ///< pump-E leakage resistance [Pa·s/m³]
  T Rfric = T(0.014);         ///< viscous friction [N·m·s/rad]
  T J = T(0.015);             ///< inertia of motor–pump coupling [kg·m²]
  T rho = T(870);             ///< oil density [kg/m³]
  T Cd = T(0.61);             ///< discharge coefficient (not in Table I; sharp-edged orifice value)
  T Ptank = T(0);             ///< tank pressure, gauge [Pa] (Table I's Patm = 1 bar absolute)
  T dp_t = T(1e3);            ///< laminar transition ΔP of both orifices [Pa]
};

/// Inputs of the paper model (operator settings).
template <typename T>
struct PaperInputs {
  T A_dcv = T(5e-6);          ///< DCV port area [m²] (§5.4)
  T A_prv = T(3.525e-6);      ///< PRV port area [m²] (§4.3, A1)
};

/// Paper model: state and outputs (Ps, Pmi, Ppp [Pa], ωm [rad/s]).
template <typename T>
class PaperModel {
 public:
  using Scalar = T;
  static constexpr int kStates = 4;
  static constexpr int kOutputs = 4;
  using State = Eigen::Matrix<T, kStates, 1>;
  using Output = Eigen::Matrix<T, kOutputs, 1>;
  using Inputs = PaperInputs<T>;
  using Params = PaperParams<T>;
  enum : int { kPs = 0, kPmi = 1, kPpp = 2, kWm = 3 };  ///< state / output indices

  PaperModel() noexcept { set_params(Params{}); set_inputs(Inputs{}); }

  /// Sets parameters; returns false (model unchanged) if the pump curve is inconsistent
  /// or any magnitude is non-positive.
  bool set_params(const Params& p) noexcept {
    const T v[] = {p.Kpmp, p.Kpm, p.Kpp, p.Dm, p.Dp, p.Rmlkg, p.Rplkg, p.J, p.rho, p.Cd, p.dp_t};
    for (T e : v) {
      if (!(std::isfinite(e) && e > T(0))) return false;
    }
    if (!(std::isfinite(p.Rfric) && p.Rfric >= T(0) && std::isfinite(p.Ptank))) return false;
    PumpCurve<T> c;
    if (!c.make(p.pump)) return false;
    p_ = p;
    curve_ = c;
    orifice_ = p.Cd * std::sqrt(T(2) / p.rho);
    set_inputs(u_);
    return true;
  }

  /// True when both port areas are finite and non-negative.
  static bool inputs_valid(const Inputs& u) noexcept {
    return std::isfinite(u.A_dcv) && std::isfinite(u.A_prv) && u.A_dcv >= T(0) && u.A_prv >= T(0);
  }

  void set_inputs(const Inputs& u) noexcept {
    u_ = u;
    k_dcv_ = orifice_ * u.A_dcv;
    k_prv_ = orifice_ * u.A_prv;
  }

  const Params& params() const noexcept { return p_; }
  const Inputs& inputs() const noexcept { return u_; }
  const PumpCurve<T>& pump_curve() const noexcept { return curve_; }

  /// Time derivative of the state; y (optional) receives the outputs (= the state).
  State derivative(const State& x, Output* y = nullptr) const noexcept {
    const T q_dcv = k_dcv_ * signed_root(x[kPs] - x[kPmi], p_.dp_t);
    const T q_prv = k_prv_ * signed_root(x[kPpp] - p_.Ptank, p_.dp_t);
    State d;
    d[kPs] = p_.Kpmp * (curve_.flow(x[kPs]) - q_dcv);
    d[kPmi] = p_.Kpm * (q_dcv - p_.Dm * x[kWm] - x[kPmi] / p_.Rmlkg);
    d[kPpp] = p_.Kpp * (p_.Dp * x[kWm] - x[kPpp] / p_.Rplkg - q_prv);
    d[kWm] = (p_.Dm * x[kPmi] - p_.Rfric * x[kWm] - p_.Dp * x[kPpp]) / p_.J;
    if (y != nullptr) *y = x;
    return d;
  }

  Output outputs(const State& x) const noexcept { return x; }

  /// Output channel that measures state i: every state is an output (Ps, Pmi, Ppp, ωm).
  static constexpr int state_channel(int i) noexcept { return i; }

  /// Bound on the spectral radius of ∂f/∂x [1/s]: Gershgorin on the diagonally scaled
  /// chain Ps–Pmi–ωm–Ppp (each coupling replaced by √|Jij·Jji|).
  T spectral_radius(const State& x) const noexcept {
    const T g_dcv = k_dcv_ * signed_root_slope(x[kPs] - x[kPmi], p_.dp_t);
    const T g_prv = k_prv_ * signed_root_slope(x[kPpp] - p_.Ptank, p_.dp_t);
    const T a_s = p_.Kpmp * (g_dcv - curve_.slope(x[kPs]));
    const T a_mi = p_.Kpm * (g_dcv + T(1) / p_.Rmlkg);
    const T a_pp = p_.Kpp * (g_prv + T(1) / p_.Rplkg);
    const T a_w = p_.Rfric / p_.J;
    const T c_s_mi = std::sqrt(p_.Kpmp * g_dcv * p_.Kpm * g_dcv);
    const T c_mi_w = std::sqrt(p_.Kpm * p_.Dm * p_.Dm / p_.J);
    const T c_w_pp = std::sqrt(p_.Kpp * p_.Dp * p_.Dp / p_.J);
    T r = a_s + c_s_mi;
    r = std::fmax(r, a_mi + c_s_mi + c_mi_w);
    r = std::fmax(r, a_w + c_mi_w + c_w_pp);
    r = std::fmax(r, a_pp + c_w_pp);
    return r;
  }

  /// No algebraic part: always true.
  bool algebraic_ok(const State&) const noexcept { return true; }

  /// derivative(x, &y) with the observer's per-tick checks (Observer's model interface).
  /// @param x        state (Ps, Pmi, Ppp [Pa], ωm [rad/s])
  /// @param rho_max  unused: the Gershgorin bound is cheap, so ρ is always returned [1/s]
  /// @param y        out: outputs at x (= x)
  /// @param rho      out: spectral_radius(x) [1/s]
  /// @param alg_ok   out: algebraic_ok(x) (true)
  /// @return         derivative(x) [Pa/s, rad/s²]
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok) const noexcept {
    (void)rho_max;
    rho = spectral_radius(x);
    alg_ok = algebraic_ok(x);
    return derivative(x, &y);
  }

  /// True when pressures stay within [−1 bar, 2·Pmax] gauge and |ωm| within the speed
  /// pump B's whole flow could drive.
  bool state_plausible(const State& x) const noexcept {
    const T pmax = T(2) * p_.pump.Pmax;
    const T wmax = T(2) * p_.pump.Q0 / p_.Dm;
    return x[kPs] > T(-1e5) && x[kPs] < pmax && x[kPmi] > T(-1e5) && x[kPmi] < pmax &&
           x[kPpp] > T(-1e5) && x[kPpp] < pmax && std::fabs(x[kWm]) < wmax;
  }

  /// Rest: all pressures at tank, shaft still.
  State rest_state() const noexcept { return State(p_.Ptank, p_.Ptank, p_.Ptank, T(0)); }

  /// The paper model has no closed-form steady state; the observer starts it from rest.
  bool steady_state(State&) const noexcept { return false; }

 private:
  Params p_{};
  Inputs u_{};
  PumpCurve<T> curve_{};
  T orifice_{}, k_dcv_{}, k_prv_{};
};

}  // namespace hstmon
