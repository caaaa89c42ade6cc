#pragma once
/// @file validate.hpp
/// Structural check of a circuit description: indices in range, ports that are nodes,
/// shafts where a kind needs one, the numbers each kind cannot do without. Values are
/// checked when they are resolved (CircuitModel::valid()); this is about the wiring.

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/laws.hpp"

namespace hstmon::circuit {

namespace detail {

template <class Cap>
constexpr bool ref_ok(const Circuit<Cap>& c, Ref r) noexcept {
  return r.kind == RefKind::kNone || (r.kind == RefKind::kParam && r.index < c.n_params) ||
         (r.kind == RefKind::kInput && r.index < c.n_inputs);
}

constexpr bool given(Ref r) noexcept { return r.kind != RefKind::kNone; }

/// An orifice or poppet coefficient: k, or area, Cd and density all three.
constexpr bool coefficient_given(const Element& e) noexcept {
  return given(e.r[kK]) || (given(e.r[kArea]) && given(e.r[kCd]) && given(e.r[kRho]));
}

}  // namespace detail

/// Number of states c yields: volume nodes outside the stiff mask plus free shafts.
template <class Cap>
constexpr int state_count(const Circuit<Cap>& c) noexcept {
  int n = 0;
  for (int i = 0; i < c.n_nodes; ++i) {
    if (c.nodes[i].kind == NodeKind::kVolume && ((c.stiff_mask >> i) & 1u) == 0) ++n;
  }
  for (int s = 0; s < c.n_shafts; ++s) {
    if (!c.shafts[s].driven) ++n;
  }
  return n;
}

/// First structural error of c, or kOk.
template <class Cap>
constexpr CircuitError validate(const Circuit<Cap>& c) noexcept {
  using detail::given;
  using detail::ref_ok;
  if (c.n_nodes > Cap::kNodes || c.n_shafts > Cap::kShafts || c.n_elements > Cap::kElements ||
      c.n_channels > Cap::kChannels || c.n_inputs > Cap::kInputs || c.n_params > Cap::kParams) {
    return CircuitError::kCounts;
  }
  if (!ref_ok(c, c.pressure_max) || !ref_ok(c, c.speed_max)) return CircuitError::kBadRef;
  if (!given(c.pressure_max) || !given(c.speed_max)) return CircuitError::kNoEnvelope;
  for (int i = 0; i < c.n_nodes; ++i) {
    const Node& n = c.nodes[i];
    if (!ref_ok(c, n.K) || !ref_ok(c, n.beta) || !ref_ok(c, n.volume) || !ref_ok(c, n.pressure)) {
      return CircuitError::kBadRef;
    }
    if (n.kind == NodeKind::kVolume && !given(n.K) && !(given(n.beta) && given(n.volume))) {
      return CircuitError::kMissingNumber;
    }
    if (((c.stiff_mask >> i) & 1u) != 0 && n.kind != NodeKind::kVolume) return CircuitError::kStiffNotVolume;
  }
  if (c.n_nodes < 32 && (c.stiff_mask >> c.n_nodes) != 0) return CircuitError::kStiffNotVolume;
  for (int s = 0; s < c.n_shafts; ++s) {
    const Shaft& sh = c.shafts[s];
    if (!ref_ok(c, sh.J) || !ref_ok(c, sh.speed)) return CircuitError::kBadRef;
    if (sh.driven ? !given(sh.speed) : !given(sh.J)) return CircuitError::kMissingNumber;
  }
  for (int k = 0; k < c.n_elements; ++k) {
    const Element& e = c.elements[k];
    for (const Ref& r : e.r) {
      if (!ref_ok(c, r)) return CircuitError::kBadRef;
    }
    if (has_ports(e.kind) && (e.a >= c.n_nodes || e.b >= c.n_nodes || e.a == e.b)) return CircuitError::kBadPort;
    if (has_shaft(e.kind) && (e.shaft < 0 || e.shaft >= c.n_shafts)) return CircuitError::kBadShaft;
    switch (e.kind) {
      case ElementKind::kOrifice:
        if (!detail::coefficient_given(e)) return CircuitError::kMissingNumber;
        break;
      case ElementKind::kPoppet:
        if (!detail::coefficient_given(e) || !given(e.r[kFull])) return CircuitError::kMissingNumber;
        break;
      case ElementKind::kCompPump:
        for (int s = kQ0; s <= kPmax; ++s) {
          if (!given(e.r[s])) return CircuitError::kMissingNumber;
        }
        break;
      default:
        if (!given(e.r[0])) return CircuitError::kMissingNumber;
        break;
    }
  }
  for (int ch = 0; ch < c.n_channels; ++ch) {
    const Channel& h = c.channels[ch];
    const int lim = h.kind == ChannelKind::kPressure ? c.n_nodes
                    : h.kind == ChannelKind::kSpeed  ? c.n_shafts
                                                     : c.n_elements;
    if (h.index >= lim) return CircuitError::kBadChannel;
    if (h.kind == ChannelKind::kFlow && !has_ports(c.elements[h.index].kind)) return CircuitError::kBadChannel;
  }
  if (state_count(c) > Cap::kStates) return CircuitError::kTooManyStates;
  int unknowns = 0;  // volume nodes and free shafts
  for (int i = 0; i < c.n_nodes; ++i) unknowns += c.nodes[i].kind == NodeKind::kVolume ? 1 : 0;
  for (int s = 0; s < c.n_shafts; ++s) unknowns += c.shafts[s].driven ? 0 : 1;
  if (unknowns > Cap::kUnknowns) return CircuitError::kTooManyStates;
  return CircuitError::kOk;
}

}  // namespace hstmon::circuit
