/// @file stlsq.cpp
/// Collinearity drop, STLSQ pool, check-log judge and standard errors (stlsq.hpp).
#include "stlsq.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "autocorr.hpp"

namespace hstmon::gap::detail {

namespace {

Eigen::VectorXd solve(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<int>& active) {
  Eigen::MatrixXd Xa(X.rows(), static_cast<Eigen::Index>(active.size()));
  for (std::size_t j = 0; j < active.size(); ++j) Xa.col(static_cast<Eigen::Index>(j)) = X.col(active[j]);
  return Xa.colPivHouseholderQr().solve(y);
}

double rms_after(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<int>& active,
                 const Eigen::VectorXd& beta) {
  Eigen::VectorXd r = y;
  for (std::size_t j = 0; j < active.size(); ++j) r -= beta[static_cast<Eigen::Index>(j)] * X.col(active[j]);
  return std::sqrt(r.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, y.size())));
}

// Candidates not (nearly) collinear with earlier ones on the fit log (Gram–Schmidt on the
// normalised columns): a constant Pbp makes p_pp - Pbp the constant plus p_pp.
std::vector<int> independent_columns(const Eigen::MatrixXd& X) {
  std::vector<int> keep;
  std::vector<Eigen::VectorXd> basis;
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    Eigen::VectorXd v = X.col(j);
    const double n0 = v.norm();
    if (!(n0 > 0) || !std::isfinite(n0)) continue;
    v /= n0;
    for (const auto& q : basis) v -= q.dot(v) * q;
    const double n1 = v.norm();
    if (n1 < 1e-3) continue;
    basis.push_back(v / n1);
    keep.push_back(static_cast<int>(j));
  }
  return keep;
}

// Model pool: every single term, and the STLSQ path over thresholds on the normalised
// columns (thresholds compare contributions).
std::vector<std::vector<int>> model_pool(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                                         const std::vector<int>& keep) {
  Eigen::VectorXd scale(X.cols());
  for (Eigen::Index j = 0; j < X.cols(); ++j) scale[j] = std::max(X.col(j).norm(), 1e-300);
  const Eigen::MatrixXd Xn = X * scale.cwiseInverse().asDiagonal();
  std::vector<std::vector<int>> pool;
  auto add = [&](std::vector<int> s) {
    std::sort(s.begin(), s.end());
    if (!s.empty() && std::find(pool.begin(), pool.end(), s) == pool.end()) pool.push_back(std::move(s));
  };
  for (int j : keep) add({j});
  for (double lambda : {0.01, 0.03, 0.1, 0.2, 0.35, 0.5}) {
    std::vector<int> act = keep;
    for (int it = 0; it < 20; ++it) {
      const Eigen::VectorXd xi = solve(Xn, y, act);
      const double mx = xi.cwiseAbs().maxCoeff();
      std::vector<int> next;
      for (std::size_t j = 0; j < act.size(); ++j) {
        if (std::fabs(xi[static_cast<Eigen::Index>(j)]) >= lambda * mx) next.push_back(act[j]);
      }
      if (next == act) break;
      act = next;
    }
    add(act);
  }
  return pool;
}

}  // namespace

std::optional<StlsqChoice> stlsq_choose(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::MatrixXd& Xc,
                                        const Eigen::VectorXd& yc) {
  const std::vector<int> keep = independent_columns(X);
  if (keep.empty()) return std::nullopt;
  const std::vector<std::vector<int>> pool = model_pool(X, y, keep);
  // Judge on the check log: the sparsest model within 10 % of the best achievable shrink.
  const double before = std::sqrt(yc.squaredNorm() / static_cast<double>(yc.size()));
  std::vector<double> after(pool.size());
  std::vector<Eigen::VectorXd> betas(pool.size());
  double best = before;
  for (std::size_t m = 0; m < pool.size(); ++m) {
    betas[m] = solve(X, y, pool[m]);
    after[m] = rms_after(Xc, yc, pool[m], betas[m]);
    best = std::min(best, after[m]);
  }
  if (!(best < before)) return std::nullopt;
  std::size_t pick = pool.size();
  for (std::size_t m = 0; m < pool.size(); ++m) {
    if (after[m] > best + 0.1 * (before - best)) continue;
    if (pick == pool.size() || pool[m].size() < pool[pick].size() ||
        (pool[m].size() == pool[pick].size() && after[m] < after[pick])) {
      pick = m;
    }
  }
  const std::vector<int>& act = pool[pick];
  const Eigen::VectorXd& beta = betas[pick];
  // Standard errors: s²·(XᵀX)⁻¹ on the weighted rows, scaled by the residuals'
  // autocorrelation time (effective sample size n/τ).
  Eigen::MatrixXd Xa(X.rows(), static_cast<Eigen::Index>(act.size()));
  for (std::size_t j = 0; j < act.size(); ++j) Xa.col(static_cast<Eigen::Index>(j)) = X.col(act[j]);
  const Eigen::VectorXd res = y - Xa * beta;
  const double dof = std::max(1.0, static_cast<double>(X.rows()) - static_cast<double>(act.size()));
  const double tau = autocorrelation_time(res.data(), static_cast<std::size_t>(res.size()));
  const Eigen::MatrixXd cov = (Xa.transpose() * Xa).inverse() * (res.squaredNorm() / dof * tau);
  StlsqChoice out;
  out.rms_w_before_check = before;
  out.rms_w_after_check = after[pick];
  out.rms_w_before_fit = std::sqrt(y.squaredNorm() / static_cast<double>(y.size()));
  out.rms_w_after_fit = std::sqrt(res.squaredNorm() / static_cast<double>(y.size()));
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t j = 0; j < act.size(); ++j) {
    order.emplace_back(std::fabs(beta[static_cast<Eigen::Index>(j)]) * Xa.col(static_cast<Eigen::Index>(j)).norm(), j);
  }
  std::sort(order.rbegin(), order.rend());
  for (const auto& [contrib, j] : order) {
    const auto ji = static_cast<Eigen::Index>(j);
    out.active.push_back(act[j]);
    out.coefficient.push_back(beta[ji]);
    out.std_error.push_back(std::sqrt(std::max(0.0, cov(ji, ji))));
  }
  return out;
}

}  // namespace hstmon::gap::detail
