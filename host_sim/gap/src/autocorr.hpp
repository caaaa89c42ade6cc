#pragma once
/// @file autocorr.hpp
/// Integrated autocorrelation time τ of a residual series, by batch means: τ ≈ L·var(batch
/// means)/var(r) for batches of L samples (O(n); 20 batches). Residuals of a model error
/// are smooth, not white: n samples carry the information of n/τ independent ones (the
/// effective sample size), and standard errors from the linearised covariance are scaled
/// by √τ.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace hstmon::gap::detail {

inline double autocorrelation_time(const double* r, std::size_t n) {
  constexpr std::size_t kBatches = 20;
  if (n < 4 * kBatches) return 1.0;
  const std::size_t L = n / kBatches;
  double mean = 0;
  for (std::size_t i = 0; i < L * kBatches; ++i) mean += r[i];
  mean /= static_cast<double>(L * kBatches);
  double var = 0, var_b = 0;
  for (std::size_t b = 0; b < kBatches; ++b) {
    double s = 0;
    for (std::size_t i = b * L; i < (b + 1) * L; ++i) {
      s += r[i] - mean;
      var += (r[i] - mean) * (r[i] - mean);
    }
    const double bm = s / static_cast<double>(L);
    var_b += bm * bm;
  }
  var /= static_cast<double>(L * kBatches - 1);
  var_b /= static_cast<double>(kBatches - 1);
  if (!(var > 0)) return 1.0;
  return std::clamp(static_cast<double>(L) * var_b / var, 1.0, static_cast<double>(L));
}

/// τ of several series laid end to end (e.g. channel-major residuals), each of length len,
/// weighted by each series' sum of squares.
inline double autocorrelation_time_blocks(const std::vector<double>& r, std::size_t len) {
  if (len == 0 || r.size() < len) return 1.0;
  double num = 0, den = 0;
  for (std::size_t b = 0; b + len <= r.size(); b += len) {
    double ss = 0;
    for (std::size_t i = b; i < b + len; ++i) ss += r[i] * r[i];
    num += ss * autocorrelation_time(r.data() + b, len);
    den += ss;
  }
  return den > 0 ? num / den : 1.0;
}

}  // namespace hstmon::gap::detail
