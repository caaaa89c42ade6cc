#pragma once
/// @file thesis_model.hpp
/// The thesis's state equations 2.5–2.8, as read in docs/equations.md:
///   dPmi/dt = K·( kf·sq(Psupl − Pmi) − Dm·ωm − Pmi/Rlkg − (Pmi − Pmo)/Ripl )
///   dPmo/dt = K·( Dm·ωm + (Pmi − Pmo)/Ripl − Pmo/Rlkg − kf·sq(Pmo − Ps) )
///   dPpp/dt = K·( Dp·ωm − kp·sq(Ppp − Pbp) )
///   J·dωm/dt = Dm·(Pmi − Pmo) − (Rf + Rbl)·ωm − Dp·(Ppp − Pbp)
/// with sq the regularised signed root. This full model is stiff (DCV-side modes near
/// −3.7e5 1/s): it is the reference for host_sim's implicit solver and for tests. The
/// observer integrates the reduced form in thesis_reduced.hpp.

#include "hstmon/signed_root.hpp"
#include "hstmon/thesis_params.hpp"

namespace hstmon {

/// Right-hand side of equations 2.5–2.8.
/// @param p   parameters
/// @param u   inputs
/// @param x   state
/// @return    time derivative [Pa/s, Pa/s, Pa/s, rad/s²]; never allocates or throws
template <typename T>
inline ThesisState<T> thesis_derivative(const ThesisParams<T>& p, const ThesisInputs<T>& u,
                                        const ThesisState<T>& x) noexcept {
  const T q_in = p.kf * signed_root(u.Psupl - x.Pmi, p.dp_t_dcv);    // DCV inlet flow, eq. 2.2
  const T q_out = p.kf * signed_root(x.Pmo - u.Ps, p.dp_t_dcv);      // DCV outlet flow, eq. 2.3
  const T q_prv = u.kp * signed_root(x.Ppp - u.Pbp, p.dp_t_prv);     // PRV flow, eq. 2.4
  const T q_m = p.Dm * x.w_m;                                        // motor swept flow
  const T q_ipl = (x.Pmi - x.Pmo) / p.Ripl;                          // cross-port leakage
  ThesisState<T> d;
  d.Pmi = p.K * (q_in - q_m - x.Pmi / p.Rlkg - q_ipl);
  d.Pmo = p.K * (q_m + q_ipl - x.Pmo / p.Rlkg - q_out);
  d.Ppp = p.K * (p.Dp * x.w_m - q_prv);
  d.w_m = (p.Dm * (x.Pmi - x.Pmo) - (p.Rf + p.Rbl) * x.w_m - p.Dp * (x.Ppp - u.Pbp)) / p.J;
  return d;
}

/// Jacobian ∂f/∂x of thesis_derivative, row-major 4×4, order (Pmi, Pmo, Ppp, ωm).
/// Used by implicit reference solvers and by the stiffness analysis in docs/.
/// @param jac  output [4][4] in SI units of (d state/dt) / state
template <typename T>
inline void thesis_jacobian(const ThesisParams<T>& p, const ThesisInputs<T>& u,
                            const ThesisState<T>& x, T (&jac)[4][4]) noexcept {
  const T g_in = p.kf * signed_root_slope(u.Psupl - x.Pmi, p.dp_t_dcv);
  const T g_out = p.kf * signed_root_slope(x.Pmo - u.Ps, p.dp_t_dcv);
  const T g_prv = u.kp * signed_root_slope(x.Ppp - u.Pbp, p.dp_t_prv);
  const T gl = T(1) / p.Rlkg;
  const T gi = T(1) / p.Ripl;
  jac[0][0] = p.K * (-g_in - gl - gi);
  jac[0][1] = p.K * gi;
  jac[0][2] = T(0);
  jac[0][3] = -p.K * p.Dm;
  jac[1][0] = p.K * gi;
  jac[1][1] = p.K * (-gi - gl - g_out);
  jac[1][2] = T(0);
  jac[1][3] = p.K * p.Dm;
  jac[2][0] = T(0);
  jac[2][1] = T(0);
  jac[2][2] = -p.K * g_prv;
  jac[2][3] = p.K * p.Dp;
  jac[3][0] = p.Dm / p.J;
  jac[3][1] = -p.Dm / p.J;
  jac[3][2] = -p.Dp / p.J;
  jac[3][3] = -(p.Rf + p.Rbl) / p.J;
}

}  // namespace hstmon
