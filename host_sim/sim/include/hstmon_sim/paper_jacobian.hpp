#pragma once
/// @file paper_jacobian.hpp
/// Analytic Jacobian ∂f/∂x of the paper model (hstmon::PaperModel, equations 1–8), written
/// host-side because lib/ provides only the right-hand side. States (Ps, Pmi, Ppp [Pa], ωm
/// [rad/s]); with q_dcv = k_dcv·sq(Ps − Pmi), q_prv = k_prv·sq(Ppp − Ptank),
/// k = Cd·A·√(2/ρ), sq' the regularised root's slope and Q_B' the pump-curve slope:
///   row Ps : Kpmp·( Q_B'(Ps) − g_dcv ),  Kpmp·g_dcv,  0,  0
///   row Pmi: Kpm·g_dcv,  −Kpm·(g_dcv + 1/Rmlkg),  0,  −Kpm·Dm
///   row Ppp: 0,  0,  −Kpp·(1/Rplkg + g_prv),  Kpp·Dp
///   row ωm : 0,  Dm/J,  −Dp/J,  −Rfric/J
/// where g_dcv = k_dcv·sq'(Ps − Pmi), g_prv = k_prv·sq'(Ppp − Ptank).

#include "hstmon/paper_model.hpp"

namespace hstmon::sim {

/// Jacobian of PaperModel::derivative at x under the model's current inputs.
/// @param m    model (parameters, inputs, pump curve)
/// @param x    state (Ps, Pmi, Ppp [Pa], ωm [rad/s])
/// @param jac  out: row-major 4×4 in SI units of (d state/dt) / state
void paper_jacobian(const PaperModel<double>& m, const PaperModel<double>::State& x, double (&jac)[4][4]);

}  // namespace hstmon::sim
