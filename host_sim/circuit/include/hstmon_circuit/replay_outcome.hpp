#pragma once
/// @file replay_outcome.hpp
/// Did a circuit replay run at all? replay_circuit() returns without a tick when it cannot
/// start (no steady state, a log without rows, …) and says why in a note ending
/// ": nothing replayed"; a caller reports that as an error, never as quiet residuals
/// (`hstmon replay --circuit`, the Python module).

#include <string>

#include "hstmon_circuit/circuit_replay.hpp"

namespace hstmon::circuit_tools {

/// Why the replay stopped before its first tick (its note, without the tail), or "" when it ran.
inline std::string why_not_replayed(const CircuitReplayResult& r) {
  if (r.ticks > 0) return {};
  const std::string tail = ": nothing replayed";
  for (const std::string& n : r.notes) {
    const std::size_t at = n.rfind(tail);
    if (at != std::string::npos) return n.substr(0, at);
  }
  return "the log has no rows";
}

}  // namespace hstmon::circuit_tools
