/// @file param_allowance.cpp
/// The penalised least-squares parameter move of param_allowance.hpp (ridge regression with
/// the prior's unit weight): (JᵀJ + I)·δ = −Jᵀr, K ≤ a few dozen parameters.
#include "param_allowance.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace hstmon::gap::detail {

Allowance parameter_allowance(const std::vector<double>& r, const std::vector<std::vector<double>>& J) {
  Allowance a;
  const std::size_t m = r.size(), K = J.size();
  a.after = r;
  double ss = 0;
  for (double v : r) ss += v * v;
  a.rms_before = m > 0 ? std::sqrt(ss / static_cast<double>(m)) : 0.0;
  a.z = a.rms_before;
  if (m == 0 || K == 0) return a;
  Eigen::MatrixXd A(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(K));
  for (std::size_t k = 0; k < K; ++k) {
    for (std::size_t i = 0; i < m; ++i) {
      const double v = i < J[k].size() ? J[k][i] : 0.0;
      A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = std::isfinite(v) ? v : 0.0;
    }
  }
  const Eigen::Map<const Eigen::VectorXd> rv(r.data(), static_cast<Eigen::Index>(m));
  const Eigen::MatrixXd N = A.transpose() * A + Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(K), static_cast<Eigen::Index>(K));
  const Eigen::VectorXd d = N.ldlt().solve(-A.transpose() * rv);
  if (!d.allFinite()) return a;
  const Eigen::VectorXd after = rv + A * d;
  a.delta.assign(d.data(), d.data() + K);
  a.after.assign(after.data(), after.data() + m);
  a.z = std::sqrt((after.squaredNorm() + d.squaredNorm()) / static_cast<double>(m));
  return a;
}

}  // namespace hstmon::gap::detail
