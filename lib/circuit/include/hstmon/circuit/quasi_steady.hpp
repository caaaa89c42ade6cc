#pragma once
/// @file quasi_steady.hpp
/// The quasi-steady solve of stiff nodes and the Schur reduction of their Jacobian block,
/// written once for the interpreting CircuitModel (run-time loops over index lists) and the
/// compiled models that hstmon-circuit-header --compiled generates (straight-line node
/// balances passed in as callables): the same iterations, the same convergence tests, the
/// same rounding. No heap, no exceptions.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hstmon/circuit/inlining.hpp"

namespace hstmon::circuit {

/// Gauss–Seidel sweeps and Newton iterations per node before a solve is declared failed.
inline constexpr int kMaxSweeps = 40;
inline constexpr int kMaxNewton = 60;

/// Solves one node's balance F(p) = 0 for its pressure p [Pa], the other pressures held:
/// Newton, kept inside the bracket the signs of the balance have established, with a
/// bisection whenever a Newton step would leave it or would not halve the step before last
/// (a root law makes Newton cycle across zero flow otherwise), and a widening search while
/// the balance is flat (valves shut).
/// @param p        in: the start; out: the solution (or the last iterate) [Pa]
/// @param p_env    the circuit's pressure envelope [Pa] (scales the tests)
/// @param balance  F = balance(p, dF): net inflow [m³/s] at p with the other pressures
///                 held, dF its slope by p (≤ 0); it must leave the node at p (z[i] = p)
/// @return true when converged (a step below 8ε relative, or F exactly 0)
template <typename T, class Balance>
HSTMON_CIRCUIT_RARE bool solve_node_newton_bracketed(T& p_io, T p_env, Balance&& balance) noexcept {
  const T eps = std::numeric_limits<T>::epsilon();
  const T floor = T(1e-6) * p_env;
  const T inf = std::numeric_limits<T>::infinity();
  T p = p_io;
  T lo = -inf, hi = inf;
  T dx_old = inf, dx = inf;
  for (int it = 0; it < kMaxNewton; ++it) {
    T dF;
    const T F = balance(p, dF);
    if (F == T(0)) return true;
    if (!(F == F)) return false;
    if (F > T(0)) {
      lo = p;
    } else {
      hi = p;
    }
    const bool bracketed = lo > -inf && hi < inf;
    const T newton = dF < T(0) ? p - F / dF : std::numeric_limits<T>::quiet_NaN();
    T p_new;
    if (bracketed && (!(newton > lo && newton < hi) || std::fabs(T(2) * F) > std::fabs(dx_old * dF))) {
      p_new = T(0.5) * (lo + hi);
    } else if (newton == newton) {
      p_new = newton;
    } else {
      p_new = p + (F > T(0) ? T(1) : T(-1)) * (std::fabs(p) + T(0.01) * p_env);
    }
    dx_old = dx;
    dx = p_new - p;
    p = p_new;
    if (std::fabs(dx) <= T(8) * eps * (std::fabs(p) + floor)) {
      p_io = p;
      return true;
    }
  }
  p_io = p;
  return false;
}

/// solve_node_newton_bracketed's first iteration, inline: the usual call (warm-started from
/// the last solution, converged after one Newton step) then costs one balance and a
/// division, without the bracket's bookkeeping. Any other case restarts the bracketed
/// solve from p_io, which repeats this iteration bit for bit (the balance is a function of
/// p and the held pressures), so both give the same result.
template <typename T, class Balance>
HSTMON_CIRCUIT_INLINE bool solve_node_newton(T& p_io, T p_env, Balance&& balance) noexcept {
  T dF;
  const T F = balance(p_io, dF);
  if (F == T(0)) return true;
  if (dF < T(0)) {
    const T p = p_io - F / dF;
    if (std::fabs(p - p_io) <= T(8) * std::numeric_limits<T>::epsilon() * (std::fabs(p) + T(1e-6) * p_env)) {
      p_io = p;
      return true;
    }
  }
  return solve_node_newton_bracketed(p_io, p_env, balance);
}

/// A node whose balance is one orifice to pressure u plus flows linear in its pressure p,
///   F(p) = c0·sq(u − p) + lin − B·p   (sq: signed_root.hpp's regularised root),
/// solved in closed form: with Δ = u − p and c = lin − B·u, F = c0·sq(Δ) + B·Δ + c rises
/// strictly with Δ, and beyond the transition |Δ| ≥ ΔP_t it is the quadratic
/// B·s² + c0·s − |c| = 0 in s = √|Δ|, whose root s = 2|c|/(c0 + √(c0² + 4B|c|)) has no
/// cancellation. The exact node solve Gauss–Seidel needs (the contraction argument of
/// docs/circuits.md is unchanged), at one square root instead of Newton iterations.
/// @param p_io  out: the node's pressure when solved [Pa]; untouched otherwise
/// @param u     the orifice's other port [Pa]
/// @param c0    orifice coefficient k·opening [m³/(s·√Pa)]
/// @param c0_sq c0·c0 [m⁶/(s²·Pa)]
/// @param x_t   its transition pressure ΔP_t [Pa]
/// @param lin   the linear flows' constant part: Σ g·p_other + Σ fixed inflows [m³/s]
/// @param B     Σ g of the linear flows [m³/(s·Pa)], ≥ 0
/// @param four_B 4·B [m³/(s·Pa)]
/// @param root  out: √|Δ| at the solution [√Pa] (the orifice's slope is c0/(2·root))
/// @return false when the root lies in the laminar band (|Δ| < ΔP_t, the cubic law), the
///         orifice is shut, or a value is not finite: the caller then uses Newton
template <typename T>
HSTMON_CIRCUIT_INLINE bool solve_node_orifice(T& p_io, T u, T c0, T c0_sq, T x_t, T lin, T B, T four_B, T& root) noexcept {
  const T c = lin - B * u;
  const T a = std::fabs(c);
  if (!(c0 > T(0))) return false;
  const T s = T(2) * a / (c0 + std::sqrt(c0_sq + four_B * a));
  const T d = s * s;
  if (!(d >= x_t) || !(d <= std::numeric_limits<T>::max())) return false;
  p_io = c > T(0) ? u + d : u - d;
  root = s;
  return true;
}

/// solve_node_orifice with c0² and 4·B computed here (the interpreter's call; the compiled
/// kernels pass them, folded once per input change where the usual tick asks).
template <typename T>
HSTMON_CIRCUIT_INLINE bool solve_node_orifice(T& p_io, T u, T c0, T x_t, T lin, T B, T& root) noexcept {
  return solve_node_orifice(p_io, u, c0, c0 * c0, x_t, lin, B, T(4) * B, root);
}

/// Where a compiled kernel's solve takes its input-constant subexpressions from (its
/// fold.at(i, expr)): computed in place — the general tick, firmware, derivative().
struct Unfolded {
  template <typename T>
  HSTMON_CIRCUIT_INLINE static T at(int, T computed) noexcept {
    return computed;
  }
};

/// ... or read from N values folded once per input change (the kernel's fold(), the usual
/// tick's coefficients): the same values, without their multiplies and loads per solve.
template <typename T, std::size_t N>
struct Folded {
  T v[N]{};  ///< Kernel::fold's values [SI, per expression]
  HSTMON_CIRCUIT_INLINE T at(int i, T) const noexcept { return v[i]; }
};

/// One Gauss–Seidel sweep's bookkeeping: whether every node solve converged and the
/// largest relative move of a pressure.
template <typename T>
struct Sweep {
  T floor{};      ///< 1e-6 of the pressure envelope [Pa]: the relative test's floor
  T change{};     ///< largest |Δp|/(|p| + floor) of the sweep [-]
  bool ok = true;  ///< every node solve converged

