#pragma once
/// @file stiffness.hpp
/// Which volume nodes to take quasi-steady, found from the circuit: capacitance against
/// conductance at the tick. A node is stiff when its *guaranteed* conductance G_min (the
/// least it keeps anywhere in the envelope, laws.hpp) makes its own time constant so
/// short that explicit RK4 would need more than about ten substeps per tick,
/// K·G_min·h ≥ κ (κ = 8 with the observer's |λ|·h ≤ 0.8). The guaranteed conductance,
/// not the one at an operating point, because a node whose conductance can vanish (a
/// line behind a check valve that closes) has real dynamics there and must stay a state.
/// Nodes are taken stiffest first, and one is only added while the solve's a-priori
/// contraction factor (CircuitModel::contraction_bound) stays ≤ 0.5 for every stiff node.

#include <cstdint>

#include "hstmon/circuit/circuit_model.hpp"

namespace hstmon::circuit {

/// The stiff-node mask for circuit c under parameters p and nominal inputs u at tick h.
/// @tparam T      scalar of the model used for the decision
/// @param c       the description (its own stiff_mask is ignored)
/// @param p       parameter values
/// @param u       nominal inputs (orifice openings enter the guaranteed conductances)
/// @param tick    observer tick h [s], > 0
/// @param kappa   K·G_min·h at and above which a node is stiff [-]
/// @param states  out, optional: the number of states the mask leaves
/// @return        bit i set: node i stiff; 0 if c is not a valid description
template <typename T, class Cap>
std::uint32_t auto_stiff_mask(const Circuit<Cap>& c, const typename CircuitModel<T, Cap>::Params& p,
                              const typename CircuitModel<T, Cap>::Inputs& u, T tick, T kappa = T(8),
                              int* states = nullptr) noexcept {
  // Classified on a model with room for every node as a state (c's own capacity may
  // only hold the states that remain once the stiff nodes are out).
  using Full = Capacity<Cap::kNodes, Cap::kShafts, Cap::kElements, Cap::kChannels, Cap::kInputs, Cap::kParams>;
  Circuit<Full> plain;
  plain.n_nodes = c.n_nodes;
  plain.n_shafts = c.n_shafts;
  plain.n_elements = c.n_elements;
  plain.n_channels = c.n_channels;
  plain.n_inputs = c.n_inputs;
  plain.n_params = c.n_params;
  plain.pressure_max = c.pressure_max;
  plain.speed_max = c.speed_max;
  for (int i = 0; i < Cap::kNodes; ++i) plain.nodes[i] = c.nodes[i];
  for (int i = 0; i < (Cap::kShafts > 0 ? Cap::kShafts : 1); ++i) plain.shafts[i] = c.shafts[i];
  for (int i = 0; i < Cap::kElements; ++i) plain.elements[i] = c.elements[i];
  for (int i = 0; i < Cap::kChannels; ++i) plain.channels[i] = c.channels[i];
  CircuitModel<T, Full> m;
  if (m.bind(plain) != CircuitError::kOk) return 0;
  typename CircuitModel<T, Full>::Inputs uf;
  typename CircuitModel<T, Full>::Params pf;
  for (int i = 0; i < Cap::kInputs; ++i) uf.v[i] = u.v[i];
  for (int i = 0; i < Cap::kParams; ++i) pf.v[i] = p.v[i];
  m.set_inputs(uf);
  m.set_params(pf);
  // Each volume's K·G_min·h, then take them stiffest first.
  T stiffness[kExtent<Cap::kNodes>];
  for (int i = 0; i < c.n_nodes; ++i) {
    stiffness[i] = T(0);
    if (c.nodes[i].kind != NodeKind::kVolume) continue;
    T g_min, g_fix, s_max;
    m.conductance_bounds(i, 0u, g_min, g_fix, s_max);
    stiffness[i] = m.node_stiffness(i) * g_min * tick;
  }
  std::uint32_t mask = 0;
  for (;;) {
    int best = -1;
    for (int i = 0; i < c.n_nodes; ++i) {
      if (stiffness[i] >= kappa && (best < 0 || stiffness[i] > stiffness[best])) best = i;
    }
    if (best < 0) break;
    stiffness[best] = T(0);  // decided either way
    const std::uint32_t trial = mask | (1u << best);
    bool ok = true;
    for (int i = 0; i < c.n_nodes && ok; ++i) {
      if (((trial >> i) & 1u) == 0) continue;
      T g_min, g_fix, s_max;
      m.conductance_bounds(i, trial, g_min, g_fix, s_max);
      ok = g_fix > T(0) && s_max <= g_fix;  // S/(S + G) ≤ 0.5
    }
    if (ok) mask = trial;
  }
  if (states != nullptr) {
    plain.stiff_mask = mask;
    *states = state_count(plain);
  }
  return mask;
}

}  // namespace hstmon::circuit
