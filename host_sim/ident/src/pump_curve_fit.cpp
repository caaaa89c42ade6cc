/// @file pump_curve_fit.cpp
/// Levenberg–Marquardt fit of the 3-region pump curve.
#include "hstmon_ident/pump_curve_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hstmon::ident {

namespace {

PumpCurveParams<double> from_x(const std::vector<double>& x) {
  PumpCurveParams<double> p;
  p.Q0 = std::exp(x[0]);
  p.R = std::exp(x[1]);
  p.Pc = std::exp(x[2]);
  p.Pk = p.Pc + std::exp(x[3]);
  p.Pmax = p.Pk + std::exp(x[4]);
  return p;
}

std::vector<double> to_x(const PumpCurveParams<double>& p) {
  return {std::log(p.Q0), std::log(p.R), std::log(p.Pc), std::log(p.Pk - p.Pc), std::log(p.Pmax - p.Pk)};
}

}  // namespace

const std::array<const char*, 5>& pump_curve_param_names() {
  static const std::array<const char*, 5> names{"Q0", "R", "Pc", "Pk", "Pmax"};
  return names;
}

PumpCurveFit fit_pump_curve(const std::vector<FlowPressureSample>& samples,
                            const std::optional<PumpCurveParams<double>>& start, double confidence) {
  PumpCurveFit f;
  f.n = samples.size();
  if (samples.size() < 8) {
    f.error = fmt::format("pump curve: too few samples ({}), at least 8 needed for 5 parameters", samples.size());
    return f;
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples[i].p) || !std::isfinite(samples[i].q)) {
      f.error = fmt::format("pump curve: non-finite value in sample {}", i + 1);
      return f;
    }
    if (samples[i].p < 0.0) {
      f.error = fmt::format("pump curve: negative pressure in sample {}", i + 1);
      return f;
    }
  }
  std::vector<FlowPressureSample> s = samples;
  std::sort(s.begin(), s.end(), [](const auto& a, const auto& b) { return a.p < b.p; });
  const double p_hi = s.back().p;
  if (!(p_hi > s.front().p)) {
    f.error = "pump curve: singular design — every sample is at the same pressure";
    return f;
  }

  // Residuals Q_model − Q, scaled by the largest flow so that LM sees numbers of order 1.
  double q_scale = 0.0;
  for (const auto& v : s) q_scale = std::max(q_scale, std::fabs(v.q));
  if (!(q_scale > 0.0)) {
    f.error = "pump curve: every flow is zero";
    return f;
  }
  const ResidualFn res = [&s, q_scale](const std::vector<double>& x, std::vector<double>& r) {
    PumpCurve<double> c;
    if (!c.make(from_x(x))) return false;
    for (std::size_t i = 0; i < s.size(); ++i) r[i] = (c.flow(s[i].p) - s[i].q) / q_scale;
    return true;
  };

  // Start values.
  std::vector<PumpCurveParams<double>> starts;
  if (start) {
    starts.push_back(*start);
  } else {
    // Region 1: line through the lower half.
    const std::size_t h = std::max<std::size_t>(2, s.size() / 2);
    double pm = 0.0, qm = 0.0;
    for (std::size_t i = 0; i < h; ++i) {
      pm += s[i].p;
      qm += s[i].q;
    }
    pm /= static_cast<double>(h);
    qm /= static_cast<double>(h);
    double spp = 0.0, spq = 0.0;
    for (std::size_t i = 0; i < h; ++i) {
      spp += (s[i].p - pm) * (s[i].p - pm);
      spq += (s[i].p - pm) * (s[i].q - qm);
    }
    const double slope = spp > 0.0 ? spq / spp : 0.0;
    const double q0 = qm - slope * pm;
    const double R = slope < 0.0 ? -1.0 / slope : 1e3 * p_hi / std::max(q0, 1e-12);
    // Dead head: where the flow falls below 2 % of Q0, else a little beyond the last sample.
    double pmax = 1.02 * p_hi;
    for (const auto& v : s) {
      if (v.q < 0.02 * q0) {
        pmax = v.p;
        break;
      }
    }
    for (double fc : {0.70, 0.80, 0.88}) {
      for (double fk : {0.93, 0.97}) {
        PumpCurveParams<double> p;
        p.Q0 = std::max(q0, 1e-12);
        p.R = R;
        p.Pc = fc * pmax;
        p.Pk = fk * pmax;
        p.Pmax = pmax;
        starts.push_back(p);
      }
    }
  }
  LmResult best;
  bool have = false;
  for (const auto& p0 : starts) {
    PumpCurve<double> c;
    if (!c.make(p0)) continue;
    LmResult lm = levenberg_marquardt(res, s.size(), to_x(p0));
    if (lm.finite && (!have || lm.ssr < best.ssr)) {
      best = lm;
      have = true;
    }
  }
  if (!have) {
    f.error = "pump curve: no start value gives a valid curve (data not shaped like a compensated pump?)";
    return f;
  }
  f.lm_status = best.status_text;
  f.params = from_x(best.x);
  f.rms = q_scale * std::sqrt(best.ssr / static_cast<double>(s.size()));
  const double dof = static_cast<double>(s.size()) - 5.0;
  DenseMatrix J;
  if (!central_jacobian(res, s.size(), best.x, std::vector<double>(5, 1e-6), J)) {
    f.error = "pump curve: the curve cannot be evaluated around the estimate";
    return f;
  }
  const LinearStats st = linear_stats(J, best.ssr / dof);
  f.condition = st.condition;
  f.correlation = st.correlation;
  const double t = t_quantile(1.0 - confidence, dof);
  // Interval of each physical number: Q0, R, Pc directly from their log; Pk = Pc + e^x3,
  // Pmax = Pk + e^x4 by the delta method on the covariance.
  const std::array<double, 5> v{f.params.Q0, f.params.R, f.params.Pc, f.params.Pk, f.params.Pmax};
  const double e3 = std::exp(best.x[3]), e4 = std::exp(best.x[4]);
  const std::array<std::array<double, 5>, 5> grad{{{v[0], 0, 0, 0, 0},
                                                   {0, v[1], 0, 0, 0},
                                                   {0, 0, v[2], 0, 0},
                                                   {0, 0, v[2], e3, 0},
                                                   {0, 0, v[2], e3, e4}}};
  for (std::size_t k = 0; k < 5; ++k) {
    double var = 0.0;
    bool finite = true;
    for (std::size_t i = 0; i < 5; ++i) {
      for (std::size_t j = 0; j < 5; ++j) {
        if (grad[k][i] == 0.0 || grad[k][j] == 0.0) continue;
        const double c = st.covariance(i, j);
        if (!std::isfinite(c)) finite = false;
        var += grad[k][i] * grad[k][j] * c;
      }
    }
    f.se[k] = finite ? std::sqrt(std::max(var, 0.0)) : std::numeric_limits<double>::infinity();
    f.ci_lo[k] = v[k] - t * f.se[k];
    f.ci_hi[k] = v[k] + t * f.se[k];
    f.identifiable[k] = std::isfinite(f.se[k]) && t * f.se[k] < v[k];
  }
  return f;
}

}  // namespace hstmon::ident
