#pragma once
/// @file rosenbrock.hpp
/// One linearly implicit (Rosenbrock) step for the stiff ticks of a model that offers its
/// Jacobian: ROS34PW2 of Rang and Angermann (BIT 45, 2005), 4 stages, order 3, L-stable
/// and stiffly accurate.
///
/// Why this method: a closed-circuit HST's low-pressure line sits on its open charge check
/// valve, whose conductance makes that node's time constant tens of microseconds against a
/// 1 ms tick; explicit RK4 then needs ~90 substeps. A Rosenbrock step solves the tick's
/// linearisation instead: L-stability damps such a mode in one step (R(∞) = 0, no ringing
/// at ρh ≫ 1, unlike the trapezoidal rule), and order 3 keeps the slow modes (the shaft
/// and the high-pressure line, |λ|h ≲ 0.3 at a 10 ms tick) as accurate as the monitor
/// needs. Its four stages need f at the tick's start (the observer has it with the
/// outputs) and three more evaluations — RK4's count — plus one n×n LU factorisation.
/// Being a W-method, it keeps order 2 for any Jacobian approximation, so a Jacobian that is
/// slightly off (a valve opening inside the tick) costs accuracy, not stability.
///
/// Form (autonomous: inputs are held over a tick), with W = I − γ·h·J:
///   W·k_i = h·f(x + Σ_{j<i} α_ij·k_j) + h·J·Σ_{j<i} γ_ij·k_j,   x⁺ = x + Σ b_i·k_i.
/// No heap, no exceptions; O(n³) for the factorisation, O(n²) per stage.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <limits>

#include "hstmon/code_size.hpp"  // HSTMON_UNROLL
#include "hstmon/model_concept.hpp"
#include "hstmon/rk4.hpp"

