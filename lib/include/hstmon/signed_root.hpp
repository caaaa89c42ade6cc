#pragma once
/// @file signed_root.hpp
/// Regularised signed square root of an orifice law, and its exact inverse.
///
/// An orifice passes Q = k·sign(ΔP)·√|ΔP|. The slope dQ/dΔP = k/(2√|ΔP|) is unbounded at
/// ΔP = 0, which makes any explicit integrator unstable at start from rest. Below a
/// transition pressure ΔP_t the flow is taken laminar-like: the odd cubic
///   r(x) = x·(5 − x²/ΔP_t²) / (4·√ΔP_t),  |x| < ΔP_t,
/// which matches √|x| in value and slope at ±ΔP_t (C¹), is monotone, and has the finite
/// slope 5/(4√ΔP_t) at zero. Beyond ΔP_t the law is exact, so steady states at normal
/// operating points are untouched. docs/numerics.md gives the analysis.
///
/// All functions are pure, allocation-free and never throw.

#include <cmath>
#include <limits>

#include "hstmon/code_size.hpp"  // HSTMON_COLD

namespace hstmon {

/// Regularised sign(x)·√|x|.
/// @param x    pressure difference [Pa]
/// @param x_t  transition pressure ΔP_t > 0 [Pa]
/// @return     [√Pa]
template <typename T>
inline T signed_root(T x, T x_t) noexcept {
  const T ax = std::fabs(x);
  if (ax >= x_t) {
    const T r = std::sqrt(ax);
    return x < T(0) ? -r : r;
  }
  return x * (T(5) - (x * x) / (x_t * x_t)) / (T(4) * std::sqrt(x_t));
}

/// Derivative of signed_root with respect to x.
/// @param x    pressure difference [Pa]
/// @param x_t  transition pressure ΔP_t > 0 [Pa]
/// @return     [1/√Pa], finite everywhere (at most 5/(4√ΔP_t))
template <typename T>
inline T signed_root_slope(T x, T x_t) noexcept {
  const T ax = std::fabs(x);
  if (ax >= x_t) {
    return T(0.5) / std::sqrt(ax);
  }
  return (T(5) - T(3) * (x * x) / (x_t * x_t)) / (T(4) * std::sqrt(x_t));
}

/// signed_root(x, x_t), and signed_root_slope(x, x_t) in slope, sharing the square root.
/// @param x      pressure difference [Pa]
/// @param x_t    transition pressure ΔP_t > 0 [Pa]
/// @param slope  out: d(signed_root)/dx [1/√Pa]
/// @return       [√Pa]
template <typename T>
inline T signed_root(T x, T x_t, T& slope) noexcept {
  const T ax = std::fabs(x);
  if (ax >= x_t) {
    const T r = std::sqrt(ax);
    slope = T(0.5) / r;
    return x < T(0) ? -r : r;
  }
  slope = signed_root_slope(x, x_t);
  return signed_root(x, x_t);
}

namespace detail {

/// The laminar branch of signed_square (|y·|y|| < x_t): Newton on the cubic. Kept out of
/// line so the turbulent fast path, taken at every normal operating point, stays a few
/// instructions and the loops around it (DCV refinements, RK4 stages) can unroll.
template <typename T>
HSTMON_COLD T signed_square_laminar(T y, T x_t) noexcept {
  const T s = std::sqrt(x_t);
  const T inv_xt2 = T(1) / (x_t * x_t);
  T x = T(4) * s * y / T(5);
  for (int i = 0; i < 12; ++i) {
    const T f = x * (T(5) - x * x * inv_xt2) - T(4) * s * y;
    const T df = T(5) - T(3) * x * x * inv_xt2;
    const T dx = f / df;
    x -= dx;
    if (std::fabs(dx) <= T(4) * std::numeric_limits<T>::epsilon() * x_t) {
      break;
    }
  }
  return x;
}

}  // namespace detail

/// Inverse of signed_root: the pressure difference x with signed_root(x, x_t) = y.
/// Beyond the transition this is y·|y| (no square root needed); inside it, the cubic is
/// solved by Newton's method from the linear guess, which converges monotonically
/// because the cubic is increasing and concave on each side of zero.
/// @param y    flow divided by the orifice coefficient, Q/k [√Pa]
/// @param x_t  transition pressure ΔP_t > 0 [Pa]
/// @return     pressure difference [Pa]
template <typename T>
inline T signed_square(T y, T x_t) noexcept {
  const T q = y * std::fabs(y);
  if (std::fabs(q) >= x_t) {
    return q;
  }
  return detail::signed_square_laminar(y, x_t);
}

/// signed_square for hot loops, with √x_t precomputed: the branch tests |y| ≥ √x_t, which
/// reuses |y| (the two tests differ only by rounding, where both branches agree).
/// @param y         Q/k [√Pa]
/// @param x_t       transition pressure ΔP_t > 0 [Pa]
/// @param root_x_t  √x_t [√Pa]
/// @return          pressure difference [Pa]
template <typename T>
inline T signed_square(T y, T x_t, T root_x_t) noexcept {
  const T ay = std::fabs(y);
  if (ay >= root_x_t) {
    return y * ay;
  }
  return detail::signed_square_laminar(y, x_t);
}

/// Derivative d(signed_square)/dy = 1 / signed_root_slope(x) [√Pa].
/// @param y    Q/k [√Pa]
/// @param x_t  transition pressure ΔP_t > 0 [Pa]
template <typename T>
inline T signed_square_slope(T y, T x_t) noexcept {
  const T q = y * std::fabs(y);
  if (std::fabs(q) >= x_t) {
    return T(2) * std::fabs(y);
  }
  return T(1) / signed_root_slope(signed_square(y, x_t), x_t);
}

/// signed_square_slope with √x_t precomputed; same branch as signed_square(y, x_t, root_x_t).
/// @param y         Q/k [√Pa]
/// @param x_t       transition pressure ΔP_t > 0 [Pa]
/// @param root_x_t  √x_t [√Pa]
/// @return          [√Pa]
template <typename T>
inline T signed_square_slope(T y, T x_t, T root_x_t) noexcept {
  const T ay = std::fabs(y);
  if (ay >= root_x_t) {
    return T(2) * ay;
  }
  return T(1) / signed_root_slope(detail::signed_square_laminar(y, x_t), x_t);
}

}  // namespace hstmon
