/// @file operating_point.cpp
#include "hstmon_fdi/operating_point.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon/signed_root.hpp"
#include "hstmon/circuit/thesis_circuit_model.hpp"

namespace hstmon::fdi {

bool steady_outputs(const ThesisParams<double>& p, const ThesisInputs<double>& u, double (&y)[4]) {
  // The solve's own outputs: a model's outputs() at the solved state may differ in the
  // last bits (its tick path reassociates the DCV balance), and small-fault directions
  // are differences of nearly equal steady states.
  if (!ThesisCircuitModel<double>::params_valid(p)) return false;
  return ThesisCircuitModel<double>::steady_outputs(p, u, y);
}

OperatingPoint operating_point(const ThesisParams<double>& p, const ThesisInputs<double>& u) {
  double y[4];
  if (!steady_outputs(p, u, y)) throw std::invalid_argument("operating_point: the inputs admit no steady state");
  OperatingPoint op;
  op.p = p;
  op.u = u;
  op.x.Pmi = y[kChPmi];
  op.x.Pmo = y[kChPmo];
  op.x.Ppp = y[kChPpp];
  op.x.w_m = y[kChWm];
  // Eq. 2.11: the linear resistance passing the same flow at the same drop, R = ΔP/Q = √ΔP/k.
  op.Rin = std::sqrt(u.Psupl - op.x.Pmi) / p.kf;
  op.Rout = std::sqrt(op.x.Pmo - u.Ps) / p.kf;
  op.Rpl = std::sqrt(op.x.Ppp - u.Pbp) / u.kp;
  op.g_in = p.kf * signed_root_slope(u.Psupl - op.x.Pmi, p.dp_t_dcv);
  op.g_out = p.kf * signed_root_slope(op.x.Pmo - u.Ps, p.dp_t_dcv);
  op.g_prv = u.kp * signed_root_slope(op.x.Ppp - u.Pbp, p.dp_t_prv);
  return op;
}

}  // namespace hstmon::fdi
