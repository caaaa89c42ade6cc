#pragma once
/// @file same_circuit.hpp
/// Whether two circuit descriptions, of any capacities, describe the same circuit: the
/// same counts, envelope references and stiff mask, and the same nodes, shafts, elements
/// and channels in the same order, every number referred to the same parameter or input.
/// The values behind the references are not compared (they are the model's, not the
/// description's). A host that carries circuits compiled at build time (compiled_model.hpp)
/// asks this of a description read from a file before running the compiled code on it.

#include "hstmon/circuit/circuit.hpp"

namespace hstmon::circuit {

namespace same_circuit_detail {

constexpr bool same(const Ref& a, const Ref& b) noexcept { return a.kind == b.kind && a.index == b.index; }

constexpr bool same(const Node& a, const Node& b) noexcept {
  return a.kind == b.kind && same(a.K, b.K) && same(a.beta, b.beta) && same(a.volume, b.volume) &&
         same(a.pressure, b.pressure);
}

constexpr bool same(const Shaft& a, const Shaft& b) noexcept {
  return a.driven == b.driven && same(a.J, b.J) && same(a.speed, b.speed);
}

constexpr bool same(const Element& a, const Element& b) noexcept {
  if (!(a.kind == b.kind && a.a == b.a && a.b == b.b && a.shaft == b.shaft && a.opening_sign == b.opening_sign)) {
    return false;
  }
  for (int s = 0; s < kSlots; ++s) {
    if (!same(a.r[s], b.r[s])) return false;
  }
  return true;
}

constexpr bool same(const Channel& a, const Channel& b) noexcept { return a.kind == b.kind && a.index == b.index; }

}  // namespace same_circuit_detail

/// True when a and b describe the same circuit (see the file comment); O(elements).
template <class CapA, class CapB>
constexpr bool same_circuit(const Circuit<CapA>& a, const Circuit<CapB>& b) noexcept {
  using same_circuit_detail::same;
  if (!(a.n_nodes == b.n_nodes && a.n_shafts == b.n_shafts && a.n_elements == b.n_elements &&
        a.n_channels == b.n_channels && a.n_inputs == b.n_inputs && a.n_params == b.n_params &&
        a.stiff_mask == b.stiff_mask && same(a.pressure_max, b.pressure_max) && same(a.speed_max, b.speed_max))) {
    return false;
  }
  // Counts beyond either capacity describe no circuit (and would index past an array).
  if (a.n_nodes > CapA::kNodes || a.n_nodes > CapB::kNodes || a.n_shafts > CapA::kShafts ||
      a.n_shafts > CapB::kShafts || a.n_elements > CapA::kElements || a.n_elements > CapB::kElements ||
      a.n_channels > CapA::kChannels || a.n_channels > CapB::kChannels) {
    return false;
  }
  for (int i = 0; i < a.n_nodes; ++i) {
    if (!same(a.nodes[i], b.nodes[i])) return false;
  }
  for (int i = 0; i < a.n_shafts; ++i) {
    if (!same(a.shafts[i], b.shafts[i])) return false;
  }
  for (int i = 0; i < a.n_elements; ++i) {
    if (!same(a.elements[i], b.elements[i])) return false;
  }
  for (int i = 0; i < a.n_channels; ++i) {
    if (!same(a.channels[i], b.channels[i])) return false;
  }
  return true;
}

}  // namespace hstmon::circuit
