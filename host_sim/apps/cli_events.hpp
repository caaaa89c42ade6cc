#pragma once
// What `hstmon replay` prints for the thesis rig and for any circuit alike: the matcher's
// events (JSON lines and the human diagnosis block) and a channel's residual statistics;
// and the JSON number every hstmon command writes (null for NaN or infinity).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// v as a JSON number, or null when it is not finite (JSON has no NaN or infinity).
nlohmann::json number_or_null(double v);

/// Adds a channel's residual statistics to j (when s has samples): mean, rms, max_abs,
/// max, t_max, noise [SI].
void add_residual_stats(nlohmann::json& j, const host::ChannelStats& s);

/// One event as a JSON line object: {"type":"event","t",...,"candidates":[{fault,score}]}.
nlohmann::json event_json(const host::ReplayEvent& e);
/// The envelope check's JSON line: {"type":"envelope","checked","out","unverified","text"}.
nlohmann::json envelope_json(const host::EnvelopeResult& e);

/// Candidates in words: "kp- (0.998), Pbp+ (0.71) and 3 more" (at most `show` named).
std::string candidate_list(const host::ReplayEvent& e, std::size_t show);

/// The human diagnosis block: every event in time order, then the final status.
void print_events(const std::vector<host::ReplayEvent>& events, const std::string& final_status);

}  // namespace hstmon::cli
