/// @file least_squares.cpp
/// Eigen Levenberg–Marquardt driver and the linearised statistics at its optimum.
/// This target is compiled with EIGEN_NO_MALLOC undefined (see CMakeLists.txt).
#include "hstmon_ident/least_squares.hpp"

#include <Eigen/Dense>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

namespace hstmon::ident {

namespace {

// Eigen functor around a ResidualFn. A point where the model fails gets a huge, finite
// residual, so LM's step control rejects it and shrinks the trust region.
struct Functor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const ResidualFn* f = nullptr;
  Eigen::Index n = 0;
  Eigen::Index m = 0;
  int* evaluations = nullptr;

  Eigen::Index inputs() const { return n; }
  Eigen::Index values() const { return m; }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
    ++*evaluations;
    std::vector<double> xv(x.data(), x.data() + x.size());
    std::vector<double> r(static_cast<std::size_t>(m), 0.0);
    bool ok = (*f)(xv, r);
    for (double v : r) ok = ok && std::isfinite(v);
    for (Eigen::Index i = 0; i < m; ++i) fvec[i] = ok ? r[static_cast<std::size_t>(i)] : 1e150;
    return 0;
  }
};

const char* status_text(int s) {
  switch (s) {
    case Eigen::LevenbergMarquardtSpace::ImproperInputParameters: return "improper input parameters";
    case Eigen::LevenbergMarquardtSpace::RelativeReductionTooSmall: return "converged (relative reduction of the sum of squares below tolerance)";
    case Eigen::LevenbergMarquardtSpace::RelativeErrorTooSmall: return "converged (relative change of the parameters below tolerance)";
    case Eigen::LevenbergMarquardtSpace::RelativeErrorAndReductionTooSmall: return "converged (sum of squares and parameters)";
    case Eigen::LevenbergMarquardtSpace::CosinusTooSmall: return "converged (residuals orthogonal to the Jacobian)";
    case Eigen::LevenbergMarquardtSpace::TooManyFunctionEvaluation: return "stopped: too many function evaluations";
    case Eigen::LevenbergMarquardtSpace::FtolTooSmall: return "converged (no further reduction possible)";
    case Eigen::LevenbergMarquardtSpace::XtolTooSmall: return "converged (no further parameter improvement possible)";
    case Eigen::LevenbergMarquardtSpace::GtolTooSmall: return "converged (gradient orthogonal)";
    case Eigen::LevenbergMarquardtSpace::UserAsked: return "stopped by the residual function";
    default: return "not run";
  }
}

}  // namespace

namespace {

// Eigen functor with the caller's Jacobian (JacobianFn) instead of numerical differences.
struct JacobianFunctor : Functor {
  const JacobianFn* df_fn = nullptr;
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& fjac) const {
    std::vector<double> xv(x.data(), x.data() + x.size());
    DenseMatrix jac;
    if (!(*df_fn)(xv, jac) || jac.rows != static_cast<std::size_t>(m) || jac.cols != static_cast<std::size_t>(n)) {
      return -1;  // Eigen stops with UserAsked: no step without a Jacobian
    }
    for (Eigen::Index i = 0; i < m; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) fjac(i, j) = jac(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
    }
    return 0;
  }
};

// The LM run shared by both drivers: x0 → res, with Eigen's stop reason in words.
template <class Lm>
void run_lm(Lm& lm, const ResidualFn& f, std::size_t m, const LmOptions& options, LmResult& res) {
  lm.parameters.maxfev = options.max_evaluations;
  lm.parameters.ftol = options.tolerance;
  lm.parameters.xtol = options.tolerance;
  Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(res.x.data(), static_cast<Eigen::Index>(res.x.size()));
  const auto status = lm.minimize(x);
  res.status = static_cast<int>(status);
  res.status_text = status_text(res.status);
  switch (status) {
    case Eigen::LevenbergMarquardtSpace::RelativeReductionTooSmall:
    case Eigen::LevenbergMarquardtSpace::RelativeErrorTooSmall:
    case Eigen::LevenbergMarquardtSpace::RelativeErrorAndReductionTooSmall:
    case Eigen::LevenbergMarquardtSpace::CosinusTooSmall:
    case Eigen::LevenbergMarquardtSpace::FtolTooSmall:
    case Eigen::LevenbergMarquardtSpace::XtolTooSmall:
    case Eigen::LevenbergMarquardtSpace::GtolTooSmall:
      res.converged = true;
      break;
    default:
      res.converged = false;
  }
  res.x.assign(x.data(), x.data() + x.size());
  res.residuals.assign(m, 0.0);
  const bool ok = f(res.x, res.residuals);
  res.finite = ok;
  for (double v : res.x) res.finite = res.finite && std::isfinite(v);
  res.ssr = 0.0;
  for (double v : res.residuals) {
    res.finite = res.finite && std::isfinite(v);
    res.ssr += v * v;
  }
}

// False (with res saying why) when there are fewer residuals than parameters.
bool proper(std::size_t m, const std::vector<double>& x0, LmResult& res) {
  res.x = x0;
  if (!x0.empty() && m >= x0.size()) return true;
  res.status = Eigen::LevenbergMarquardtSpace::ImproperInputParameters;
  res.status_text = "fewer residuals than parameters";
  return false;
}

}  // namespace

