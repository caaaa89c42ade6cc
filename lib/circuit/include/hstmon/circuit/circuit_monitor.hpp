#pragma once
/// @file circuit_monitor.hpp
/// The monitor of any circuit: ModelMonitor (model_monitor.hpp) on the engine's model
/// (circuit_model.hpp) with its model bound (circuit_bound.hpp). Channels are the
/// circuit's sensor channels in file order (Cap::kChannels of them in storage; the unused
/// ones are never measured); fault tables are BasicFaultSignature<Cap::kChannels> rows.
/// CompiledCircuitMonitor is the same monitor on a circuit compiled at build time
/// (compiled_model.hpp: hstmon-circuit-header --compiled), as firmware runs it.

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/circuit/compiled_bound.hpp"
#include "hstmon/model_monitor.hpp"

namespace hstmon::circuit {

/// The monitor of a circuit of capacity Cap in scalar T; see ModelMonitor for the sizes.
template <typename T, class Cap = HostCapacity, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8>
using CircuitMonitor = ModelMonitor<CircuitModel<T, Cap>, Capacity, QueueDepth, EventCandidates>;

/// The monitor of the circuit compiled into Kernel (a generated <name>_compiled.hpp's
/// Kernel), in scalar T: the same monitor, the generated straight-line code on its hot path.
template <typename T, class Kernel, int Capacity = 64, int QueueDepth = 4, int EventCandidates = 8>
using CompiledCircuitMonitor = ModelMonitor<CompiledModel<T, Kernel>, Capacity, QueueDepth, EventCandidates>;

}  // namespace hstmon::circuit
