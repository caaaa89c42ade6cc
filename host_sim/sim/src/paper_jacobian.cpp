/// @file paper_jacobian.cpp
#include "hstmon_sim/paper_jacobian.hpp"

#include <cmath>

#include "hstmon/signed_root.hpp"

namespace hstmon::sim {

void paper_jacobian(const PaperModel<double>& m, const PaperModel<double>::State& x, double (&jac)[4][4]) {
  using M = PaperModel<double>;
  const PaperParams<double>& p = m.params();
  const PaperInputs<double>& u = m.inputs();
  const double orifice = p.Cd * std::sqrt(2.0 / p.rho);
  const double g_dcv = orifice * u.A_dcv * signed_root_slope(x[M::kPs] - x[M::kPmi], p.dp_t);
  const double g_prv = orifice * u.A_prv * signed_root_slope(x[M::kPpp] - p.Ptank, p.dp_t);
  const double q_slope = m.pump_curve().slope(x[M::kPs]);
  for (auto& row : jac) {
    for (double& e : row) e = 0.0;
  }
  jac[M::kPs][M::kPs] = p.Kpmp * (q_slope - g_dcv);
  jac[M::kPs][M::kPmi] = p.Kpmp * g_dcv;
  jac[M::kPmi][M::kPs] = p.Kpm * g_dcv;
  jac[M::kPmi][M::kPmi] = -p.Kpm * (g_dcv + 1.0 / p.Rmlkg);
  jac[M::kPmi][M::kWm] = -p.Kpm * p.Dm;
  jac[M::kPpp][M::kPpp] = -p.Kpp * (1.0 / p.Rplkg + g_prv);
  jac[M::kPpp][M::kWm] = p.Kpp * p.Dp;
  jac[M::kWm][M::kPmi] = p.Dm / p.J;
  jac[M::kWm][M::kPpp] = -p.Dp / p.J;
  jac[M::kWm][M::kWm] = -p.Rfric / p.J;
}

}  // namespace hstmon::sim