LmResult levenberg_marquardt(const ResidualFn& f, std::size_t m, std::vector<double> x0, const LmOptions& options) {
  LmResult res;
  if (!proper(m, x0, res)) return res;
  Functor fun;
  fun.f = &f;
  fun.n = static_cast<Eigen::Index>(x0.size());
  fun.m = static_cast<Eigen::Index>(m);
  fun.evaluations = &res.evaluations;
  Eigen::NumericalDiff<Functor, Eigen::Central> diff(fun);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Functor, Eigen::Central>, double> lm(diff);
  run_lm(lm, f, m, options, res);
  return res;
}

LmResult levenberg_marquardt(const ResidualFn& f, const JacobianFn& df, std::size_t m, std::vector<double> x0,
                             const LmOptions& options) {
  LmResult res;
  if (!proper(m, x0, res)) return res;
  JacobianFunctor fun;
  fun.f = &f;
  fun.df_fn = &df;
  fun.n = static_cast<Eigen::Index>(x0.size());
  fun.m = static_cast<Eigen::Index>(m);
  fun.evaluations = &res.evaluations;
  Eigen::LevenbergMarquardt<JacobianFunctor, double> lm(fun);
  run_lm(lm, f, m, options, res);
  return res;
}

bool central_jacobian(const ResidualFn& f, std::size_t m, const std::vector<double>& x,
                      const std::vector<double>& steps, DenseMatrix& jac) {
  const std::size_t n = x.size();
  jac = DenseMatrix(m, n);
  std::vector<double> rp(m), rm(m);
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> xp = x, xm = x;
    xp[j] += steps[j];
    xm[j] -= steps[j];
    if (!f(xp, rp) || !f(xm, rm)) return false;
    for (std::size_t i = 0; i < m; ++i) {
      jac(i, j) = (rp[i] - rm[i]) / (2.0 * steps[j]);
      if (!std::isfinite(jac(i, j))) return false;
    }
  }
  return true;
}

LinearStats linear_stats(const DenseMatrix& jac, double s2) {
  LinearStats st;
  const auto m = static_cast<Eigen::Index>(jac.rows);
  const auto n = static_cast<Eigen::Index>(jac.cols);
  Eigen::MatrixXd J(m, n);
  for (Eigen::Index i = 0; i < m; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) J(i, j) = jac(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
  }
  Eigen::VectorXd norms = J.colwise().norm().transpose();
  st.column_norms.assign(norms.data(), norms.data() + n);
  Eigen::VectorXd scale(n);
  for (Eigen::Index j = 0; j < n; ++j) scale[j] = norms[j] > 0.0 ? 1.0 / norms[j] : 1.0;
  const Eigen::MatrixXd Js = J * scale.asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  st.singular_values.assign(sv.data(), sv.data() + sv.size());
  const double smax = sv.size() > 0 ? sv[0] : 0.0;
  st.rank = 0;
  for (Eigen::Index k = 0; k < sv.size(); ++k) {
    if (sv[k] > 1e-10 * smax && norms[k] >= 0.0) ++st.rank;
  }
  // A zero column is rank deficiency even when the SVD puts it at a unit singular value.
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!(norms[j] > 0.0) && st.rank > 0) --st.rank;
  }
  const double smin = sv.size() > 0 ? sv[sv.size() - 1] : 0.0;
  st.condition = (st.rank == static_cast<std::size_t>(n) && smin > 0.0) ? smax / smin
                                                                        : std::numeric_limits<double>::infinity();
  if (n > 0) {
    const Eigen::VectorXd v = svd.matrixV().col(n - 1);
    st.null_direction.assign(v.data(), v.data() + n);
  }
  // Covariance: s²·D·V·Σ⁻²·Vᵀ·D (D = column scaling); directions with σ ≈ 0 get ∞.
  const double inf = std::numeric_limits<double>::infinity();
  st.covariance = DenseMatrix(static_cast<std::size_t>(n), static_cast<std::size_t>(n));
  st.se.assign(static_cast<std::size_t>(n), 0.0);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(n, n);
  std::vector<bool> infinite(static_cast<std::size_t>(n), false);
  for (Eigen::Index k = 0; k < sv.size(); ++k) {
    const Eigen::VectorXd v = svd.matrixV().col(k);
    if (sv[k] > 1e-10 * smax) {
      cov += (s2 / (sv[k] * sv[k])) * (v * v.transpose());
    } else {
      for (Eigen::Index j = 0; j < n; ++j) {
        if (std::fabs(v[j]) > 1e-8) infinite[static_cast<std::size_t>(j)] = true;
      }
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!(norms[j] > 0.0)) infinite[static_cast<std::size_t>(j)] = true;
  }
  cov = scale.asDiagonal() * cov * scale.asDiagonal();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const bool inf_ij = infinite[static_cast<std::size_t>(i)] || infinite[static_cast<std::size_t>(j)];
      st.covariance(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) = inf_ij ? inf : cov(i, j);
    }
    st.se[static_cast<std::size_t>(i)] = infinite[static_cast<std::size_t>(i)] ? inf : std::sqrt(std::max(0.0, cov(i, i)));
  }
  st.correlation = DenseMatrix(static_cast<std::size_t>(n), static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
      const double d = st.se[i] * st.se[j];
      st.correlation(i, j) = (std::isfinite(d) && d > 0.0) ? st.covariance(i, j) / d
                                                             : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return st;
}

double t_quantile(double alpha, double dof) {
  if (!(dof > 0.0) || !(alpha > 0.0 && alpha < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  const boost::math::students_t_distribution<double> t(dof);
  return boost::math::quantile(t, 1.0 - 0.5 * alpha);
}

}  // namespace hstmon::ident
