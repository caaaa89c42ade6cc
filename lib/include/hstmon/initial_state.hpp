#pragma once
/// @file initial_state.hpp
/// Where a run starts: the one rule the observer, the monitor, the C API, the firmware,
/// `hstmon replay`, `identify` and `gap` all use, so that a log that begins at rest, in
/// a start-up or in operation is met the same way everywhere.
///
/// A model's states are often measured (on the thesis rig both are: Ppp and ωm). The
/// rule:
///  1. every state measured (finite, channel valid) and the result plausible: start there
///     — whatever the machine is doing, at rest, mid start-up or running;
///  2. some measured: start at rest or at the steady state for the inputs, whichever lies
///     closer to the measured states, with the measured ones then set to their readings;
///  3. none measured: the measurements cannot say; start at rest (the start-up hold-off
///     that follows from it, Monitor, then covers a machine that was already running).
/// No allocation, no exceptions; one steady-state solve at most.

#include <cmath>
#include <cstdint>

#include "hstmon/model_concept.hpp"  // model_detail::HasStateCount

namespace hstmon {

/// How the initial state was chosen.
enum class InitialState : std::uint8_t {
  kMeasured = 0,  ///< every state from its measurement
  kRest = 1,      ///< the model's rest state (measured states set to their readings)
  kSteady = 2,    ///< the steady state for the inputs (measured states set to their readings)
};

/// Lower-case name ("measured", "rest", "steady"), for logs and JSON.
constexpr const char* to_string(InitialState k) noexcept {
  return k == InitialState::kMeasured ? "measured" : (k == InitialState::kRest ? "rest" : "steady");
}

/// States a model uses: n_states() where the model has it (a circuit model's kStates is
/// its capacity), else kStates.
template <typename Model>
int used_states(const Model& model) noexcept {
  if constexpr (model_detail::HasStateCount<Model>::value) {
    return model.n_states();
  } else {
    return Model::kStates;
  }
}

/// The initial state for a model whose inputs are already set, from the first sample.
/// @tparam Model  needs kStates, State, Output, state_channel(i) (static or not), rest_state(),
///                steady_state(State&) and state_plausible(State)
/// @param model   the model, inputs set to the first sample's
/// @param y       first measured sample, in output order and units
/// @param valid   bit c set: channel c of y was sampled
/// @param x       out: the initial state (state units)
/// @return        how x was chosen
template <typename Model>
InitialState choose_initial_state(const Model& model, const typename Model::Output& y, std::uint8_t valid,
                                  typename Model::State& x) noexcept {
  using State = typename Model::State;
  using T = typename Model::Scalar;
  const int n = used_states(model);
  unsigned measured = 0;
  State xm = model.rest_state();
  for (int i = 0; i < n; ++i) {
    const int c = model.state_channel(i);
    if (c >= 0 && ((static_cast<unsigned>(valid) >> static_cast<unsigned>(c)) & 1u) != 0 && std::isfinite(y[c])) {
      measured |= 1u << i;
      xm[i] = y[c];
    }
  }
  const unsigned all = n >= 32 ? ~0u : (1u << static_cast<unsigned>(n)) - 1u;
  if (measured == all && model.state_plausible(xm)) {
    x = xm;
    return InitialState::kMeasured;
  }
  if (measured == all) measured = 0;  // implausible readings: as if none were measured

  const State xr = model.rest_state();
  State xs;
  InitialState kind = InitialState::kRest;
  x = xr;
  if (measured != 0 && model.steady_state(xs)) {
    // Closer in each measured state, scaled by the distance rest → steady.
    T d_rest = T(0), d_steady = T(0);
    for (int i = 0; i < n; ++i) {
      if (((measured >> i) & 1u) == 0) continue;
      const T scale = std::fabs(xs[i] - xr[i]);
      if (!(scale > T(0))) continue;
      d_rest += std::fabs(xm[i] - xr[i]) / scale;
      d_steady += std::fabs(xm[i] - xs[i]) / scale;
    }
    if (d_steady < d_rest) {
      x = xs;
      kind = InitialState::kSteady;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (((measured >> i) & 1u) != 0) x[i] = xm[i];
  }
  if (!model.state_plausible(x)) x = kind == InitialState::kSteady ? xs : xr;
  return kind;
}

}  // namespace hstmon
