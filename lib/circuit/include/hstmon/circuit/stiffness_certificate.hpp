#pragma once
/// @file stiffness_certificate.hpp
/// A stiffness certificate over a box of states: proof, made once, that at every point of
/// the box the observer's general tick would take one RK4 substep and find the
/// quasi-steady solve contracting — so a fused tick may skip the per-tick reduction and
/// spectral radius while the state stays inside (CompiledModel's usual tick).
///
/// The unknowns' Jacobian G is affine in the elements' conductances, and each conductance
/// has a range over the box (laws.hpp conductance_range), so G lies entrywise in
/// [G_lo, G_hi]. From there, with a: the stiff nodes, x: the states, M: the states' inverse
/// masses:
///   - the stiff block: −G_aa is a Z-matrix (every flow law is monotone); if its worst case
///     (least diagonal, largest coupling) is strictly diagonally dominant by q < 1, every
///     −G_aa in the range is an M-matrix and (−G_aa)⁻¹ lies in [(−G_aa,hi)⁻¹, (−G_aa,lo)⁻¹],
///     entrywise ≥ 0 (inverse-monotonicity of M-matrices);
///   - the reduced Jacobian J = M·(G_xx + G_xa·(−G_aa)⁻¹·G_ax) then lies in the range that
///     interval arithmetic gives, and its spectral radius below the bound of
///     reduced_radius_bound.
/// The general tick computes ρ exactly for up to two states and, beyond, starts its bound
/// from the largest absolute row sum (dense.hpp radius_bound), which is one of the bounds
/// used here: certified ⇒ the general tick finds ρ ≤ rho_max. A relative margin of 1e-3
/// covers the rounding of both. No heap, no exceptions.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hstmon/circuit/dense.hpp"