  /// Solves one node (solve() updates p, its pressure, and says if it converged) and
  /// records the move.
  template <class Solve>
  HSTMON_CIRCUIT_INLINE void node(T& p, Solve&& solve) noexcept {
    const T before = p;
    ok = solve() && ok;
    // A node that did not move at all (steady operation, the last sweep) needs no relative
    // test: three instructions on Cortex-M4 instead of nine, per node and sweep.
    if (p == before) return;
    // Not std::fmax: a library call on Cortex-M4 (no VMAXNM); NaN moves are ignored alike.
    const T move = std::fabs(p - before) / (std::fabs(p) + floor);
    if (move > change) change = move;
  }
};

/// The quasi-steady solve: Gauss–Seidel sweeps (sweep(Sweep<T>&) solves every stiff node
/// once, in order, through Sweep::node) until a sweep moves no pressure by more than 16ε
/// relative, or after one sweep when no two stiff nodes are connected (each is then exact).
/// @return true when converged within kMaxSweeps with every node solve converged
template <typename T, class SweepFn>
HSTMON_CIRCUIT_INLINE bool gauss_seidel(T p_env, bool coupled, SweepFn&& sweep) noexcept {
  const T eps = std::numeric_limits<T>::epsilon();
  const T floor = T(1e-6) * p_env;
  bool conv = false;
  for (int s = 0; s < kMaxSweeps && !conv; ++s) {
    Sweep<T> w;
    w.floor = floor;
    sweep(w);
    if (!w.ok) break;
    conv = !coupled || w.change <= T(16) * eps;
  }
  return conv;
}

/// Reduced Jacobian jr = M⁻¹(G_xx − G_xa·G_aa⁻¹·G_ax) (a: the m stiff nodes, x: the n states)
/// from the unknowns' Jacobian G, and the local contraction factor q of the stiff block
/// (the largest Σ_{b≠a}|G_ab|/|G_aa|). G_aa is strictly diagonally dominant wherever the
/// solve contracts, so it is eliminated without pivoting, in place on the stiff rows.
/// @param G         unknowns' Jacobian [m³/(s·Pa), N·m/Pa, …]; its stiff rows are destroyed
/// @param ia, ix    row/column of stiff node a and of state s in G
/// @param inv_mass  K [Pa/m³] or 1/J of state s's row
/// @param jr        out: the n × n reduced Jacobian [1/s in state units]
/// @param q         out: the contraction factor [-]
template <typename T, std::size_t U, std::size_t S>
HSTMON_CIRCUIT_INLINE void schur_reduce(T (&G)[U][U], const std::uint8_t* ia, int m, const std::uint8_t* ix, int n, const T* inv_mass,
                  T (&jr)[S][S], T& q) noexcept {
  q = T(0);
  for (int a = 0; a < m; ++a) {
    T off = T(0);
    for (int b = 0; b < m; ++b) {
      if (b != a) off += std::fabs(G[ia[a]][ia[b]]);
    }
    const T qa = off / std::fabs(G[ia[a]][ia[a]]);
    if (qa > q) q = qa;  // not std::fmax (a call on Cortex-M4); NaN is skipped alike
  }
  for (int k = 0; k < m; ++k) {
    const T inv = T(1) / G[ia[k]][ia[k]];
    for (int r = k + 1; r < m; ++r) {
      const T f = G[ia[r]][ia[k]] * inv;
      if (f == T(0)) continue;
      for (int c = k + 1; c < m; ++c) G[ia[r]][ia[c]] -= f * G[ia[k]][ia[c]];
      for (int s = 0; s < n; ++s) G[ia[r]][ix[s]] -= f * G[ia[k]][ix[s]];
    }
  }
  for (int k = m - 1; k >= 0; --k) {
    for (int s = 0; s < n; ++s) {
      T v = G[ia[k]][ix[s]];
      for (int c = k + 1; c < m; ++c) v -= G[ia[k]][ia[c]] * G[ia[c]][ix[s]];
      G[ia[k]][ix[s]] = v / G[ia[k]][ia[k]];
    }
  }
  for (int r = 0; r < n; ++r) {
    for (int s = 0; s < n; ++s) {
      T v = G[ix[r]][ix[s]];
      for (int a = 0; a < m; ++a) v -= G[ix[r]][ia[a]] * G[ia[a]][ix[s]];
      jr[r][s] = inv_mass[r] * v;
    }
  }
}

}  // namespace hstmon::circuit
