#pragma once
// What `hstmon replay` prints (and the thesis firmware image's oracle, tests/firmware): the
// matcher's events (JSON lines and the human diagnosis block), a channel's residual statistics;
// and the JSON number every hstmon command writes (null for NaN or infinity).
#include <cstddef>
#include <cstdint>
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

/// The keys every replay's first JSON line has: its type ("replay"), the log, its rows and
/// times, the tick, how the observer started, its health and the notes. The circuit replay
/// adds its own (JSON objects keep their keys sorted: where a key is added changes nothing).
/// @param r  a host::ReplayResult or a circuit_tools::CircuitReplayResult
template <class Result>
nlohmann::json replay_head_json(const std::string& log, const Result& r) {
  return {{"type", "replay"},
          {"log", log},
          {"rows", r.rows},
          {"t_first", r.t_first},
          {"t_last", r.t_last},
          {"tick_s", r.tick},
          {"ticks", r.ticks},
          {"start", to_string(r.start)},
          {"startup_hold_s", r.startup_hold},
          {"health", host::health_names(r.health)},
          {"unhealthy_rows", r.unhealthy_rows},
          {"max_substeps", r.max_substeps},
          {"notes", r.notes}};
}

/// The JSON lines that end a replay: the envelope check, every event, and the diagnosis
/// (the final status and the number of events, plus the keys of `more`: a circuit replay's
/// class of the final candidates).
void print_json_diagnosis(const host::EnvelopeResult& envelope, const std::vector<host::ReplayEvent>& events,
                          const std::string& final_status, const nlohmann::json& more = nlohmann::json::object());

/// The human diagnosis block: every event in time order, then the final status.
void print_events(const std::vector<host::ReplayEvent>& events, const std::string& final_status);

/// The human report's observer health line: "ok (max N RK4 substeps per tick)" — with
/// implicit_ticks > 0, "ok (max N steps per tick; K stiff ticks by Rosenbrock steps)" — or
/// the HealthFlag names raised and on how many rows.
void print_observer_health(std::uint32_t health, std::size_t unhealthy_rows, std::uint32_t max_substeps,
                           std::uint64_t implicit_ticks = 0);

}  // namespace hstmon::cli
