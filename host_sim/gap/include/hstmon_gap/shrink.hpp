#pragma once
/// @file shrink.hpp
/// How far a gap shrinks: the one definition behind every shrink the gap tool reports.
#include <cmath>

namespace hstmon::gap {

/// Share of a log's systematic gap that a model change removes [-], from the residual's
/// RMS before and after it in units of the sensor noise (pooled over channels, or of one
/// equation's imbalance): 1 − e(after)/e(before) with e(r) = √max(r² − 1, 0), the RMS
/// above the noise. A residual of noise alone has r ≈ 1 and is no gap: a plain 1 − a/b
/// would cap the shrink of an effect that leaves only noise at 1 − 1/b (0.69 for a gap
/// 3.3× the noise) and read the noise as gap left. Ordered as 1 − a/b for one `before`
/// (both fall as `after` grows). Where `before` is not above the noise there is no gap to
/// share out and 1 − a/b is returned.
inline double shrink(double rms_w_before, double rms_w_after) {
  if (!(rms_w_before > 1.0)) return rms_w_before > 0.0 ? 1.0 - rms_w_after / rms_w_before : 0.0;
  const double left = rms_w_after > 1.0 ? std::sqrt(rms_w_after * rms_w_after - 1.0) : 0.0;
  return 1.0 - left / std::sqrt(rms_w_before * rms_w_before - 1.0);
}

/// 1 − a/b, the plain ratio: what the ranking, the pair test and the cannot-tell-apart
/// test compare (differences in it are differences in RMS, whatever the noise).
inline double plain_shrink(double rms_w_before, double rms_w_after) {
  return rms_w_before > 0.0 ? 1.0 - rms_w_after / rms_w_before : 0.0;
}

}  // namespace hstmon::gap
