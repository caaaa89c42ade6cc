#pragma once
/// @file monitor.hpp
/// The thesis rig's monitor: ModelMonitor (model_monitor.hpp) on the engine's thesis model
/// (circuit/thesis_circuit_model.hpp: thesis.json compiled, in the rig's vocabulary) with
/// the thesis model bound (residual_bounds.hpp). `hstmon replay` without --circuit, the
/// host tools and the tests use it; any other circuit from a file uses
/// circuit/circuit_monitor.hpp. The firmware C API (hstmon_c.h) instantiates ModelMonitor
/// on the hand-written specialisation instead (ThesisReducedModel, equal to the engine by
/// test_thesis_circuit): its 128-byte model and static steady solve fit the C API's 1.5 KiB
/// RAM and 512 B stack, which the engine's 0.7 KB model does not (docs/circuits.md).

#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon/model_monitor.hpp"

namespace hstmon {

/// The thesis rig's monitor in scalar T (float or double); see ModelMonitor for the sizes.
template <typename T, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8,
          bool UsualTick = ThesisCircuitModel<T>::kHasUsualTick>
using Monitor = ModelMonitor<ThesisCircuitModel<T>, Capacity, QueueDepth, EventCandidates, UsualTick>;

}  // namespace hstmon
