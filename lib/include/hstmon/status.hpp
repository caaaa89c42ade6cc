#pragma once
/// @file status.hpp
/// Status codes and health flags of the core. Nothing in lib/ throws; functions that can
/// refuse return a Status, and each observer tick leaves a set of HealthFlags that a
/// running controller can read without logging.

#include <cstdint>

namespace hstmon {

/// Result of a configuration call.
enum class Status : std::uint8_t {
  kOk = 0,               ///< accepted
  kInvalidParams = 1,    ///< a model parameter is non-finite or out of its physical range
  kInvalidConfig = 2,    ///< tick, substep limits or gain are non-finite or out of range
  kInvalidInputs = 3,    ///< an input (Psupl, Ps, Pbp, kp) is non-finite or kp < 0
  kNoSteadyState = 4,    ///< the inputs admit no steady state (e.g. kp = 0)
};

/// Health flags of one observer tick, OR-ed into a bit set. Zero means healthy.
enum HealthFlag : std::uint32_t {
  kHealthInputNonFinite = 1u << 0,     ///< an input was NaN/Inf or kp < 0; the last good inputs were held
  kHealthMeasNonFinite = 1u << 1,      ///< a measured channel was NaN/Inf; it was treated as missing
  kHealthSubstepsClipped = 1u << 2,    ///< stiffness needed more substeps than allowed; step may be inaccurate
  kHealthStateNonFinite = 1u << 3,     ///< the model state became NaN/Inf; it was reset to the last good state
  kHealthStateOutOfBounds = 1u << 4,   ///< ωm or Ppp beyond the physical bound for the inputs
  kHealthAlgebraicDiverged = 1u << 5,  ///< quasi-steady DCV solve not contracting (leakage too strong)
};

}  // namespace hstmon
