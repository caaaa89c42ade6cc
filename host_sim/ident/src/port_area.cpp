/// @file port_area.cpp
/// Line-through-the-origin fit of Q against √(2|ΔP|/ρ).
#include "hstmon_ident/port_area.hpp"

#include <cmath>

#include "hstmon_ident/least_squares.hpp"

namespace hstmon::ident {

PortAreaFit fit_port_area(const std::string& label, const std::vector<PortSample>& samples, double cd, double rho,
                          double confidence) {
  PortAreaFit f;
  f.label = label;
  if (!(std::isfinite(cd) && cd > 0.0) || !(std::isfinite(rho) && rho > 0.0)) {
    f.error = label + ": Cd and rho must be finite and positive";
    return f;
  }
  if (samples.size() < 2) {
    f.error = label + ": too few samples (" + std::to_string(samples.size()) + "), at least 2 needed";
    return f;
  }
  double sxx = 0.0, sxq = 0.0, sqq = 0.0;
  std::vector<double> x(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const PortSample& s = samples[i];
    if (!std::isfinite(s.dp) || !std::isfinite(s.q)) {
      f.error = label + ": non-finite value in sample " + std::to_string(i + 1);
      return f;
    }
    x[i] = std::copysign(std::sqrt(2.0 * std::fabs(s.dp) / rho), s.dp);
    sxx += x[i] * x[i];
    sxq += x[i] * s.q;
    sqq += s.q * s.q;
  }
  if (!(sxx > 0.0)) {
    f.error = label + ": singular design — every pressure drop is zero, the slope is undetermined";
    return f;
  }
  f.n = samples.size();
  f.cd_area = sxq / sxx;
  double sse = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double r = samples[i].q - f.cd_area * x[i];
    sse += r * r;
  }
  const double dof = static_cast<double>(f.n - 1);
  const double se_b = std::sqrt(sse / dof / sxx);
  const double t = t_quantile(1.0 - confidence, dof);
  f.area = f.cd_area / cd;
  f.area_se = se_b / cd;
  f.ci_lo = f.area - t * f.area_se;
  f.ci_hi = f.area + t * f.area_se;
  f.rms = std::sqrt(sse / static_cast<double>(f.n));
  f.r2 = sqq > 0.0 ? 1.0 - sse / sqq : 0.0;
  if (!(f.cd_area > 0.0)) {
    f.error = label + ": the fitted Cd·A is not positive (flow against the pressure drop?)";
  }
  return f;
}

}  // namespace hstmon::ident
