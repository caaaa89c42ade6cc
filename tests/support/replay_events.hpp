#pragma once
/// @file replay_events.hpp
/// A replay's events as text, one per line ("  t=80.030000 detected kp- Dp+"), for test
/// failure messages: a thesis replay's (host::ReplayResult) or a circuit's
/// (circuit_tools::CircuitReplayResult), both lists of host::ReplayEvent.

#include <string>

#include "hstmon_host/replay.hpp"

namespace hstmon_test {

template <class Result>
std::string event_lines(const Result& r) {
  if (r.events.empty()) return "  (no events)\n";
  std::string s;
  for (const hstmon::host::ReplayEvent& e : r.events) {
    s += "  t=" + std::to_string(e.t) + " " + e.event;
    for (const auto& c : e.candidates) s += " " + c.fault;
    s += "\n";
  }
  return s;
}

}  // namespace hstmon_test
