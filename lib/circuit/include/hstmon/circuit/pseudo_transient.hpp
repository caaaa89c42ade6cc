#pragma once
/// @file pseudo_transient.hpp
/// Steady state of M·du/dt = g(u) by pseudo-transient continuation: implicit Euler steps
/// (M/Δt − ∂g/∂u)·δ = g(u) whose Δt grows as the residual falls (switched evolution
/// relaxation, Δt ← Δt·‖g_old‖/‖g_new‖, at least 1.5× a step), so far from the solution it follows the
/// circuit's own (dissipative, stable) transient and near it it becomes Newton's method.
/// Plain Newton from rest diverges on orifice circuits (the root's slope is unbounded at
/// zero flow); the transient does not. Runs at configuration and on input changes only.

#include <cmath>
#include <cstddef>
#include <limits>

#include "hstmon/circuit/dense.hpp"

namespace hstmon::circuit {

/// Settings of pseudo_transient().
template <typename T>
struct PtcConfig {
  T dt0 = T(1e-6);         ///< first pseudo time step [s]
  T dt_newton = T(1e4);    ///< Δt beyond which a small step means convergence [s]
  /// A residual whose every unknown moves by less than this fraction of its envelope per
  /// second is steady, whatever Δt [1/s] (floored at 64ε): near rounding the residual
  /// flickers, the overshoot guard keeps cutting Δt, and dt_newton is never reached.
  T rate_tol = T(1e-10);
  int max_iterations = 600;
};

/// Finds u with g(u) = 0 starting from u (in place).
/// @param eval   eval(u, g, J): g [n] the residual (flows [m³/s], torques [N·m]) and J [N][N]
///               its Jacobian ∂g/∂u at u
/// @param mass   M's diagonal [n]: 1/K [m³/Pa] for a node, J [kg·m²] for a shaft
/// @param scale  typical magnitude of each unknown [n] (its envelope), for the norms
/// @param n      unknowns used, ≤ N
/// @param u      in: start (rest); out: the steady state when true is returned
/// @return       true on convergence (relative Newton step ≤ 64ε with Δt ≥ dt_newton, or a
///               residual rate ≤ rate_tol)
template <typename T, std::size_t N, typename Eval>
bool pseudo_transient(Eval& eval, const T (&mass)[N], const T (&scale)[N], int n, T (&u)[N],
                      const PtcConfig<T>& cfg = PtcConfig<T>{}) noexcept {
  // The Newton matrix is built in J's storage and the step in g's: both are evaluated
  // afresh at the top of every iteration, so one array serves each pair (firmware stack).
  T g[N], J[N][N], u_prev[N]{};  // u_prev zeroed: GCC cannot see it is set before use
  T(&d)[N] = g;
  T dt = cfg.dt0;
  T prev_norm = T(-1);
  bool rounding_step = false;  // the last step moved no unknown beyond tol (relative)
  const T tol = T(64) * std::numeric_limits<T>::epsilon();
  const T rate_tol = std::fmax(cfg.rate_tol, tol);
  for (int it = 0; it < cfg.max_iterations; ++it) {
    eval(u, g, J);
    T norm = T(0);
    for (int k = 0; k < n; ++k) norm = std::fmax(norm, std::fabs(g[k] / mass[k]) / scale[k]);
    if (!std::isfinite(norm)) {
      if (prev_norm < T(0)) return false;
      for (int k = 0; k < n; ++k) u[k] = u_prev[k];  // retreat with a shorter step
      dt *= T(0.1);
      continue;
    }
    if (norm <= rate_tol) return true;
    if (prev_norm > T(0) && rounding_step && norm >= prev_norm) {
      // The last step moved no unknown beyond rounding, and the residual did not fall:
      // it is the residual's rounding floor at the solution (in float a stiff node's is
      // ~1e-4/s, above rate_tol), which flickers. A Newton-length step decides: at rounding
      // level it passes the step test below; otherwise the transient resumes from it.
      // Without this, the flicker's rises tripped the guards below — back and Δt/4 past
      // a doubling, back to dt0 past dt_newton — and thesis.json in float failed 19 % of
      // its steady solves after 600 iterations.
      dt = std::fmax(dt, cfg.dt_newton);
    } else if (prev_norm > T(0)) {
      // A step that more than doubled the residual overshot (a valve's kink, a lightly
      // damped mode): back, and a quarter of the pseudo time.
      if (norm > T(2) * prev_norm) {
        for (int k = 0; k < n; ++k) u[k] = u_prev[k];
        dt *= T(0.25);
        continue;
      }
      // Grow Δt with the fall of the residual (SER), but by at least 1.5× while it does
      // not rise much: during a physical transient the residual stays level and pure SER
      // would follow it at the first step's pace. Implicit Euler is L-stable, so a long
      // step on a dissipative circuit is safe; a residual that halves or worse shrinks it.
      const T r = prev_norm / norm;
      dt *= r >= T(0.5) ? (r > T(10) ? T(10) : (r < T(1.5) ? T(1.5) : r)) : T(0.5);
      if (dt > T(1e15)) dt = T(1e15);
      // A Newton step (Δt past dt_newton) that raised the residual is at a valve's kink,
      // where Newton can cycle between two iterates for ever (the closed loop's ±2 % k_hp
      // at swash 0.6: 10.7 ↔ 16.3 for 600 iterations, so no bound at that point): back to
      // the circuit's own transient from the first step's length.
      if (r < T(1) && dt > cfg.dt_newton) dt = cfg.dt0;
    }
    prev_norm = norm;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) J[r][c] = -J[r][c];
      J[r][r] += mass[r] / dt;
    }
    if (!solve_dense(J, d, n)) {
      dt *= T(0.1);
      continue;
    }
    // At most a tenth of an unknown's envelope per step: a linearisation across a valve's
    // kink can ask for far more than the circuit would move.
    T big = T(0);
    for (int k = 0; k < n; ++k) big = std::fmax(big, std::fabs(d[k]) / scale[k]);
    if (big > T(0.1)) {
      for (int k = 0; k < n; ++k) d[k] *= T(0.1) / big;
    }
    T step = T(0);
    for (int k = 0; k < n; ++k) {
      u_prev[k] = u[k];
      u[k] += d[k];
      step = std::fmax(step, std::fabs(d[k]) / (std::fabs(u[k]) + T(1e-6) * scale[k]));
    }
    if (step <= tol && dt >= cfg.dt_newton) return true;
    rounding_step = step <= tol;
  }
  return false;
}

}  // namespace hstmon::circuit
