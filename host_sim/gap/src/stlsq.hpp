#pragma once
/// @file stlsq.hpp
/// The regression core behind a discovered term (discover.cpp for the thesis rig,
/// circuit_discover.cpp for any circuit; docs/gap.md, "Beyond the library"): given the
/// candidate terms' columns on the fit log and on the check log, each row already weighted
/// by 1/(its propagated noise), it
///  1. drops candidates (nearly) collinear with earlier ones on the fit log (Gram–Schmidt
///     on the normalised columns, residual norm < 1e-3), so a candidate's place in the list
///     is its priority;
///  2. builds a pool of sparse models: every single term, and sequentially thresholded
///     least squares on the normalised columns for thresholds 0.01 … 0.5 of the largest
///     coefficient, each fitted on the fit log;
///  3. judges them on the check log: the sparsest model within 10 % of the best achievable
///     reduction of the check log's RMS;
///  4. gives standard errors from s²(XᵀX)⁻¹ scaled by the fit residuals' autocorrelation
///     time (effective sample size n/τ).
#include <Eigen/Dense>
#include <cstddef>
#include <optional>
#include <vector>

#include "hstmon_gap/shrink.hpp"

namespace hstmon::gap::detail {

/// The chosen sparse model.
struct StlsqChoice {
  std::vector<int> active;                           ///< candidate columns, largest contribution on the fit log first
  std::vector<double> coefficient;                   ///< per active term, unweighted units of its candidate
  std::vector<double> std_error;                     ///< per active term, with the autocorrelation time
  double rms_w_before_fit = 0, rms_w_after_fit = 0;  ///< weighted RMS of the target, fit log
  double rms_w_before_check = 0, rms_w_after_check = 0;  ///< the same, check log
};

/// Chooses the model (see the file comment). X, y: the fit log's weighted candidate
/// columns and target; Xc, yc: the check log's (same columns).
/// @return nullopt when no candidate survives or nothing reduces the check log's RMS
std::optional<StlsqChoice> stlsq_choose(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const Eigen::MatrixXd& Xc,
                                        const Eigen::VectorXd& yc);

/// stlsq_choose on two logs' data: design(log, X, y) fills one log's weighted columns and target.
template <class Log, class Design>
std::optional<StlsqChoice> stlsq_choose_on(const Log& fit, const Log& check, Design&& design) {
  Eigen::MatrixXd X, Xc;
  Eigen::VectorXd y, yc;
  design(fit, X, y);
  design(check, Xc, yc);
  return stlsq_choose(X, y, Xc, yc);
}

/// A discovery's judge figures from the choice: the check log's RMS/noise before and after,
/// and the share above noise removed on each log (shrink.hpp).
template <class Discovery>
void take_judgement(const StlsqChoice& ch, Discovery& d) {
  d.rms_w_before_check = ch.rms_w_before_check;
  d.rms_w_after_check = ch.rms_w_after_check;
  d.shrink_check = shrink(ch.rms_w_before_check, ch.rms_w_after_check);
  d.shrink_fit = shrink(ch.rms_w_before_fit, ch.rms_w_after_fit);
}

}  // namespace hstmon::gap::detail
