#pragma once
/// @file param_fault.hpp
/// A fault on one model parameter, as every part of hstmon applies it: the machine's value
/// is factor × the model's, and the parameter's companions (the other pressure thresholds
/// of a setting, circuit/setting_shift.hpp) move by the same amount.

#include <cstdint>

namespace hstmon {

/// Most companions one parameter has (a compensated pump's cut-in: its knee and dead-head).
constexpr int kMaxCompanions = 2;

/// Applies a fault on parameter k to p: p.v[k] = nominal.v[k]·factor, and each companion j
/// (with[i] ≥ 0) p.v[j] = nominal.v[j] + nominal.v[k]·(factor − 1). Other entries of p are
/// left as they are. Params has an array v [SI].
/// @param factor  the fault, > 0 [-]
template <class Params, typename T>
void apply_param_fault(Params& p, const Params& nominal, int k, const std::int16_t (&with)[kMaxCompanions],
                       T factor) noexcept {
  p.v[k] = nominal.v[k] * factor;
  const T shift = nominal.v[k] * (factor - T(1));
  for (const std::int16_t j : with) {
    if (j >= 0) p.v[j] = nominal.v[j] + shift;
  }
}

}  // namespace hstmon