namespace hstmon::circuit {

/// The margin a certified bound keeps below its limit, relative [-]: rounding of the
/// interval arithmetic and of the general tick's own ρ.
inline constexpr double kCertificateMargin = 1e-3;

namespace certificate_detail {

/// [lo, hi] of a·b for a in [a_lo, a_hi], b in [b_lo, b_hi].
template <typename T>
inline void mul(T a_lo, T a_hi, T b_lo, T b_hi, T& lo, T& hi) noexcept {
  const T p1 = a_lo * b_lo, p2 = a_lo * b_hi, p3 = a_hi * b_lo, p4 = a_hi * b_hi;
  lo = std::fmin(std::fmin(p1, p2), std::fmin(p3, p4));
  hi = std::fmax(std::fmax(p1, p2), std::fmax(p3, p4));
}

/// The largest |v| for v in [lo, hi].
template <typename T>
inline T mag(T lo, T hi) noexcept {
  return std::fmax(std::fabs(lo), std::fabs(hi));
}

/// Inverse of the leading m×m block of A into inv, column by column (solve_dense).
/// @return false if A is singular or not finite
template <typename T, std::size_t U>
bool invert(const T (&A)[U][U], int m, T (&inv)[U][U]) noexcept {
  for (int col = 0; col < m; ++col) {
    T a[U][U];
    T b[U];
    for (int r = 0; r < m; ++r) {
      for (int c = 0; c < m; ++c) a[r][c] = A[r][c];
      b[r] = r == col ? T(1) : T(0);
    }
    if (!solve_dense(a, b, m)) return false;
    for (int r = 0; r < m; ++r) inv[r][col] = b[r];
  }
  return true;
}

}  // namespace certificate_detail

/// Upper bound on the spectral radius of every n×n matrix J with J_lo ≤ J ≤ J_hi
/// (entrywise) [1/s]: the largest absolute row sum (any n), and for n = 2 with a
/// non-positive diagonal and off-diagonals of opposite signs, max(|a|, |d|, √(a·d + |b·c|))
/// (a real pair has |λ| ≤ |tr|/2 + |a − d|/2 = max(|a|, |d|), as b·c ≤ 0 shrinks the
/// discriminant; a complex pair has |λ|² = det = a·d + |b·c|). NaN for a non-finite entry.
template <typename T, std::size_t N>
T interval_radius_bound(const T (&J_lo)[N][N], const T (&J_hi)[N][N], int n) noexcept {
  using certificate_detail::mag;
  T rows = T(0);
  for (int r = 0; r < n; ++r) {
    T s = T(0);
    for (int c = 0; c < n; ++c) s += mag(J_lo[r][c], J_hi[r][c]);
    if (!(s == s)) return s;
    rows = std::fmax(rows, s);
  }
  if constexpr (N >= 2) {
    if (n == 2 && J_hi[0][0] <= T(0) && J_hi[1][1] <= T(0) &&
        ((J_lo[0][1] >= T(0) && J_hi[1][0] <= T(0)) || (J_hi[0][1] <= T(0) && J_lo[1][0] >= T(0)))) {
      const T a = -J_lo[0][0], d = -J_lo[1][1];
      const T bc = mag(J_lo[0][1], J_hi[0][1]) * mag(J_lo[1][0], J_hi[1][0]);
      const T pair = std::fmax(std::fmax(a, d), std::sqrt(a * d + bc));
      return std::fmin(rows, pair);
    }
  }
  return rows;
}

/// The certificate itself, on the unknowns' Jacobian bounded over a box.
/// @param G_lo, G_hi  entrywise bounds of the unknowns' Jacobian over the box (kU × kU;
///                    CircuitModel::unknowns_jacobian_range)
/// @param ia, m       unknown index of each of the m stiff nodes
/// @param ix, n       unknown index of each of the n states
/// @param inv_mass    the states' K [Pa/m³] or 1/J, > 0
/// @param rho_max     the spectral radius one substep covers [1/s]; +∞: no stiffness test
/// @return true when, everywhere in the box, the stiff block contracts by q < 0.5 and the
///         reduced Jacobian's spectral radius is at most rho_max (both with the margin)
template <typename T, std::size_t U>
bool certify_reduced(const T (&G_lo)[U][U], const T (&G_hi)[U][U], const std::uint8_t* ia, int m, const std::uint8_t* ix,
                     int n, const T* inv_mass, T rho_max) noexcept {
  using certificate_detail::mul;
  const T keep = T(1) - static_cast<T>(kCertificateMargin);
  // The stiff block: negative diagonal, non-negative coupling, contracting in the worst case.
  T A_lo[U][U], A_hi[U][U];  // bounds of −G_aa
  for (int a = 0; a < m; ++a) {
    const T diag = -G_hi[ia[a]][ia[a]];  // the least |G_aa|
    if (!(diag > T(0))) return false;
    T off = T(0);
    for (int b = 0; b < m; ++b) {
      A_lo[a][b] = -G_hi[ia[a]][ia[b]];
      A_hi[a][b] = -G_lo[ia[a]][ia[b]];
      if (b == a) continue;
      if (!(G_lo[ia[a]][ia[b]] >= T(0))) return false;  // not a Z-matrix: no certificate
      off += G_hi[ia[a]][ia[b]];
    }
    if (!(off < T(0.5) * keep * diag)) return false;
  }
  if (!(rho_max < std::numeric_limits<T>::infinity())) return true;
  // N = (−G_aa)⁻¹ ∈ [A_hi⁻¹, A_lo⁻¹], both ≥ 0.
  T N_lo[U][U], N_hi[U][U];
  if (m > 0 && !(certificate_detail::invert(A_hi, m, N_lo) && certificate_detail::invert(A_lo, m, N_hi))) return false;
  // P = N·G_ax (m × n), then J = M·(G_xx + G_xa·P).
  T P_lo[U][U], P_hi[U][U];
  for (int a = 0; a < m; ++a) {
    for (int s = 0; s < n; ++s) {
      T lo = T(0), hi = T(0);
      for (int b = 0; b < m; ++b) {
        T l, h;
        mul(std::fmax(N_lo[a][b], T(0)), N_hi[a][b], G_lo[ia[b]][ix[s]], G_hi[ia[b]][ix[s]], l, h);
        lo += l;
        hi += h;
      }
      P_lo[a][s] = lo;
      P_hi[a][s] = hi;
    }
  }
  T J_lo[U][U], J_hi[U][U];
  for (int r = 0; r < n; ++r) {
    for (int s = 0; s < n; ++s) {
      T lo = G_lo[ix[r]][ix[s]], hi = G_hi[ix[r]][ix[s]];
      for (int a = 0; a < m; ++a) {
        T l, h;
        mul(G_lo[ix[r]][ia[a]], G_hi[ix[r]][ia[a]], P_lo[a][s], P_hi[a][s], l, h);
        lo += l;
        hi += h;
      }
      J_lo[r][s] = inv_mass[r] * lo;
      J_hi[r][s] = inv_mass[r] * hi;
    }
  }
  const T rho = interval_radius_bound(J_lo, J_hi, n);
  return rho <= keep * rho_max;
}

}  // namespace hstmon::circuit
