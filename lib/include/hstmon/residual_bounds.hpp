#pragma once
/// @file residual_bounds.hpp
/// Model bound of the thesis observer's residuals from parameter intervals: the largest
/// steady-state output change that the parameter uncertainty can produce at the current
/// operating point,
///   m_i = Σ_θ max(|ŷ_i(θ + Δθ) − ŷ_i(θ)|, |ŷ_i(θ − Δθ) − ŷ_i(θ)|),   Δθ = ε_θ·|θ|,
/// one parameter at a time (first order in Δθ, as the LFT bond-graph bounds; interactions
/// are second order, ≈ ε² of the output). Feed it to ResidualEvaluator::set_model_bound.
///
/// At Table 2.2 with ε = 2 % on Dm, Dp, Rlkg, Ripl, Rf, Rbl, kf and exact inputs it is
/// (0.27, 0.27, 4.9 bar, 6.2 rad/s) on (Pmi, Pmo, Ppp, ωm) — 5.3, 5.3, 98 and 119 σ of
/// the thesis sensors; a 2 % error on kp would add ≈ 2.0 bar and 2.4 rad/s.
///
/// Cost: two steady-state solves per uncertain parameter (≈ 20 solves of ≤ 200 torque
/// evaluations): call it at configuration and when the logged inputs change, not per
/// tick. Stack: ≈ 350 B in float on Cortex-M4F (a copy of the parameters and inputs, three
/// output vectors, the solve's coefficients; no model object). Never allocates, never
/// throws. Transients (J, K, sensor lags) are not covered: those are left to the CUSUM's
/// drift and clip.

#include <cmath>

#include "hstmon/fault_signature.hpp"
#include "hstmon/model_bound.hpp"
#include "hstmon/status.hpp"
#include "hstmon/thesis_reduced.hpp"

/// The bound runs once per input change, not per tick: optimised for size and kept out
/// of the tick path (GCC, Clang; the steady-state solves it calls keep their own options).
#if defined(__GNUC__)
#define HSTMON_BOUND_PATH __attribute__((noinline, cold))
#else
#define HSTMON_BOUND_PATH
#endif

