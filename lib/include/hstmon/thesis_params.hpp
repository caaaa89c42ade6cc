#pragma once
/// @file thesis_params.hpp
/// Parameters and inputs of the thesis HST (seed 000): supply → DCV → motor → coupled
/// loading pump → PRV. Defaults are Table 2.2 with the thesis's simplifications
/// (one bulk stiffness K for all volumes, kfi = kfo = kf, Rlkg1 = Rlkg2 = Rlkg,
/// Rbl = Rbl1 + Rbl2). Pressures are gauge (Ps = 0 is atmosphere).

#include <cmath>

namespace hstmon {

/// Physical parameters of the thesis model (Table 2.2). Plain aggregate; copy freely.
template <typename T>
struct ThesisParams {
  T Dm = T(7.96e-6);          ///< motor displacement [m³/rad]
  T Dp = T(1.00745e-6);       ///< loading-pump displacement [m³/rad]
  T Rlkg = T(6.4779e16);      ///< leakage resistance of each motor port to drain [Pa·s/m³]
  T Ripl = T(16.97088e18);    ///< cross-port leakage resistance of the motor [Pa·s/m³]
  T Rf = T(1.59154e-3);       ///< shaft friction [N·m·s/rad]
  T Rbl = T(4.758732e-2);     ///< fluid friction Rbl1 + Rbl2 of the flow-control valves [N·m·s/rad]
  T kf = T(0.3226e-5);        ///< DCV orifice coefficient, Q = kf·√ΔP [m³/(s·√Pa)]
  T J = T(1e-3);              ///< moment of inertia of motor + pump [kg·m²]
  T K = T(1e14);              ///< bulk stiffness of each fluid volume [Pa/m³]
  T dp_t_dcv = T(1e3);        ///< laminar transition ΔP of the DCV orifices [Pa] (see signed_root.hpp)
  T dp_t_prv = T(1e5);        ///< laminar transition ΔP of the PRV orifice [Pa]
};

/// Inputs of the thesis model; held constant over one observer tick.
template <typename T>
struct ThesisInputs {
  T Psupl = T(3.5e6);         ///< supply pressure upstream of the DCV [Pa]
  T Ps = T(0);                ///< DCV return (tank) pressure [Pa]
  T Pbp = T(1.0e6);           ///< booster-pump pressure downstream of the PRV [Pa]
  T kp = T(4.41e-8);          ///< PRV orifice coefficient, Q = kp·√ΔP [m³/(s·√Pa)]

  /// True when every input is equal (the monitor's test for an input change).
  friend constexpr bool operator==(const ThesisInputs& a, const ThesisInputs& b) noexcept {
    return a.Psupl == b.Psupl && a.Ps == b.Ps && a.Pbp == b.Pbp && a.kp == b.kp;
  }
  /// True when b is within tol [-] of a (input_change.hpp): each pressure within tol of
  /// a's largest pressure (a tank pressure near 0 is no scale of its own), kp within tol
  /// of a's kp. False for a NaN.
  friend bool inputs_within(const ThesisInputs& a, const ThesisInputs& b, T tol) noexcept {
    T p = std::fabs(a.Psupl);
    if (std::fabs(a.Ps) > p) p = std::fabs(a.Ps);
    if (std::fabs(a.Pbp) > p) p = std::fabs(a.Pbp);
    p *= tol;
    return std::fabs(b.Psupl - a.Psupl) <= p && std::fabs(b.Ps - a.Ps) <= p && std::fabs(b.Pbp - a.Pbp) <= p &&
           std::fabs(b.kp - a.kp) <= tol * std::fabs(a.kp);
  }
};

/// True when every parameter is finite and strictly positive (all are physical
/// magnitudes; Rf or Rbl may be 0 if the other is not). The thesis rig's models refuse
/// anything else (ThesisReducedModel, ThesisCircuitModel: params_valid).
template <typename T>
bool thesis_params_valid(const ThesisParams<T>& p) noexcept {
  const T v[] = {p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf + p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
  for (T e : v) {
    if (!(std::isfinite(e) && e > T(0))) return false;
  }
  return std::isfinite(p.Rf) && std::isfinite(p.Rbl) && p.Rf >= T(0) && p.Rbl >= T(0);
}

/// True when the inputs are finite and kp (an orifice coefficient) is not negative.
template <typename T>
bool thesis_inputs_valid(const ThesisInputs<T>& u) noexcept {
  // v·0 is ±0 for finite v and NaN for ±Inf/NaN: one test for all four, no branches.
  const T z = u.Psupl * T(0) + u.Ps * T(0) + u.Pbp * T(0) + u.kp * T(0);
  return z == T(0) && u.kp >= T(0);
}

/// Full state of equations 2.5–2.8.
template <typename T>
struct ThesisState {
  T Pmi = T(0);               ///< motor inlet pressure [Pa]
  T Pmo = T(0);               ///< motor outlet pressure [Pa]
  T Ppp = T(0);               ///< loading-pump outlet pressure [Pa]
  T w_m = T(0);               ///< motor shaft speed ωm [rad/s]
};

}  // namespace hstmon
