#pragma once
/// @file dense.hpp
/// Small dense linear algebra on fixed-capacity arrays with a run-time size: the
/// circuits' Jacobians are a few rows of a capacity-sized block, and looping over the used
/// rows only keeps a padded capacity from costing time. No heap, no exceptions.

#include <cmath>
#include <cstddef>
#include <limits>

#include "hstmon/code_size.hpp"  // HSTMON_UNROLL

namespace hstmon::circuit {

/// Solves A·x = b in place (b becomes x) for the leading n×n block of A, by Gaussian
/// elimination with row equilibration (rows mix flows and torques, decades apart) and
/// partial pivoting. A is destroyed.
/// @return false if A is singular to working precision or holds a non-finite number
template <typename T, std::size_t N>
bool solve_dense(T (&A)[N][N], T (&b)[N], int n) noexcept {
  for (int r = 0; r < n; ++r) {
    T m = T(0);
    for (int c = 0; c < n; ++c) m = std::fmax(m, std::fabs(A[r][c]));
    if (!(m > T(0)) || !std::isfinite(m)) return false;
    const T s = T(1) / m;
    for (int c = 0; c < n; ++c) A[r][c] *= s;
    b[r] *= s;
  }
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int r = k + 1; r < n; ++r) {
      if (std::fabs(A[r][k]) > std::fabs(A[piv][k])) piv = r;
    }
    if (!(std::fabs(A[piv][k]) > T(16) * std::numeric_limits<T>::epsilon())) return false;
    if (piv != k) {
      for (int c = 0; c < n; ++c) {
        const T t = A[k][c];
        A[k][c] = A[piv][c];
        A[piv][c] = t;
      }
      const T t = b[k];
      b[k] = b[piv];
      b[piv] = t;
    }
    const T inv = T(1) / A[k][k];
    for (int r = k + 1; r < n; ++r) {
      const T f = A[r][k] * inv;
      if (f == T(0)) continue;
      for (int c = k + 1; c < n; ++c) A[r][c] -= f * A[k][c];
      b[r] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    T s = b[k];
    for (int c = k + 1; c < n; ++c) s -= A[k][c] * b[c];
    b[k] = s / A[k][k];
  }
  for (int k = 0; k < n; ++k) {
    if (!std::isfinite(b[k])) return false;
  }
  return true;
}

/// Spectral radius of [[a, b], [c, d]] [1/s], exact, or 0 when it is at most rho_max
/// (a complex pair has ρ² = det; a real pair ρ = |tr|/2 + √disc). NaN stays NaN.
template <typename T>
T radius_2x2(T a, T b, T c, T d, T rho_max) noexcept {
  const T tr = a + d;
  const T det = a * d - b * c;
  const T disc = T(0.25) * tr * tr - det;
  const T half_tr = T(0.5) * std::fabs(tr);
  if (disc >= T(0)) {
    const T m = rho_max - half_tr;
    return (m >= T(0) && disc <= m * m) ? T(0) : half_tr + std::sqrt(disc);
  }
  return det <= rho_max * rho_max ? T(0) : std::sqrt(det);
}

