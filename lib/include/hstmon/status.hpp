#pragma once
/// @file status.hpp
/// Status codes and health flags of the core. Nothing in lib/ throws; functions that can
/// refuse return a Status, and each observer tick leaves a set of HealthFlags that a
/// running controller can read without logging.

#include <cstdint>

namespace hstmon {

/// Result of a configuration call.
enum class Status : std::uint8_t {
  kOk = 0,             ///< accepted
  kInvalidParams = 1,  ///< a model parameter is non-finite or out of its physical range
  kInvalidConfig = 2,  ///< tick, substep limits or gain are non-finite or out of range
  kInvalidInputs = 3,  ///< an input is non-finite or out of its range (e.g. an orifice coefficient < 0)
  kNoSteadyState = 4,  ///< the inputs admit no steady state (e.g. a relief path shut)
};

/// Health flags of one observer tick, OR-ed into a bit set. Zero means healthy.
enum HealthFlag : std::uint32_t {
  kHealthInputNonFinite = 1u << 0,     ///< an input was NaN/Inf or out of range; the last good inputs were held
  kHealthMeasNonFinite = 1u << 1,      ///< a measured channel was NaN/Inf; it was treated as missing
  kHealthSubstepsClipped = 1u << 2,    ///< stiffness needed more substeps than allowed; step may be inaccurate
  kHealthStateNonFinite = 1u << 3,     ///< the model state became NaN/Inf; it was reset to the last good state
  kHealthStateOutOfBounds = 1u << 4,   ///< a state (a speed or pressure) beyond its physical bound for the inputs
  kHealthAlgebraicDiverged = 1u << 5,  ///< a quasi-steady node's solve not contracting (e.g. leakage too strong)
};

}  // namespace hstmon
