#pragma once
// The matcher's events as `hstmon replay` prints them, for the thesis rig and for any
// circuit alike: JSON lines and the human diagnosis block.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// One event as a JSON line object: {"type":"event","t",...,"candidates":[{fault,score}]}.
nlohmann::json event_json(const host::ReplayEvent& e);

/// Candidates in words: "kp- (0.998), Pbp+ (0.71) and 3 more" (at most `show` named).
std::string candidate_list(const host::ReplayEvent& e, std::size_t show);

/// The human diagnosis block: every event in time order, then the final status.
void print_events(const std::vector<host::ReplayEvent>& events, const std::string& final_status);

}  // namespace hstmon::cli
