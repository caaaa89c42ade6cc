#pragma once
/// @file circuit_bound.hpp
/// The model bound (model_bound.hpp) of a circuit from the engine: per channel, the sum
/// over the circuit's parameters of the largest steady-state output change that a
/// relative error of ±ε_k in parameter k makes at the current inputs — the thesis rig's
/// rule (residual_bounds.hpp) with the circuit's parameters in place of Table 2.2's.
/// That sum is a linearisation: near a valve's kink (a relief valve just cracked) each
/// parameter alone moves the output little, as the valve absorbs it, while all of them
/// together take the machine to the shut side, where nothing does. So per channel the
/// two corner models (every uncertain parameter at the side that moved the channel up, or
/// every one at the other) are solved too, and the bound is the larger of the sum and
/// their changes. Each parameter with ε_k > 0 costs two steady-state solves, each channel
/// two more, so the bound runs once per input change, never per tick. Nothing here
/// allocates.

#include <cmath>
#include <cstdint>

#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/model_bound.hpp"
#include "hstmon/status.hpp"

namespace hstmon::circuit {

/// Relative uncertainty of each parameter of a circuit [-], by parameter index
/// (0 = exact; 0.02 = ±2 %). The host takes a parameter file's stated `uncertainty`, else
/// sets it from the parameters' quantities (circuit_tools::circuit_uncertainty): what
/// moves a steady state (displacements, resistances, orifices, curve pressures) ±2 %,
/// capacitances and inertias exact.
template <typename T, class Cap>
struct CircuitUncertainty {
  T rel[kExtent<Cap::kParams>]{};
};

/// What makes up each channel's bound: the parameter whose ±ε moves the channel most on
/// its own, and by how much (compute()'s optional output).
template <typename T, int N>
struct BoundLead {
  int param[kExtent<N>]{};   ///< parameter index, −1 where no uncertain parameter moves the channel
  T change[kExtent<N>]{};    ///< its largest steady output change [channel unit]
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
  /// compute() can also report the slowest time constant over the models it solves.
  static constexpr bool kSlowestTau = true;

  /// The largest relative uncertainty over the parameters [-] (0 when none is uncertain).
  static T largest_uncertainty(const Uncertainty& eps) noexcept {
    T e = T(0);
    for (int k = 0; k < Cap::kParams; ++k) e = std::fmax(e, eps.rel[k]);
    return e;
  }

  /// The bound on a copy of model (hosts; firmware perturbs in place: compute_in_place).
  /// @param model  the observer's model (description, parameters and inputs set)
  /// @param eps    relative uncertainties, each finite, ≥ 0 and < 0.5
  /// @param m      out: bound per channel [channel unit] (unused channels 0; a partial sum after an error)
  /// @param slowest_tau  out, optional: the slowest time constant over the model and its
  ///                perturbed copies, each at its own steady state [s] (0 where none is
  ///                stable): a ±ε machine may sit on the other side of a valve's opening,
  ///                with that side's time constant; one eigenvalue problem per solve more
  /// @param lead   out, optional: per channel the parameter that moves it most on its own
  ///                (a user's question: which value to pin down to narrow this channel's bound)
  /// @return       kOk; kInvalidParams (eps out of range); kNoSteadyState
  static Status compute(const Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>],
                        T* slowest_tau = nullptr, circuit::BoundLead<T, kN>* lead = nullptr) noexcept {
    typename Model::Output y0;
    const Status s = unperturbed(model, eps, m, slowest_tau, lead, y0);
    if (s != Status::kOk) return s;
    Model p = model;
    return perturbed(p, model.params(), y0, eps, m, slowest_tau, lead);
  }

