#pragma once
/// @file replay_events.hpp
/// A replay's events as text, one per line ("  t=80.030000 detected kp- Dp+"), for test
/// failure messages.

#include <string>

#include "hstmon_host/replay.hpp"

namespace hstmon_test {

inline std::string event_lines(const hstmon::host::ReplayResult& r) {
  std::string s;
  for (const auto& e : r.events) {
    s += "  t=" + std::to_string(e.t) + " " + e.event;
    for (const auto& c : e.candidates) s += " " + c.fault;
    s += "\n";
  }
  return s;
}

}  // namespace hstmon_test