namespace hstmon {

/// Relative uncertainty ε of each thesis parameter and logged input [-] (fraction of the
/// nominal value; 0.02 = ±2 %). J, K and the laminar transitions do not move steady states.
template <typename T>
struct ThesisUncertainty {
  T Dm = T(0.02);     ///< motor displacement [-]
  T Dp = T(0.02);     ///< loading-pump displacement [-]
  T Rlkg = T(0.02);   ///< port leakage resistance [-]
  T Ripl = T(0.02);   ///< cross-port leakage resistance [-]
  T Rf = T(0.02);     ///< shaft friction [-]
  T Rbl = T(0.02);    ///< valve fluid friction [-]
  T kf = T(0.02);     ///< DCV orifice coefficient [-]
  T Psupl = T(0);     ///< logged supply pressure [-]
  T Pbp = T(0);       ///< logged booster pressure [-]
  T kp = T(0);        ///< logged PRV coefficient [-]
};

/// Steady-state outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) for parameters p and inputs u.
/// @return false if p is invalid or u admits no steady state (y untouched)
template <typename T>
HSTMON_BOUND_PATH bool steady_outputs(const ThesisParams<T>& p, const ThesisInputs<T>& u,
                                      typename ThesisReducedModel<T>::Output& y) noexcept {
  using Model = ThesisReducedModel<T>;
  T v[Model::kOutputs];
  if (!Model::params_valid(p) || !Model::steady_outputs(p, u, v)) return false;
  for (int i = 0; i < Model::kOutputs; ++i) y[i] = v[i];
  return true;
}

namespace detail {

/// The uncertain quantities in the order the bound sums them: the parameters, then the
/// logged inputs. Member pointers, so the tables are constants in flash.
constexpr int kBoundParams = 7;
constexpr int kBoundItems = 10;

template <typename T>
struct BoundItems {
  static constexpr T ThesisParams<T>::*kParam[kBoundParams] = {
      &ThesisParams<T>::Dm, &ThesisParams<T>::Dp, &ThesisParams<T>::Rlkg, &ThesisParams<T>::Ripl,
      &ThesisParams<T>::Rf, &ThesisParams<T>::Rbl, &ThesisParams<T>::kf};
  static constexpr T ThesisInputs<T>::*kInput[kBoundItems - kBoundParams] = {
      &ThesisInputs<T>::Psupl, &ThesisInputs<T>::Pbp, &ThesisInputs<T>::kp};
  static constexpr T ThesisUncertainty<T>::*kEps[kBoundItems] = {
      &ThesisUncertainty<T>::Dm,   &ThesisUncertainty<T>::Dp,    &ThesisUncertainty<T>::Rlkg,
      &ThesisUncertainty<T>::Ripl, &ThesisUncertainty<T>::Rf,    &ThesisUncertainty<T>::Rbl,
      &ThesisUncertainty<T>::kf,   &ThesisUncertainty<T>::Psupl, &ThesisUncertainty<T>::Pbp,
      &ThesisUncertainty<T>::kp};
};

}  // namespace detail

/// Computes the model bound m (see the file comment) at the steady state of `model`'s
/// parameters and current inputs.
/// @param model  the observer's model (parameters and inputs set)
/// @param eps    relative uncertainties, each finite, ≥ 0 and < 0.5
/// @param m      out: bound per channel (Pmi, Pmo, Ppp [Pa], ωm [rad/s]); it is the sum's
///               storage, so after kNoSteadyState it holds a partial sum (untouched after
///               kInvalidParams)
/// @return       kOk; kInvalidParams (eps out of range); kNoSteadyState (the nominal or a
///               perturbed model has no steady state)
/// @tparam Model  a thesis-rig model: Params = ThesisParams<T>, Inputs = ThesisInputs<T>,
///                static params_valid(p) and steady_outputs(p, u, y) (ThesisReducedModel, or
///                ThesisCircuitModel on the engine)
template <class Model, typename T = typename Model::Scalar>
HSTMON_BOUND_PATH Status thesis_model_bound(const Model& model, const ThesisUncertainty<T>& eps,
                                            T (&m)[kFdiChannels]) noexcept {
  using I = detail::BoundItems<T>;
  for (int k = 0; k < detail::kBoundItems; ++k) {
    const T e = eps.*(I::kEps[k]);
    if (!(std::isfinite(e) && e >= T(0) && e < T(0.5))) return Status::kInvalidParams;
  }
  // Stack (a firmware monitor has 512 B for everything): one copy of the parameters and
  // inputs, one quantity perturbed in place at a time and restored, the + and − sides
  // solved one after the other, the sum in m, and no model object of ours
  // (Model::steady_outputs: none in the hand-written model, one per solve on the engine).
  ThesisParams<T> p = model.params();
  ThesisInputs<T> u = model.inputs();
  T y0[kFdiChannels], plus[kFdiChannels], y[kFdiChannels];
  if (!Model::params_valid(p) || !Model::steady_outputs(p, u, y0)) return Status::kNoSteadyState;
  for (int i = 0; i < kFdiChannels; ++i) m[i] = T(0);
  for (int k = 0; k < detail::kBoundItems; ++k) {
    const T e = eps.*(I::kEps[k]);
    if (e == T(0)) continue;
    T& v = k < detail::kBoundParams ? p.*(I::kParam[k]) : u.*(I::kInput[k - detail::kBoundParams]);
    const T v0 = v;
    // m += max(|y(+) − y0|, |y(−) − y0|) per channel; plus holds y(+), then |y(+) − y0|.
    v = v0 * (T(1) + e);
    if (!Model::params_valid(p) || !Model::steady_outputs(p, u, plus)) return Status::kNoSteadyState;
    for (int i = 0; i < kFdiChannels; ++i) plus[i] = std::fabs(plus[i] - y0[i]);
    v = v0 * (T(1) - e);
    if (!Model::params_valid(p) || !Model::steady_outputs(p, u, y)) return Status::kNoSteadyState;
    for (int i = 0; i < kFdiChannels; ++i) {
      const T d = std::fabs(y[i] - y0[i]);
      m[i] += plus[i] > d ? plus[i] : d;
    }
    v = v0;
  }
  return Status::kOk;
}

/// The model bound (model_bound.hpp) of any model of the thesis rig's vocabulary:
/// thesis_model_bound() with that model's steady states. Each thesis model's ModelBound
/// derives from it.
template <class Model>
struct ThesisModelBound {
  using T = typename Model::Scalar;
  using Uncertainty = ThesisUncertainty<T>;  ///< relative uncertainty per parameter and logged input [-]
  /// thesis_model_bound().
  static Status compute(const Model& model, const Uncertainty& eps, T (&m)[kFdiChannels]) noexcept {
    return thesis_model_bound(model, eps, m);
  }
};

/// The hand-written thesis model's bound for the monitor.
template <typename T>
struct ModelBound<ThesisReducedModel<T>> : ThesisModelBound<ThesisReducedModel<T>> {};

}  // namespace hstmon
