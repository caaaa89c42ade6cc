#include "hstmon_circuit/healthy_record.hpp"

#include <algorithm>
#include <cmath>

namespace hstmon::circuit_tools {

HealthyRecord::HealthyRecord(const Model& model, const Uncertainty& eps, const double* sigma, unsigned measured,
                             const Config& cfg)
    : model_(model), nominal_(model.params()), measured_(measured), cfg_(cfg), n_ch_(Model::kOutputs) {
  const int n = model.description() != nullptr ? model.description()->n_params : 0;
  for (int k = 0; k < n; ++k) {
    if (eps.rel[k] > 0.0) {
      params_.push_back(k);
      eps_.push_back(eps.rel[k]);
    }
  }
  sigma_.assign(sigma, sigma + n_ch_);
  const auto p = static_cast<Eigen::Index>(params_.size());
  // The prior: each relative error uniform on ±ε, σ² = ε²/3.
  info_ = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double e = eps_[static_cast<std::size_t>(j)];
    info_(j, j) = 3.0 / (e * e);
  }
  score_ = Eigen::VectorXd::Zero(p);
  update_estimate();
  sum_.assign(static_cast<std::size_t>(n_ch_), 0.0);
  n_.assign(static_cast<std::size_t>(n_ch_), 0);
}

void HealthyRecord::begin(const Inputs& u, double t_settled) {
  close();
  open_ = cfg_.on && !params_.empty() && !off_;
  u_ = u;
  t_settled_ = t_settled;
  t_first_ = t_last_ = t_judged_ = 0.0;
  sampled_ = false;
  std::fill(sum_.begin(), sum_.end(), 0.0);
  std::fill(n_.begin(), n_.end(), 0);
  solved_ = false;
  chi2_ = 0.0;
  dof_ = 0;
}

bool HealthyRecord::add(double t, const double* y, unsigned valid) {
  if (!open_ || t < t_settled_) return false;
  bool any = false;
  for (int i = 0; i < n_ch_; ++i) {
    if ((((valid & measured_) >> i) & 1u) == 0 || !std::isfinite(y[i])) continue;
    sum_[static_cast<std::size_t>(i)] += y[i];
    ++n_[static_cast<std::size_t>(i)];
    any = true;
  }
  if (!any) return false;
  if (!sampled_) t_first_ = t;
  sampled_ = true;
  t_last_ = t;
  if (t_last_ - t_first_ < cfg_.test_min || t - t_judged_ < cfg_.test_every) return false;
  t_judged_ = t;
  if (!solved_) {
    solved_ = true;
    point_.ok = solve_point(u_, point_);
  }
  if (!point_.ok) return false;
  return !judge() && windows_ > 0;
}

// The nominal model at u: its steady outputs, their sensitivities (central differences at ±ε
// per uncertain parameter), the bound, and the bend: what the line misses within ±ε, per
// parameter and at the two corners of each channel (every parameter at once at the side
// that moves it up, or down), where a valve that one parameter alone leaves shut may open.
bool HealthyRecord::solve_point(const Inputs& u, Point& p) {
  const auto np = static_cast<Eigen::Index>(params_.size());
  p.s = Eigen::MatrixXd::Zero(n_ch_, np);
  p.bound = Eigen::VectorXd::Zero(n_ch_);
  p.bend = Eigen::VectorXd::Zero(n_ch_);
  model_.set_params(nominal_);
  model_.set_inputs(u);
  typename Model::State xs;
  if (!model_.valid() || !model_.steady_state(xs)) return false;
  const typename Model::Output y0 = model_.outputs(xs);
  p.y0 = Eigen::VectorXd(y0);
  bool ok = true;
  for (Eigen::Index j = 0; ok && j < np; ++j) {
    const int k = params_[static_cast<std::size_t>(j)];
    const double e = eps_[static_cast<std::size_t>(j)];
    typename Model::Params v = nominal_;
    typename Model::Output y[2];
    for (int side = 0; ok && side < 2; ++side) {
      v.v[k] = nominal_.v[k] * (side == 0 ? 1.0 + e : 1.0 - e);
      model_.set_params(v);
      ok = model_.valid() && model_.steady_state(xs);
      if (ok) y[side] = model_.outputs(xs);
    }
    if (!ok) break;
    for (int i = 0; i < n_ch_; ++i) {
      p.s(i, j) = (y[0][i] - y[1][i]) / (2.0 * e);
      p.bound(i) += std::max(std::fabs(y[0][i] - y0[i]), std::fabs(y[1][i] - y0[i]));
      p.bend(i) += std::fabs(y[0][i] + y[1][i] - 2.0 * y0[i]);
    }
  }
  for (int i = 0; ok && i < n_ch_; ++i) {
    for (const double side : {1.0, -1.0}) {
      typename Model::Params v = nominal_;
      double lin = 0.0;
      for (Eigen::Index j = 0; j < np; ++j) {
        const int k = params_[static_cast<std::size_t>(j)];
        const double e = eps_[static_cast<std::size_t>(j)];
        const double sg = (p.s(i, j) >= 0.0 ? 1.0 : -1.0) * side;
        v.v[k] = nominal_.v[k] * (1.0 + sg * e);
        lin += sg * e * p.s(i, j);
      }
      model_.set_params(v);
      if (!model_.valid() || !model_.steady_state(xs)) {
        p.bend(i) += p.bound(i);  // the machine may stall there: the line holds nothing
        continue;
      }
      const typename Model::Output yc = model_.outputs(xs);
      p.bend(i) = std::max(p.bend(i), std::fabs(yc[i] - y0[i] - lin));
    }
  }
  model_.set_params(nominal_);
  return ok;
}

