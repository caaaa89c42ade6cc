#pragma once
/// @file least_squares.hpp
/// Nonlinear least squares for the identification tools: Eigen's Levenberg–Marquardt
/// (unsupported/Eigen/NonLinearOptimization, central-difference Jacobian) and the
/// linearised statistics at the optimum — covariance s²·(JᵀJ)⁻¹, standard errors, Student-t
/// intervals, correlations, rank and condition of the column-scaled Jacobian.
///
/// The public types are std::vector based: lib/ defines EIGEN_NO_MALLOC for its users, so
/// dynamic Eigen matrices stay inside this library's sources.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace hstmon::ident {

/// Dense row-major matrix of doubles (no arithmetic; a container for results).
struct DenseMatrix {
  std::size_t rows = 0;      ///< number of rows
  std::size_t cols = 0;      ///< number of columns
  std::vector<double> data;  ///< rows·cols entries, row-major
  DenseMatrix() = default;
  /// rows × cols matrix filled with `fill`.
  DenseMatrix(std::size_t r, std::size_t c, double fill = 0.0) : rows(r), cols(c), data(r * c, fill) {}
  /// Entry (i, j).
  double& operator()(std::size_t i, std::size_t j) { return data[i * cols + j]; }
  /// Entry (i, j).
  double operator()(std::size_t i, std::size_t j) const { return data[i * cols + j]; }
};

/// Residual function r(x): fills r (its size fixed by the caller) from the parameters x.
/// Returns false where the model cannot be evaluated; the solver then treats the point as
/// infinitely bad (the step is rejected).
using ResidualFn = std::function<bool(const std::vector<double>& x, std::vector<double>& r)>;

/// Settings of levenberg_marquardt.
struct LmOptions {
  int max_evaluations = 4000;  ///< residual evaluations allowed (Jacobian columns included)
  double tolerance = 1e-12;    ///< relative tolerance on the sum of squares and on x (Eigen's ftol, xtol)
};

/// Outcome of levenberg_marquardt.
struct LmResult {
  std::vector<double> x;          ///< parameters at the end
  std::vector<double> residuals;  ///< r(x)
  double ssr = 0.0;               ///< Σ r² at x
  int status = 0;                 ///< Eigen's LevenbergMarquardtSpace::Status
  std::string status_text;        ///< status in words
  int evaluations = 0;            ///< residual evaluations used
  bool converged = false;         ///< true for a tolerance-based stop (status 1, 2, 3, 4, 6, 7, 8)
  bool finite = false;            ///< true when x and r(x) are finite
};

/// Minimises Σ r(x)² from x0 with Eigen's LevenbergMarquardt on a central-difference
/// Jacobian (Eigen::NumericalDiff, Central).
/// @param f   residual function
/// @param m   number of residuals (≥ x0.size())
/// @param x0  start; parameters should be of order 1–100 (e.g. logarithms)
LmResult levenberg_marquardt(const ResidualFn& f, std::size_t m, std::vector<double> x0,
                             const LmOptions& options = {});

/// Jacobian function: fills jac (m × n, ∂r_i/∂x_j) at x. Returns false where the model
/// cannot be evaluated (the solver then stops).
using JacobianFn = std::function<bool(const std::vector<double>& x, DenseMatrix& jac)>;

/// As above with the caller's Jacobian: for problems whose structure makes it cheaper than
/// n central differences of the whole residual (block-sparse ones, e.g. one unknown per
/// operating point that moves only that point's residuals).
/// @param df  Jacobian of f
LmResult levenberg_marquardt(const ResidualFn& f, const JacobianFn& df, std::size_t m, std::vector<double> x0,
                             const LmOptions& options = {});

/// Central-difference Jacobian m × n of f at x, column j with step steps[j] (same units
/// as x[j]). Returns false if f fails at any probe.
bool central_jacobian(const ResidualFn& f, std::size_t m, const std::vector<double>& x,
                      const std::vector<double>& steps, DenseMatrix& jac);

/// Linearised statistics of least-squares estimates.
struct LinearStats {
  DenseMatrix covariance;             ///< s²·(JᵀJ)⁺ [units of x squared]
  std::vector<double> se;             ///< √diag(covariance) (∞ for a rank-deficient direction)
  DenseMatrix correlation;            ///< covariance scaled to unit diagonal (NaN where se is ∞ or 0)
  std::vector<double> singular_values;  ///< of J with unit-norm columns, descending [-]
  double condition = 0.0;             ///< largest / smallest singular value (∞ if rank deficient)
  std::size_t rank = 0;               ///< singular values above 1e-10 × the largest
  std::vector<double> null_direction; ///< right singular vector of the smallest singular value (column-scaled)
  std::vector<double> column_norms;   ///< ‖J(:, j)‖ [residual units per unit of x]
};

/// Statistics of the estimates from the Jacobian J of the residuals at the optimum and the
/// residual variance s² (Σr²/dof). Columns are scaled to unit norm before the SVD so the
/// condition number reflects the design, not the parameter units.
LinearStats linear_stats(const DenseMatrix& jac, double s2);

/// Two-sided Student-t quantile t(1 − α/2, dof) [-], e.g. 1.96 for α = 0.05 and large dof.
double t_quantile(double alpha, double dof);

}  // namespace hstmon::ident
