#pragma once
/// @file local_fit.hpp
/// The smoothing of the balance equations (equations.cpp for the thesis rig,
/// circuit_equations.cpp for any circuit; docs/gap.md, "Where, at equation level"): a local
/// linear fit — mean and slope — of each signal over a window of ±kSmoothTime (at least 2,
/// at most kMaxHalf samples each side), and the test that leaves out a window in which a
/// signal bends (the fit's χ²/dof beyond its 4σ band for white noise: a transient faster
/// than the smoothing biases the window's mean and slope).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace hstmon::gap::detail {

inline constexpr double kSmoothTime = 5e-3;  ///< half-width of the smoothing window [s]: ≈ the thesis ωm time constant
inline constexpr int kMaxHalf = 25;          ///< most samples each side of the window centre

/// Half-width of the smoothing window [samples] for sample times t [s] (n ≥ 2): the median
/// interval's share of kSmoothTime, within [2, kMaxHalf].
inline int smoothing_half_width(const std::vector<double>& t) {
  std::vector<double> dts;
  for (std::size_t k = 1; k < t.size(); ++k) dts.push_back(t[k] - t[k - 1]);
  std::nth_element(dts.begin(), dts.begin() + static_cast<std::ptrdiff_t>(dts.size() / 2), dts.end());
  const double dt = dts[dts.size() / 2];
  return std::clamp(static_cast<int>(std::lround(kSmoothTime / dt)), 2, kMaxHalf);
}

/// The window of rows [lo, hi] around a centre, with its time statistics.
struct Window {
  std::size_t lo = 0, hi = 0;
  double N = 0;     ///< rows in the window
  double tbar = 0;  ///< mean time [s]
  double stt = 0;   ///< Σ (t − t̄)² [s²]
};

/// The window of half-width m [samples] centred on row k of t (k ≥ m, k + m < t.size()).
inline Window window_at(const std::vector<double>& t, std::size_t k, std::size_t m) {
  Window w;
  w.lo = k - m;
  w.hi = k + m;
  w.N = 2.0 * static_cast<double>(m) + 1.0;
  for (std::size_t i = w.lo; i <= w.hi; ++i) w.tbar += t[i];
  w.tbar /= w.N;
  for (std::size_t i = w.lo; i <= w.hi; ++i) w.stt += (t[i] - w.tbar) * (t[i] - w.tbar);
  return w;
}

/// Local linear fit of y(i) over window w: mean (the smoothed value at the centre) and
/// slope [unit of y per s].
template <class Y>
void line_fit(const std::vector<double>& t, const Window& w, Y y, double& mean, double& slope) {
  double s = 0, sty = 0;
  for (std::size_t i = w.lo; i <= w.hi; ++i) {
    s += y(i);
    sty += (t[i] - w.tbar) * y(i);
  }
  mean = s / w.N;
  slope = sty / w.stt;
}

/// True when y bends within w: the residual χ²/dof of the line (mean, slope) with white
/// noise σ = noise beyond 1 + 4·√(2/(N − 2)).
template <class Y>
bool bends(const std::vector<double>& t, const Window& w, Y y, double mean, double slope, double noise) {
  double chi = 0;
  for (std::size_t i = w.lo; i <= w.hi; ++i) chi += std::pow(y(i) - mean - slope * (t[i] - w.tbar), 2);
  chi /= noise * noise * (w.N - 2.0);
  return chi > 1.0 + 4.0 * std::sqrt(2.0 / (w.N - 2.0));
}

}  // namespace hstmon::gap::detail