// The open window's χ² against the record's prediction at its point, over the channels it
// has: the prediction's covariance S·Σ·Sᵀ plus each mean's noise and structure share.
bool HealthyRecord::judge() {
  std::vector<int> ch;
  for (int i = 0; i < n_ch_; ++i) {
    if (n_[static_cast<std::size_t>(i)] > 0) ch.push_back(i);
  }
  const auto m = static_cast<Eigen::Index>(ch.size());
  dof_ = static_cast<int>(m);
  if (m == 0) return true;
  Eigen::MatrixXd s(m, info_.cols());
  Eigen::VectorXd innov(m), v(m);
  for (Eigen::Index a = 0; a < m; ++a) {
    const int i = ch[static_cast<std::size_t>(a)];
    s.row(a) = point_.s.row(i);
    v(a) = noise_var(i) + unmodelled_var(point_, i);
    innov(a) = residual(i) - s.row(a).dot(delta_);
  }
  Eigen::MatrixXd cov = s * posterior_.solve(s.transpose());
  cov.diagonal() += v;
  chi2_ = innov.dot(cov.ldlt().solve(innov));
  return chi2_ <= cfg_.k_chi2;
}

// The open window into the record, if it had window_min of samples and is healthy at its end.
void HealthyRecord::close() {
  if (!open_) return;
  open_ = false;
  if (!solved_ || !point_.ok || t_last_ - t_first_ < cfg_.window_min) return;
  if (!judge()) {
    // The first window the model does not describe within its parameters: the machine is
    // not one this picture covers, and nothing learnt from it would hold.
    if (windows_ == 0) off_ = true;
    return;
  }
  for (int i = 0; i < n_ch_; ++i) {
    const auto c = static_cast<std::size_t>(i);
    if (n_[c] == 0) continue;
    const double w = 1.0 / (noise_var(i) + unmodelled_var(point_, i));
    const Eigen::VectorXd row = point_.s.row(i).transpose();
    info_.noalias() += w * row * row.transpose();
    score_.noalias() += w * residual(i) * row;
  }
  ++windows_;
  update_estimate();
}

// The estimate changes only when a window enters the record: factor it then, once.
void HealthyRecord::update_estimate() {
  posterior_.compute(info_);
  delta_ = posterior_.solve(score_);
}

double HealthyRecord::noise_var(int i) const {
  const auto c = static_cast<std::size_t>(i);
  return sigma_[c] * sigma_[c] / std::min(static_cast<double>(n_[c]), cfg_.n_cap);
}

double HealthyRecord::unmodelled_var(const Point& p, int i) const {
  const double structure = cfg_.k_struct * p.bound(i);
  return structure * structure + p.bend(i) * p.bend(i);
}

double HealthyRecord::residual(int i) const {
  const auto c = static_cast<std::size_t>(i);
  return sum_[c] / static_cast<double>(n_[c]) - point_.y0(i);
}

unsigned HealthyRecord::predicted(double* mean, double* var) const {
  if (!open_ || !point_.ok) return 0u;
  return predict(point_, mean, var);
}

unsigned HealthyRecord::expected_at(const Inputs& u, double* mean, double* var) {
  if (windows_ == 0 || off_) return 0u;
  Point p;
  if (!solve_point(u, p)) return 0u;
  return predict(p, mean, var);
}

unsigned HealthyRecord::predict(const Point& p, double* mean, double* var) const {
  if (windows_ == 0 || off_) return 0u;
  unsigned have = 0;
  for (int i = 0; i < n_ch_; ++i) {
    if (((measured_ >> i) & 1u) == 0) continue;
    const Eigen::VectorXd row = p.s.row(i).transpose();
    mean[i] = row.dot(delta_);
    var[i] = row.dot(posterior_.solve(row)) + unmodelled_var(p, i);
    have |= 1u << i;
  }
  return have;
}

}  // namespace hstmon::circuit_tools
