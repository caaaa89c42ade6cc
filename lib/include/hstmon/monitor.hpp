#pragma once
/// @file monitor.hpp
/// The thesis rig's monitor: ModelMonitor (model_monitor.hpp) on the hand-written reduced
/// model of equations 2.5–2.8 (thesis_reduced.hpp) with its model bound
/// (residual_bounds.hpp). The C API and the firmware use it; a circuit from a file uses
/// circuit/circuit_monitor.hpp instead.

#include "hstmon/model_monitor.hpp"
#include "hstmon/residual_bounds.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace hstmon {

/// The thesis rig's monitor in scalar T (float or double); see ModelMonitor for the sizes.
template <typename T, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8,
          bool UsualTick = ThesisReducedModel<T>::kHasUsualTick>
using Monitor = ModelMonitor<ThesisReducedModel<T>, Capacity, QueueDepth, EventCandidates, UsualTick>;

}  // namespace hstmon
