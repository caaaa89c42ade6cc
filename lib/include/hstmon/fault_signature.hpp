#pragma once
/// @file fault_signature.hpp
/// The fault-signature table the matcher runs on: one row per single-fault hypothesis,
/// with the qualitative signature the temporal causal graph predicts on each measured
/// channel and a quantitative residual direction for faults whose qualitative
/// signatures coincide. Tables are `constexpr` arrays of these aggregates, generated on
/// the host (see docs/fdi.md) so they live in flash.

#include <cstddef>
#include <cstdint>

namespace hstmon {

/// Number of measured channels of the thesis rig (Pmi, Pmo, Ppp, ωm; see ThesisChannel).
inline constexpr int kFdiChannels = 4;

/// Qualitative value of a symbol: sign of a deviation or of its slope.
enum QualSign : std::int8_t {
  kQualMinus = -1,  ///< below nominal / falling
  kQualZero = 0,    ///< no change predicted (the channel does not respond)
  kQualPlus = 1,    ///< above nominal / rising
  kQualAny = 2,     ///< not predicted (ambiguous path); consistent with any observation
};

/// Predicted behaviour of one channel after one fault.
struct ChannelSignature {
  std::int8_t magnitude;  ///< QualSign of the steady-state deviation
  std::int8_t slope;      ///< QualSign of the first non-zero time derivative after the fault
  std::uint8_t order;     ///< integrations on the fastest causal path fault → channel (0 = instantaneous)
};

/// One single-fault hypothesis over N measured channels (a circuit's sensor channels in
/// its order; the thesis rig's 4 in ThesisChannel order).
template <int N>
struct BasicFaultSignature {
  static constexpr int kChannels = N;  ///< channels the row describes
  const char* name;                    ///< "kp-", "Rbl+", "sensor_p_pp", …
  bool sensor;                         ///< true for a sensor fault (one channel alone)
  ChannelSignature channel[static_cast<std::size_t>(N)];       ///< per channel
  /// Unit vector of the steady-state residual for a small fault, each channel divided by
  /// its noise level (at the nominal point) [-]: the quantitative tie-break between
  /// hypotheses with the same qualitative signature. All zero for sensor faults.
  float direction[static_cast<std::size_t>(N)];
};

/// A row of the thesis rig's table (4 channels: Pmi, Pmo, Ppp, ωm).
using FaultSignature = BasicFaultSignature<kFdiChannels>;

}  // namespace hstmon