namespace hstmon {

/// ROS34PW2's coefficients (Rang & Angermann 2005, Table 4; stiffly accurate:
/// b_i = α_4i + γ_4i).
struct Ros34pw2 {
  static constexpr int kStages = 4;
  static constexpr double kGamma = 4.3586652150845900e-01;  ///< γ, the diagonal
  /// α_ij, j < i (stage arguments)
  static constexpr double kAlpha[kStages][kStages] = {
      {0, 0, 0, 0},
      {8.7173304301691801e-01, 0, 0, 0},
      {8.4457060015369423e-01, -1.1299064236484185e-01, 0, 0},
      {0, 0, 1, 0}};
  /// γ_ij, j < i (the Jacobian's stage couplings)
  static constexpr double kGammaIJ[kStages][kStages] = {
      {0, 0, 0, 0},
      {-8.7173304301691801e-01, 0, 0, 0},
      {-9.0338057013044082e-01, 5.4180672388095326e-02, 0, 0},
      {2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, 0}};
  /// b_i (the step's weights)
  static constexpr double kB[kStages] = {2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00,
                                         4.3586652150845900e-01};
  /// b̂_i, the embedded order-2 solution's weights: x⁺ − x̂⁺ estimates the step's error
  static constexpr double kBHat[kStages] = {3.7810903145819369e-01, -9.6042292212423178e-02, 5.0e-01,
                                            2.1793326075422950e-01};
};

namespace rosenbrock_detail {

/// Ros34pw2's coefficients rounded to T once, at compile time (the same values as T(c) at
/// run time: round to nearest). A float build indexing the double tables at run time
/// converted them, and subtracted kB − kBHat, in soft-float on a Cortex-M4F (≈ 730
/// instructions a tick of closed_loop_hst.json's monitor).
template <typename T>
struct Ros34pw2As {
  T alpha[Ros34pw2::kStages][Ros34pw2::kStages]{};     ///< T(α_ij)
  T gamma_ij[Ros34pw2::kStages][Ros34pw2::kStages]{};  ///< T(γ_ij)
  T b[Ros34pw2::kStages]{};                            ///< T(b_i)
  T b_err[Ros34pw2::kStages]{};                        ///< T(b_i − b̂_i), the difference in double
  constexpr Ros34pw2As() noexcept {
    for (int i = 0; i < Ros34pw2::kStages; ++i) {
      for (int j = 0; j < Ros34pw2::kStages; ++j) {
        alpha[i][j] = static_cast<T>(Ros34pw2::kAlpha[i][j]);
        gamma_ij[i][j] = static_cast<T>(Ros34pw2::kGammaIJ[i][j]);
      }
      b[i] = static_cast<T>(Ros34pw2::kB[i]);
      b_err[i] = static_cast<T>(Ros34pw2::kB[i] - Ros34pw2::kBHat[i]);
    }
  }
};

/// std::fmax(a, b) without a call (newlib's fmaxf is one, and classifies both arguments):
/// the other argument where one is NaN, else the larger; the same value as std::fmax but
/// possibly for the sign of a zero when a and b are +0 and −0.
template <typename T>
constexpr T fmax_inline(T a, T b) noexcept {
  return (a != a) ? b : ((b != b) ? a : (a > b ? a : b));
}

/// LU factorisation with partial pivoting of the leading n×n block of the fixed-size
/// matrix A in place (L unit lower, U upper), the row order in perm. n = K where K > 0
/// (known at compile time: the loops unrolled, on a Cortex-M4F about half the
/// instructions of run-time loops), else n = m; the same operations in the same order
/// either way, so the same bits.
/// @return false if a pivot is zero or not finite (A singular to working precision)
template <int K, typename Mat, typename Index>
bool lu_factor(Mat& A, Index (&perm)[Mat::RowsAtCompileTime], int m) noexcept {
  using T = typename Mat::Scalar;
  const int n = K > 0 ? K : m;
  HSTMON_UNROLL
  for (int i = 0; i < n; ++i) perm[i] = static_cast<Index>(i);
  HSTMON_UNROLL
  for (int c = 0; c < n; ++c) {
    int p = c;
    T best = std::abs(A(c, c));
    HSTMON_UNROLL
    for (int r = c + 1; r < n; ++r) {
      const T a = std::abs(A(r, c));
      if (a > best) {
        best = a;
        p = r;
      }
    }
    if (!(best > T(0)) || !std::isfinite(best)) return false;
    if (p != c) {
      A.row(p).swap(A.row(c));
      const Index t = perm[p];
      perm[p] = perm[c];
      perm[c] = t;
    }
    const T inv = T(1) / A(c, c);
    HSTMON_UNROLL
    for (int r = c + 1; r < n; ++r) {
      const T l = A(r, c) * inv;
      A(r, c) = l;
      HSTMON_UNROLL
      for (int k = c + 1; k < n; ++k) A(r, k) -= l * A(c, k);
    }
  }
  return true;
}

/// Solves L·U·x = P·b on the leading n entries (n as lu_factor's) with lu_factor's
/// output; b is overwritten by x there (entries beyond n are left as they are: the
/// identity's solve).
template <int K, typename Mat, typename Vec, typename Index>
void lu_solve(const Mat& LU, const Index (&perm)[Mat::RowsAtCompileTime], Vec& b, int m) noexcept {
  using T = typename Mat::Scalar;
  const int n = K > 0 ? K : m;
  Vec y = b;
  HSTMON_UNROLL
  for (int i = 0; i < n; ++i) {
    T s = b[perm[i]];
    HSTMON_UNROLL
    for (int k = 0; k < i; ++k) s -= LU(i, k) * y[k];
    y[i] = s;
  }
  HSTMON_UNROLL
  for (int i = n - 1; i >= 0; --i) {
    T s = y[i];
    HSTMON_UNROLL
    for (int k = i + 1; k < n; ++k) s -= LU(i, k) * y[k];
    y[i] = s / LU(i, i);
  }
  b = y;
}

/// W = I − gh·J over the leading n×n block (n as lu_factor's).
template <int K, typename Mat>
void form_w(Mat& W, const Mat& J, typename Mat::Scalar gh, int m) noexcept {
  using T = typename Mat::Scalar;
  const int n = K > 0 ? K : m;
  HSTMON_UNROLL
  for (int r = 0; r < n; ++r) {
    HSTMON_UNROLL
    for (int c = 0; c < n; ++c) W(r, c) = (r == c ? T(1) : T(0)) - gh * J(r, c);
  }
}

/// rhs += h·(J·coupled) over the leading n entries (n as lu_factor's), row by row in
/// index order, not Eigen's blocked product: a model padded to a larger capacity (zeros
/// beyond its states) then gets the same bits.
template <int K, typename Mat, typename Vec>
void add_coupling(Vec& rhs, const Mat& J, const Vec& coupled, typename Mat::Scalar h, int m) noexcept {
  using T = typename Mat::Scalar;
  const int n = K > 0 ? K : m;
  HSTMON_UNROLL
  for (int r = 0; r < n; ++r) {
    T acc = T(0);
    HSTMON_UNROLL
    for (int c = 0; c < n; ++c) acc += J(r, c) * coupled[c];
    rhs[r] += h * acc;
  }
}

/// One ROS34PW2 increment (rosenbrock_increment) over the leading m states; K > 0: m = K
/// known at compile time. Out of line: its stages and LU (over 0.5 KiB of frame on a
/// Cortex-M4F) stay off the stack of a tick that is not implicit.
template <int K, typename Model, typename StateMatrix>
HSTMON_NOINLINE bool increment(const Model& model, const typename Model::State& x, typename Model::Scalar h,
                               const typename Model::State& f0, const StateMatrix& J, int m,
                               typename Model::State& step, typename Model::State& error) noexcept {
  using T = typename Model::Scalar;
  using State = typename Model::State;
  using M = Ros34pw2;
  constexpr int n = State::RowsAtCompileTime;
  StateMatrix W;
  const T gh = T(M::kGamma) * h;
  form_w<K>(W, J, gh, m);
  unsigned char perm[static_cast<std::size_t>(n)];
  if (!lu_factor<K>(W, perm, m)) return false;

  static constexpr Ros34pw2As<T> kC{};
  State k[M::kStages];
  step.setZero();
  error.setZero();
  for (int i = 0; i < M::kStages; ++i) {
    State arg = x;
    State coupled = State::Zero();
    for (int j = 0; j < i; ++j) {
      if (kC.alpha[i][j] != T(0)) arg += kC.alpha[i][j] * k[j];  // α_ij ≠ 0 exactly where T(α_ij) ≠ 0
      coupled += kC.gamma_ij[i][j] * k[j];
    }
    State rhs = h * (i == 0 ? f0 : model.derivative(arg));
    if (i > 0) add_coupling<K>(rhs, J, coupled, h, m);
    lu_solve<K>(W, perm, rhs, m);
    k[i] = rhs;
    step += kC.b[i] * rhs;
    error += kC.b_err[i] * rhs;
  }
  // The embedded solution is not L-stable, so the raw estimate of a component far off its
  // fast manifold is about half its distance however exact the step is; filtered through
  // W⁻¹ (Shampine's device, as Radau5 does) such a component's estimate shrinks by
  // 1/(1 + γhλ) while a slow one's is unchanged to O(h).
  lu_solve<K>(W, perm, error, m);
  return true;
}

}  // namespace rosenbrock_detail

/// One ROS34PW2 step of size h from x, given f(x) and the Jacobian there.
/// @param model  provides `State derivative(const State&) const`, inputs already set
/// @param x      the state at the step's start [state units]
/// @param h      step [s]
/// @param f0     f(x) [state units / s]
/// @param J      ∂f/∂x at x, or an approximation of it [1/s in state units]
/// @param used   the states in use: a model padded to a larger capacity has J = 0 and
///               f = 0 beyond them, where the step is then 0 without any work
/// @param step   out: x⁺ − x [state units]
/// @param error  out: the embedded estimate of the step's error, filtered by W⁻¹ [state units]
/// @return false when I − γ·h·J is singular (step, error unset)
template <typename Model, typename StateMatrix>
bool rosenbrock_increment(const Model& model, const typename Model::State& x, typename Model::Scalar h,
                          const typename Model::State& f0, const StateMatrix& J, int used, typename Model::State& step,
                          typename Model::State& error) noexcept {
  constexpr int n = Model::State::RowsAtCompileTime;
  static_assert(StateMatrix::RowsAtCompileTime == n && StateMatrix::ColsAtCompileTime == n, "J is n x n");
  static_assert(n > 0 && n <= 255, "fixed-size states; pivot indices are bytes");
  // The size known at compile time where it is: a compiled circuit's kUsedStates, or every
  // state of a model that is never padded (no n_states()). Only an interpreter padded to
  // its capacity takes the run-time size (and only there is that code instantiated).
  if constexpr (model_detail::HasUsedStates<Model>::value) {
    static_cast<void>(used);
    constexpr int k = Model::kUsedStates;
    return rosenbrock_detail::increment<k>(model, x, h, f0, J, k, step, error);
  } else if constexpr (!model_detail::HasStateCount<Model>::value) {
    static_cast<void>(used);
    return rosenbrock_detail::increment<n>(model, x, h, f0, J, n, step, error);
  } else {
    if (used < 0 || used >= n) return rosenbrock_detail::increment<n>(model, x, h, f0, J, n, step, error);
    return rosenbrock_detail::increment<0>(model, x, h, f0, J, used, step, error);
  }
}

/// What rosenbrock_tick did.
struct RosenbrockTick {
  int steps = 0;         ///< steps tried, rejected ones included (each: 3 evaluations, a Jacobian, an LU)
  bool ok = false;       ///< the tick was integrated (else the state is untouched)
  bool clipped = false;  ///< the finest step still missed the tolerance (taken anyway)
};

/// Integrates one tick of length `tick` from s.x by ROS34PW2 steps whose size adapts within
/// the tick to the embedded error estimate: steps of tick/2^L, L ≤ max_level, halved on a
/// rejected step and doubled after one well inside the tolerance, ending exactly on the
/// tick. The same arithmetic on every platform (no clock, no randomness), so host and
/// firmware agree; at most 2^max_level + max_level steps.
/// @param model      derivative(x) and jacobian(x, J), inputs already set
/// @param s          state and compensation, advanced in place on success
/// @param tick       the tick [s]
/// @param f0         f(s.x) [state units / s]
/// @param scale      per state, the magnitude the error is relative to [state units]
///                   (the observer's running peak |x|); the larger of it and |x| is used
/// @param rtol       accepted error per step relative to that magnitude [-]
/// @param max_level  finest step tick/2^max_level, 0 … 15
/// @param level      in: the level to start at (the last tick's, say); out: the last one
/// @param used       the states in use (rosenbrock_increment)
/// Out of line, as increment: a tick that is not implicit does not carry its frame.
template <typename Model>
HSTMON_NOINLINE RosenbrockTick rosenbrock_tick(const Model& model, CompensatedState<typename Model::State>& s,
                                               typename Model::Scalar tick, const typename Model::State& f0,
                                               const typename Model::State& scale, typename Model::Scalar rtol,
                                               int max_level, int& level,
                                               int used = Model::State::RowsAtCompileTime) noexcept {
  using T = typename Model::Scalar;
  using State = typename Model::State;
  RosenbrockTick r;
  CompensatedState<State> x = s;
  State f = f0;
  typename Model::StateMatrix J;
  bool fresh = false;  // J and f are those of x
  const long units = 1L << max_level;  // the tick in the finest steps
  long done = 0;
  int L = level < 0 ? 0 : (level > max_level ? max_level : level);
  while (done < units) {
    // Never step past the tick's end, and keep steps aligned so the tick ends exactly.
    while ((units - done) < (1L << (max_level - L)) || (done % (1L << (max_level - L))) != 0) ++L;
    if (!fresh) {
      model.jacobian(x.x, J);
      if (r.steps > 0) f = model.derivative(x.x);
      if (!J.allFinite() || !f.allFinite()) return r;
      fresh = true;
    }
    State step, error;
    ++r.steps;
    if (!rosenbrock_increment(model, x.x, tick / static_cast<T>(1L << L), f, J, used, step, error)) return r;
    const State x_new = x.x + step;
    if (!x_new.allFinite()) return r;
    // Largest error relative to each state's magnitude (states that do not move and
    // have no magnitude count as met).
    T err = T(0);
    for (int i = 0; i < State::RowsAtCompileTime; ++i) {
      using rosenbrock_detail::fmax_inline;  // every operand ≥ +0 or NaN: std::fmax's values
      const T mag = fmax_inline(fmax_inline(std::fabs(x.x[i]), std::fabs(x_new[i])), scale[i]);
      const T e = std::fabs(error[i]);
      if (e > T(0)) err = fmax_inline(err, mag > T(0) ? e / (rtol * mag) : std::numeric_limits<T>::infinity());
    }
    if (err > T(1) && L < max_level) {
      ++L;  // rejected: the same start, J and f, half the step
      continue;
    }
    if (err > T(1)) r.clipped = true;
    x.add(step);
    fresh = false;
    done += 1L << (max_level - L);
    // Order-2 estimate: doubling the step multiplies it by about 8.
    if (err < T(0.1) && L > 0) --L;
  }
  s = x;
  level = L;
  r.ok = true;
  return r;
}

}  // namespace hstmon