  /// compute() on model itself: its parameters are perturbed one at a time and, before
  /// this returns, put back, with the warm start its unperturbed solves left: the model
  /// compute() leaves, bit for bit. No model copy on the stack (a firmware monitor's
  /// deepest frame).
  static Status compute_in_place(Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>],
                                 T* slowest_tau = nullptr, circuit::BoundLead<T, kN>* lead = nullptr) noexcept {
    typename Model::Output y0;
    const Status s = unperturbed(model, eps, m, slowest_tau, lead, y0);
    if (s != Status::kOk) return s;
    const Restore restore(model);
    return perturbed(model, restore.params, y0, eps, m, slowest_tau, lead);
  }

 private:
  // Puts a model perturbed in place back: parameters (set_params re-resolves the same
  // coefficients from the same values) and the stiff nodes' warm start.
  struct Restore {
    explicit Restore(Model& m) noexcept : model(m), params(m.params()) {
      for (int j = 0; j < Cap::kNodes; ++j) guess[j] = j < m.n_stiff() ? m.warm_start(j) : T(0);
    }
    Restore(const Restore&) = delete;
    Restore& operator=(const Restore&) = delete;
    ~Restore() {
      model.set_params(params);
      for (int j = 0; j < model.n_stiff(); ++j) model.set_warm_start(j, guess[j]);
    }
    Model& model;
    const typename Model::Params params;
    T guess[circuit::kExtent<Cap::kNodes>]{};
  };

  // Clears the outputs, checks eps, and solves the unperturbed model: its steady outputs
  // y0 and (into slowest_tau) its slowest time constant.
  static Status unperturbed(const Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>], T* slowest_tau,
                            circuit::BoundLead<T, kN>* lead, typename Model::Output& y0) noexcept {
    for (int i = 0; i < kN; ++i) m[i] = T(0);
    if (lead != nullptr) {
      for (int i = 0; i < kN; ++i) {
        lead->param[i] = -1;
        lead->change[i] = T(0);
      }
    }
    for (int k = 0; k < Cap::kParams; ++k) {
      const T e = eps.rel[k];
      if (!(std::isfinite(e) && e >= T(0) && e < T(0.5))) return Status::kInvalidParams;
    }
    typename Model::State xs;
    if (!model.steady_state(xs)) return Status::kNoSteadyState;
    y0 = model.outputs(xs);
    if (slowest_tau != nullptr) {
      *slowest_tau = T(0);
      note_tau(model, xs, *slowest_tau);
    }
    return Status::kOk;
  }

  // tau = 1/(the slowest decay rate of mod at x) [s] when that is slower than tau.
  static void note_tau(const Model& mod, const typename Model::State& x, T& tau) noexcept {
    const T rate = mod.slowest_rate(x);
    if (rate > T(0) && T(1) > rate * tau) tau = T(1) / rate;
  }

  // The rest of the bound after unperturbed(), perturbing p, whose values p0 have the
  // steady outputs y0.
  static Status perturbed(Model& p, const typename Model::Params& p0, const typename Model::Output& y0,
                          const Uncertainty& eps, T (&m)[circuit::kExtent<kN>], T* slowest_tau,
                          circuit::BoundLead<T, kN>* lead) noexcept {
    typename Model::Output y;
    typename Model::State xs;
    const int n = p.description() != nullptr ? p.description()->n_params : 0;
    typename Model::Params v = p0;  // perturbed one parameter at a time
    // Bit k of up[i]: parameter k at +ε_k moved channel i up at least as far as −ε_k did.
    constexpr int kWords = (Cap::kParams + 31) / 32;
    std::uint32_t up[circuit::kExtent<kN>][circuit::kExtent<kWords>] = {};
    for (int k = 0; k < n; ++k) {
      const T e = eps.rel[k];
      if (e == T(0)) continue;
      const T v0 = v.v[k];
      T d[circuit::kExtent<kN>] = {};
      T plus[circuit::kExtent<kN>] = {};
      for (const T side : {T(1) + e, T(1) - e}) {
        v.v[k] = v0 * side;
        p.set_params(v);
        if (!p.valid() || !p.steady_state(xs)) return Status::kNoSteadyState;
        y = p.outputs(xs);
        if (slowest_tau != nullptr) note_tau(p, xs, *slowest_tau);
        for (int i = 0; i < kN; ++i) {
          d[i] = std::fmax(d[i], std::fabs(y[i] - y0[i]));
          if (side > T(1)) {
            plus[i] = y[i];
          } else if (plus[i] >= y[i]) {
            up[i][k / 32] |= std::uint32_t(1) << (k % 32);
          }
        }
      }
      v.v[k] = v0;
      for (int i = 0; i < kN; ++i) {
        m[i] += d[i];
        if (lead != nullptr && d[i] > lead->change[i]) {
          lead->param[i] = k;
          lead->change[i] = d[i];
        }
      }
    }
    // The corners: channel i's "up" and "down" machines. A corner without a steady state
    // (the machine stalls) adds nothing: the sum stands.
    for (int i = 0; i < kN; ++i) {
      for (const bool high : {true, false}) {
        for (int k = 0; k < n; ++k) {
          const T e = eps.rel[k];
          const bool plus = ((up[i][k / 32] >> (k % 32)) & 1u) != 0;
          v.v[k] = p0.v[k] * (plus == high ? T(1) + e : T(1) - e);
        }
        p.set_params(v);
        if (!p.valid() || !p.steady_state(xs)) continue;
        y = p.outputs(xs);
        if (slowest_tau != nullptr) note_tau(p, xs, *slowest_tau);
        m[i] = std::fmax(m[i], std::fabs(y[i] - y0[i]));
      }
    }
    return Status::kOk;
  }
};

}  // namespace hstmon
