/// @file crosscheck.cpp
#include "hstmon_fdi/crosscheck.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon/signed_root.hpp"
#include "hstmon/thesis_model.hpp"
#include "hstmon_fdi/fault_catalogue.hpp"
#include "hstmon_fdi/operating_point.hpp"
#include "hstmon_fdi/qual.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"
#include "hstmon_sim/thesis_reference.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::fdi {

namespace {

using Vec4 = std::array<double, 4>;

Vec4 as_array(const ThesisState<double>& x) {
  Vec4 v{};
  sim::to_array(x, v.data());
  return v;
}

/// DCV orifice flow kf·sq(dp) [m³/s].
double f_dcv(const ThesisParams<double>& p, double dp) { return p.kf * signed_root(dp, p.dp_t_dcv); }

/// Sign and order of the first non-zero time derivative at 0+ of each state after the
/// parameters change from (p0, u0) to (p1, u1) at the steady state x0: d1 = Δf(x0),
/// d(k+1) = J1·dk (first order in the fault size). A term within 1e-9 of the sum of
/// absolute contributions counts as zero, so structural zeros stay zero.
void taylor_signs(const ThesisParams<double>& p0, const ThesisInputs<double>& u0, const ThesisParams<double>& p1,
                  const ThesisInputs<double>& u1, const ThesisState<double>& x0, int max_order,
                  std::array<ChannelCheck, 4>& out) {
  const Vec4 f0 = as_array(thesis_derivative(p0, u0, x0));
  const Vec4 f1 = as_array(thesis_derivative(p1, u1, x0));
  double jac[4][4];
  thesis_jacobian(p1, u1, x0, jac);
  Vec4 d{}, a{};
  // x0 is steady only to rounding, so a fault that multiplies a whole equation (K, J)
  // leaves δ·(rounding residue) in Δf: read anything below 1e-12 of the equation's
  // largest term as zero. (The smallest real effect, Ripl −10 % on Pmi, is ~1e-8.)
  const double w = std::fabs(x0.w_m);
  const Vec4 term = {p1.K * (std::fabs(f_dcv(p1, u1.Psupl - x0.Pmi)) + p1.Dm * w),
                     p1.K * (std::fabs(f_dcv(p1, x0.Pmo - u1.Ps)) + p1.Dm * w), p1.K * p1.Dp * w,
                     (p1.Dm * std::fabs(x0.Pmi - x0.Pmo) + p1.Dp * std::fabs(x0.Ppp - u1.Pbp)) / p1.J};
  for (std::size_t i = 0; i < 4; ++i) {
    d[i] = f1[i] - f0[i];
    if (std::fabs(d[i]) <= 1e-12 * term[i]) d[i] = 0.0;
    a[i] = std::fabs(d[i]);
  }
  for (ChannelCheck& c : out) {
    c.order0 = -1;
    c.slope0 = kQualZero;
  }
  for (int k = 1; k <= max_order; ++k) {
    for (std::size_t i = 0; i < 4; ++i) {
      const QualSign s = qual_from_value(d[i], 1e-9 * a[i]);
      if (out[i].order0 < 0 && s != kQualZero) {
        out[i].order0 = k;
        out[i].slope0 = s;
      }
    }
    Vec4 dn{}, an{};
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j) {
        dn[i] += jac[i][j] * d[j];
        an[i] += std::fabs(jac[i][j]) * a[j];
      }
    }
    d = dn;
    a = an;
  }
}

/// State of the stiff reference t after starting at x0 under (p, u).
Vec4 reference_at(const ThesisParams<double>& p, const ThesisInputs<double>& u, const ThesisState<double>& x0, double t,
                  const sim::ReferenceTolerances& tol) {
  sim::ThesisReference ref(p, x0, 0.0, tol);
  ref.advance_to(t, u);
  return as_array(ref.state());
}

}  // namespace

std::vector<OperatingCase> default_operating_cases() { return {{"light", 1.6}, {"nominal", 1.0}, {"heavy", 0.65}}; }

std::vector<CrosscheckRow> run_crosscheck(const CrosscheckOptions& opt) {
  sim::ReferenceTolerances tol;
  tol.rel = 1e-10;
  tol.abs_pressure = 1e-4;
  tol.abs_speed = 1e-10;
  std::vector<CrosscheckRow> rows;
  for (const OperatingCase& oc : opt.cases) {
    const ThesisParams<double> p0{};
    ThesisInputs<double> u0{};
    u0.kp *= oc.kp_factor;
    const OperatingPoint op = operating_point(p0, u0);
    const CausalGraph g_nl = thesis_tcg(ValveModel::kNonlinear, op);
    const CausalGraph g_lin = thesis_tcg(ValveModel::kLinearised, op);
    const Vec4 y0 = as_array(op.x);
    const Vec4 r0 = reference_at(p0, u0, op.x, opt.t_early, tol);
    for (const FaultParameter& fp : fault_parameters()) {
      for (int dir : {-1, 1}) {
        CrosscheckRow row;
        row.case_name = oc.name;
        row.fault = fault_name(fp.name, dir);
        row.step = fp.crosscheck_step;
        ThesisParams<double> p1 = p0;
        ThesisInputs<double> u1 = u0;
        scale_parameter(fp.name, 1.0 + dir * fp.crosscheck_step, p1, u1);
        double y1[4];
        if (!steady_outputs(p1, u1, y1)) throw std::runtime_error("crosscheck: no steady state for " + row.fault);
        taylor_signs(p0, u0, p1, u1, op.x, opt.max_order, row.channel);
        const Vec4 r1 = reference_at(p1, u1, op.x, opt.t_early, tol);
        const ForwardResult q =
            forward_qualitative(g_nl, fault_steps(fp.name, dir, ValveModel::kNonlinear), opt.max_order);
        const ForwardResult w =
            forward_weighted(g_nl, fault_steps(fp.name, dir, ValveModel::kNonlinear), opt.max_order);
        const Vec4 dc_sec = linear_steady_change(g_lin, fault_steps(fp.name, dir, ValveModel::kLinearised));
        const Vec4 dc_tan = linear_steady_change(g_nl, fault_steps(fp.name, dir, ValveModel::kNonlinear));
        for (std::size_t c = 0; c < 4; ++c) {
          ChannelCheck& ch = row.channel[c];
          const double scale = std::fabs(y0[c]);
          const double dy = y1[c] - y0[c];
          ch.ss = qual_from_value(dy, opt.ss_zero_rel * scale);
          ch.ss_rel = dy / scale;
          // Resolution of the reference difference: many times its error control.
          const double resolution = 1e3 * ((c == 3 ? tol.abs_speed : tol.abs_pressure) + tol.rel * scale);
          const double dr = r1[c] - r0[c];
          ch.early = std::fabs(dr) > resolution ? qual_from_value(dr, 0.0) : kQualAny;
          ch.tcg_slope = q.channel[c].slope;
          ch.tcg_order = q.channel[c].order;
          ch.tcg_weighted = w.channel[c].slope;
          ch.lin_secant = qual_from_value(dc_sec[c], 1e-12 * scale);
          ch.lin_tangent = qual_from_value(dc_tan[c], 1e-12 * scale);
        }
        rows.push_back(row);
      }
    }
  }
  return rows;
}

}  // namespace hstmon::fdi
