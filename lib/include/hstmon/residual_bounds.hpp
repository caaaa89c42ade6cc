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
/// tick. Never allocates, never throws. Transients (J, K, sensor lags) are not covered:
/// those are left to the CUSUM's drift and clip.

#include <cmath>

#include "hstmon/fault_signature.hpp"
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
  if (!Model::params_valid(p)) return false;
  Model m(p);
  m.set_inputs(u);
  typename Model::State x;
  if (!m.steady_state(x)) return false;
  y = m.outputs(x);
  return true;
}

/// Computes the model bound m (see the file comment) at the steady state of `model`'s
/// parameters and current inputs.
/// @param model  the observer's model (parameters and inputs set)
/// @param eps    relative uncertainties, each finite, ≥ 0 and < 0.5
/// @param m      out: bound per channel (Pmi, Pmo, Ppp [Pa], ωm [rad/s]); untouched on error
/// @return       kOk; kInvalidParams (eps out of range); kNoSteadyState (the nominal or a
///               perturbed model has no steady state)
template <typename T>
HSTMON_BOUND_PATH Status thesis_model_bound(const ThesisReducedModel<T>& model, const ThesisUncertainty<T>& eps,
                          T (&m)[kFdiChannels]) noexcept {
  using Model = ThesisReducedModel<T>;
  using P = ThesisParams<T>;
  using U = ThesisInputs<T>;
  struct PItem {
    T P::*field;
    T eps;
  };
  struct UItem {
    T U::*field;
    T eps;
  };
  const PItem pitems[] = {{&P::Dm, eps.Dm}, {&P::Dp, eps.Dp}, {&P::Rlkg, eps.Rlkg}, {&P::Ripl, eps.Ripl},
                          {&P::Rf, eps.Rf}, {&P::Rbl, eps.Rbl}, {&P::kf, eps.kf}};
  const UItem uitems[] = {{&U::Psupl, eps.Psupl}, {&U::Pbp, eps.Pbp}, {&U::kp, eps.kp}};
  for (const PItem& it : pitems) {
    if (!(std::isfinite(it.eps) && it.eps >= T(0) && it.eps < T(0.5))) return Status::kInvalidParams;
  }
  for (const UItem& it : uitems) {
    if (!(std::isfinite(it.eps) && it.eps >= T(0) && it.eps < T(0.5))) return Status::kInvalidParams;
  }

  const P p0 = model.params();
  const U u0 = model.inputs();
  typename Model::Output y0;
  if (!steady_outputs(p0, u0, y0)) return Status::kNoSteadyState;
  T acc[kFdiChannels] = {};
  // Adds max(|y(+) − y0|, |y(−) − y0|) per channel for one perturbed pair.
  auto add = [&](const P& pa, const U& ua, const P& pb, const U& ub) -> bool {
    typename Model::Output ya, yb;
    if (!steady_outputs(pa, ua, ya) || !steady_outputs(pb, ub, yb)) return false;
    for (int i = 0; i < kFdiChannels; ++i) {
      const T da = std::fabs(ya[i] - y0[i]);
      const T db = std::fabs(yb[i] - y0[i]);
      acc[i] += da > db ? da : db;
    }
    return true;
  };
  for (const PItem& it : pitems) {
    if (it.eps == T(0)) continue;
    P pa = p0, pb = p0;
    pa.*(it.field) = p0.*(it.field) * (T(1) + it.eps);
    pb.*(it.field) = p0.*(it.field) * (T(1) - it.eps);
    if (!add(pa, u0, pb, u0)) return Status::kNoSteadyState;
  }
  for (const UItem& it : uitems) {
    if (it.eps == T(0)) continue;
    U ua = u0, ub = u0;
    ua.*(it.field) = u0.*(it.field) * (T(1) + it.eps);
    ub.*(it.field) = u0.*(it.field) * (T(1) - it.eps);
    if (!add(p0, ua, p0, ub)) return Status::kNoSteadyState;
  }
  for (int i = 0; i < kFdiChannels; ++i) m[i] = acc[i];
  return Status::kOk;
}

}  // namespace hstmon