/// Upper bound on the spectral radius of the leading n×n block of J [1/s]: ρ(J) ≤
/// ρ(|J|) ≤ max_i (|J|·v)_i / v_i for any v > 0 (Perron–Frobenius and Collatz–Wielandt),
/// tightened by a few power iterations on |J| (which drive v towards the Perron vector,
/// where the bound is ρ(|J|)). Exact for n = 1 and for real spectra of sign-symmetric
/// matrices; at most about twice ρ for a lightly damped oscillatory pair. 0 when the
/// bound is at most rho_max; NaN for a non-finite J.
/// The maxima and minimum are plain comparisons, not std::fmax/fmin: every value they see
/// is finite or +∞ and ≥ +0 (the NaN test comes first), where the two agree bit for bit,
/// and newlib's fmaxf/fminf are calls that classify both arguments (on the Cortex-M4F
/// they were over a quarter of a circuit monitor's usual tick).
///
/// rho_stiff (default +∞): a radius above which the caller needs no more than to know it
/// is above (the observer: a tick it integrates linearly implicit whatever the radius).
/// Once a lower bound on ρ(|J|) (the bound's limit) exceeds it — the largest |J_ii|: a
/// nonnegative matrix's radius is at least each diagonal entry, and a stiff node's
/// self-conductance K·G is one — the bound so far is returned without the remaining power
/// iterations: still an upper bound on ρ(J), only looser. With rho_stiff = +∞ the bits are
/// those of the full iteration.
template <typename T, std::size_t N>
T radius_bound(const T (&J)[N][N], int n, T rho_max, T rho_stiff = std::numeric_limits<T>::infinity()) noexcept {
  if (n <= 0) return T(0);
  if (n == 1) {
    const T r = std::fabs(J[0][0]);
    return r <= rho_max ? T(0) : r;
  }
  // A one-state capacity (N = 1) has no 2 × 2 case (n ≤ N): not even compiled there.
  if constexpr (N >= 2) {
    if (n == 2) return radius_2x2(J[0][0], J[0][1], J[1][0], J[1][1], rho_max);
  }
  T v[N], w[N];
  for (int i = 0; i < n; ++i) v[i] = T(1);
  T diag = T(0);
  for (int i = 0; i < n; ++i) {
    const T d = std::fabs(J[i][i]);
    diag = d > diag ? d : diag;
  }
  T best = std::numeric_limits<T>::infinity();
  for (int it = 0; it < 8; ++it) {
    T bound = T(0), wmax = T(0);
    for (int i = 0; i < n; ++i) {
      T s = T(0);
      for (int j = 0; j < n; ++j) s += std::fabs(J[i][j]) * v[j];
      if (!std::isfinite(s)) return s - s;  // NaN
      w[i] = s;
      const T r = s / v[i];
      bound = r > bound ? r : bound;
      wmax = s > wmax ? s : wmax;
    }
    best = bound < best ? bound : best;
    if (best <= rho_max) return T(0);
    if (!(wmax > T(0))) return T(0);
    if (diag > rho_stiff) return best;  // stiff anyway: the bound so far
    // Keep v strictly positive (a reducible |J| would zero entries and lose the bound).
    for (int i = 0; i < n; ++i) v[i] = w[i] / wmax + T(1e-3);
  }
  return best;
}

/// radius_bound(J, K, rho_max) for a size K known at compile time (a compiled circuit's
/// states), bit for bit: the same operations in the same order, with |J| taken once rather
/// than in each power iteration (fabs is exact) and the loops over K unrolled (K ≤ 8). It
/// runs on every general observer tick of a compiled circuit; on the Cortex-M4F the loop
/// form cost the paper circuit's 4 states about 680 instructions a tick, most of them loop
/// overhead and the repeated fabs (bench/RESULTS.md, 2026-11-28).
/// @tparam K  states, 1 ≤ K ≤ N
/// @param J        the reduced Jacobian [1/s], leading K×K block used
/// @param rho_max  the radius below which 0 is returned [1/s]
/// @param rho_stiff radius_bound's [1/s]
/// @return         the bound [1/s]; 0 when it is at most rho_max; NaN for a non-finite J
template <int K, typename T, std::size_t N>
T radius_bound_fixed(const T (&J)[N][N], T rho_max, T rho_stiff = std::numeric_limits<T>::infinity()) noexcept {
  static_assert(K >= 1 && static_cast<std::size_t>(K) <= N, "K states within the capacity");
  if constexpr (K <= 2 || K > 8) {
    return radius_bound(J, K, rho_max, rho_stiff);
  } else {
    constexpr std::size_t kK = static_cast<std::size_t>(K);  // an array extent
    T a[kK][kK];
    HSTMON_UNROLL
    for (int i = 0; i < K; ++i) {
      HSTMON_UNROLL
      for (int j = 0; j < K; ++j) a[i][j] = std::fabs(J[i][j]);
    }
    T v[kK], w[kK];
    HSTMON_UNROLL
    for (int i = 0; i < K; ++i) v[i] = T(1);
    T diag = T(0);
    HSTMON_UNROLL
    for (int i = 0; i < K; ++i) diag = a[i][i] > diag ? a[i][i] : diag;
    T best = std::numeric_limits<T>::infinity();
    for (int it = 0; it < 8; ++it) {
      T bound = T(0), wmax = T(0);
      HSTMON_UNROLL
      for (int i = 0; i < K; ++i) {
        T s = T(0);
        HSTMON_UNROLL
        for (int j = 0; j < K; ++j) s += a[i][j] * v[j];
        if (!std::isfinite(s)) return s - s;  // NaN
        w[i] = s;
        const T r = s / v[i];
        bound = r > bound ? r : bound;
        wmax = s > wmax ? s : wmax;
      }
      best = bound < best ? bound : best;
      if (best <= rho_max) return T(0);
      if (!(wmax > T(0))) return T(0);
      if (diag > rho_stiff) return best;  // radius_bound's shortcut
      HSTMON_UNROLL
      for (int i = 0; i < K; ++i) v[i] = w[i] / wmax + T(1e-3);
    }
    return best;
  }
}

}  // namespace hstmon::circuit
