#pragma once
/// @file circuit_bound.hpp
/// The model bound (model_bound.hpp) of a circuit from the engine: per channel, the sum
/// over the circuit's parameters of the largest steady-state output change that a
/// relative error of ±ε_k in parameter k makes at the current inputs — the thesis rig's
/// rule (residual_bounds.hpp) with the circuit's parameters in place of Table 2.2's.
/// Each parameter with ε_k > 0 costs two steady-state solves, so the bound runs once per
/// input change, never per tick. Nothing here allocates.

#include <cmath>

#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/model_bound.hpp"
#include "hstmon/status.hpp"

namespace hstmon::circuit {

/// Relative uncertainty of each parameter of a circuit [-], by parameter index
/// (0 = exact; 0.02 = ±2 %). The host sets it from the parameters' quantities
/// (circuit_tools::default_uncertainty): what moves a steady state (displacements,
/// resistances, orifices, curve pressures) is uncertain, capacitances and inertias are not.
template <typename T, class Cap>
struct CircuitUncertainty {
  T rel[kExtent<Cap::kParams>]{};
};

/// The steady-state outputs of model at its inputs [output units]; false if none.
template <typename T, class Cap>
bool steady_outputs(const CircuitModel<T, Cap>& model, typename CircuitModel<T, Cap>::Output& y) noexcept {
  typename CircuitModel<T, Cap>::State x;
  if (!model.steady_state(x)) return false;
  y = model.outputs(x);
  return true;
}

}  // namespace hstmon::circuit

namespace hstmon {

/// The circuit engine's model bound for the monitor.
template <typename T, class Cap>
struct ModelBound<circuit::CircuitModel<T, Cap>> {
  using Model = circuit::CircuitModel<T, Cap>;
  using Uncertainty = circuit::CircuitUncertainty<T, Cap>;
  static constexpr int kN = Model::kOutputs;

  /// @param model  the observer's model (description, parameters and inputs set)
  /// @param eps    relative uncertainties, each finite, ≥ 0 and < 0.5
  /// @param m      out: bound per channel [channel unit] (unused channels 0; a partial sum after an error)
  /// @return       kOk; kInvalidParams (eps out of range); kNoSteadyState
  static Status compute(const Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>]) noexcept {
    for (int i = 0; i < kN; ++i) m[i] = T(0);
    for (int k = 0; k < Cap::kParams; ++k) {
      const T e = eps.rel[k];
      if (!(std::isfinite(e) && e >= T(0) && e < T(0.5))) return Status::kInvalidParams;
    }
    typename Model::Output y0, y;
    if (!circuit::steady_outputs(model, y0)) return Status::kNoSteadyState;
    const int n = model.description() != nullptr ? model.description()->n_params : 0;
    Model p = model;  // perturbed one parameter at a time
    typename Model::Params v = model.params();
    for (int k = 0; k < n; ++k) {
      const T e = eps.rel[k];
      if (e == T(0)) continue;
      const T v0 = v.v[k];
      T d[circuit::kExtent<kN>] = {};
      for (const T side : {T(1) + e, T(1) - e}) {
        v.v[k] = v0 * side;
        p.set_params(v);
        if (!p.valid() || !circuit::steady_outputs(p, y)) return Status::kNoSteadyState;
        for (int i = 0; i < kN; ++i) d[i] = std::fmax(d[i], std::fabs(y[i] - y0[i]));
      }
      v.v[k] = v0;
      for (int i = 0; i < kN; ++i) m[i] += d[i];
    }
    return Status::kOk;
  }
};

}  // namespace hstmon
