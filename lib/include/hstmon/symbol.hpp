#pragma once
/// @file symbol.hpp
/// Observed qualitative symbols of a fault episode, one per measured channel, and the
/// rule that compares them with a signature's predictions (fault_signature.hpp).
///
/// For an abrupt fault from a steady state the first non-zero derivative of a channel's
/// deviation has the sign of the deviation when it first becomes visible, so the slope
/// symbol is the side on which the channel's residual first left its bound (the CUSUM
/// side that alarmed). The magnitude symbol is the sign of the settled deviation: the
/// residual averaged over a window after detection, less its pre-fault baseline, with a
/// dead band (kQualZero inside it). Both may differ when the response reverses (e.g. Dp+:
/// Ppp first rises, then settles lower).

#include <cstdint>

#include "hstmon/fault_signature.hpp"

namespace hstmon {

/// Symbols observed on one channel during a fault episode.
struct ChannelSymbol {
  std::int8_t magnitude = kQualAny;  ///< QualSign of the settled deviation; kQualAny = not yet known
  std::int8_t slope = kQualAny;      ///< QualSign at the onset of the deviation; kQualAny = not deviated yet
  std::uint8_t rank = 0;             ///< order of detection: 1 = first (ties share a rank); 0 = not deviated
};

/// True when an observed symbol does not contradict a predicted one: equal, or either
/// is kQualAny (not predicted / not yet observed).
constexpr bool qual_consistent(int predicted, int observed) noexcept {
  return predicted == kQualAny || observed == kQualAny || predicted == observed;
}

/// QualSign of v with a dead band: kQualZero when |v| ≤ dead, else its sign.
/// @param v     value [any unit]
/// @param dead  half-width of the dead band [same unit], ≥ 0
template <typename T>
constexpr std::int8_t qual_sign(T v, T dead) noexcept {
  return v > dead ? std::int8_t{kQualPlus} : (v < -dead ? std::int8_t{kQualMinus} : std::int8_t{kQualZero});
}

}  // namespace hstmon
