#pragma once
// An independent steady-state solve of equations 2.5–2.8 for the tests: plain
// unregularised square roots, long double, a 4×4 Newton iteration with its own
// Jacobian and Gaussian elimination. Shares no code with lib/.
#include <array>
#include <cmath>

namespace hstmon::test {

struct NewtonInputs {
  long double Psupl = 3.5e6L, Ps = 0.0L, Pbp = 1.0e6L, kp = 4.41e-8L;
};

using Vec4 = std::array<long double, 4>;  // Pmi, Pmo, Ppp, w_m

inline long double sq(long double x) { return x < 0 ? -std::sqrt(-x) : std::sqrt(x); }
inline long double dsq(long double x) { return 0.5L / std::sqrt(std::fabs(x)); }

// Table 2.2, typed in again on purpose.
struct Table22 {
  long double Dm = 7.96e-6L, Dp = 1.00745e-6L, Rlkg = 6.4779e16L, Ripl = 16.97088e18L;
  long double Rf = 1.59154e-3L, Rbl = 4.758732e-2L, kf = 0.3226e-5L, J = 1e-3L, K = 1e14L;
};

// Residual F(x) = flows / torque balance (the state equations with d/dt = 0, divided by K).
inline Vec4 residual(const Table22& p, const NewtonInputs& u, const Vec4& x) {
  const long double Pmi = x[0], Pmo = x[1], Ppp = x[2], w = x[3];
  return {p.kf * sq(u.Psupl - Pmi) - p.Dm * w - Pmi / p.Rlkg - (Pmi - Pmo) / p.Ripl,
          p.Dm * w + (Pmi - Pmo) / p.Ripl - Pmo / p.Rlkg - p.kf * sq(Pmo - u.Ps),
          p.Dp * w - u.kp * sq(Ppp - u.Pbp),
          p.Dm * (Pmi - Pmo) - (p.Rf + p.Rbl) * w - p.Dp * (Ppp - u.Pbp)};
}

inline Vec4 newton_steady_state(const Table22& p, const NewtonInputs& u, Vec4 x, int iters = 100) {
  for (int it = 0; it < iters; ++it) {
    const Vec4 f = residual(p, u, x);
    long double a[4][5] = {
        {-p.kf * dsq(u.Psupl - x[0]) - 1 / p.Rlkg - 1 / p.Ripl, 1 / p.Ripl, 0, -p.Dm, -f[0]},
        {1 / p.Ripl, -1 / p.Ripl - 1 / p.Rlkg - p.kf * dsq(x[1] - u.Ps), 0, p.Dm, -f[1]},
        {0, 0, -u.kp * dsq(x[2] - u.Pbp), p.Dp, -f[2]},
        {p.Dm, -p.Dm, -p.Dp, -(p.Rf + p.Rbl), -f[3]}};
    for (int c = 0; c < 4; ++c) {  // elimination with partial pivoting
      int piv = c;
      for (int r = c + 1; r < 4; ++r)
        if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
      for (int k = 0; k < 5; ++k) std::swap(a[c][k], a[piv][k]);
      for (int r = c + 1; r < 4; ++r) {
        const long double m = a[r][c] / a[c][c];
        for (int k = c; k < 5; ++k) a[r][k] -= m * a[c][k];
      }
    }
    Vec4 dx{};
    for (int r = 3; r >= 0; --r) {
      long double s = a[r][4];
      for (int k = r + 1; k < 4; ++k) s -= a[r][k] * dx[k];
      dx[r] = s / a[r][r];
    }
    long double rel = 0;
    for (int i = 0; i < 4; ++i) {
      x[i] += dx[i];
      rel = std::fmax(rel, std::fabs(dx[i]) / (std::fabs(x[i]) + 1));
    }
    if (rel < 1e-17L) break;
  }
  return x;
}

}  // namespace hstmon::test
