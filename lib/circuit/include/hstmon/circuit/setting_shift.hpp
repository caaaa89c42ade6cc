#pragma once
/// @file setting_shift.hpp
/// What a fault on a setting moves. A relief or check valve's cracking pressure and a
/// compensated pump's cut-in pressure are settings: a spring's preload, adjusted or worn.
/// A change of preload shifts the element's whole characteristic by one pressure and keeps
/// its shape: the full-open pressure moves with the cracking pressure (the override stays),
/// the knee and the dead-head pressure with the cut-in (the curve's fall stays). Lowering
/// the cracking pressure alone would instead stretch the valve's opening over a wider band
/// and make it softer, which no worn or mis-set valve does.
///
/// So a fault on a setting parameter moves its companions — the element's other pressure
/// thresholds — by the same pressure; every other parameter fault is that parameter alone.
/// A companion is taken only when it belongs to this setting alone (every element that
/// reads it reads it in a companion slot of an element set by the same parameter, and
/// nothing else reads it), so a fault never drags a number shared with another element.

#include <cstdint>

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/param_fault.hpp"

namespace hstmon::circuit {

/// The parameters that move with a setting parameter (apply_param_fault's `with`); -1
/// marks an unused entry.
struct SettingCompanions {
  std::int16_t index[kMaxCompanions] = {-1, -1};
};

namespace setting_detail {

inline bool is_param(Ref r, int k) noexcept { return r.kind == RefKind::kParam && r.index == k; }

/// True when element slot s of el is a companion slot of the setting slot it sits beside.
inline bool companion_slot(const Element& el, int s) noexcept {
  if (el.kind == ElementKind::kPoppet) return s == kFull;
  if (el.kind == ElementKind::kCompPump) return s == kPk || s == kPmax;
  return false;
}

/// The setting slot of el, or -1 when el has none.
inline int setting_slot(const Element& el) noexcept {
  if (el.kind == ElementKind::kPoppet) return kCrack;
  if (el.kind == ElementKind::kCompPump) return kPc;
  return -1;
}

/// True when parameter j is read only in companion slots of elements whose setting is
/// parameter k.
template <class Cap>
bool belongs_to(const Circuit<Cap>& c, int j, int k) noexcept {
  if (is_param(c.pressure_max, j) || is_param(c.speed_max, j)) return false;
  for (int i = 0; i < c.n_nodes; ++i) {
    const Node& n = c.nodes[i];
    if (is_param(n.K, j) || is_param(n.beta, j) || is_param(n.volume, j) || is_param(n.pressure, j)) return false;
  }
  for (int s = 0; s < c.n_shafts; ++s) {
    if (is_param(c.shafts[s].J, j) || is_param(c.shafts[s].speed, j)) return false;
  }
  for (int e = 0; e < c.n_elements; ++e) {
    const Element& el = c.elements[e];
    for (int s = 0; s < kSlots; ++s) {
      if (!is_param(el.r[s], j)) continue;
      const int set = setting_slot(el);
      if (!companion_slot(el, s) || set < 0 || !is_param(el.r[set], k)) return false;
    }
  }
  return true;
}

}  // namespace setting_detail

/// The companions of parameter k in circuit c: the pressure thresholds that a fault on k
/// moves by the same pressure (none when k is no element's setting). O(elements²).
template <class Cap>
SettingCompanions setting_companions(const Circuit<Cap>& c, int k) noexcept {
  SettingCompanions out;
  int n = 0;
  for (int e = 0; e < c.n_elements; ++e) {
    const Element& el = c.elements[e];
    const int set = setting_detail::setting_slot(el);
    if (set < 0 || !setting_detail::is_param(el.r[set], k)) continue;
    for (int s = 0; s < kSlots; ++s) {
      const Ref r = el.r[s];
      if (!setting_detail::companion_slot(el, s) || r.kind != RefKind::kParam || r.index == k) continue;
      bool seen = false;
      for (int i = 0; i < n; ++i) seen = seen || out.index[i] == r.index;
      if (seen || n == kMaxCompanions || !setting_detail::belongs_to(c, r.index, k)) continue;
      out.index[n++] = static_cast<std::int16_t>(r.index);
    }
  }
  return out;
}

}  // namespace hstmon::circuit
