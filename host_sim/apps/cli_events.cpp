// The matcher's events as hstmon replay prints them (cli_events.hpp).
#include "cli_events.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hstmon::cli {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

void add_residual_stats(nlohmann::json& j, const host::ChannelStats& s) {
  if (s.n == 0) return;
  j["mean"] = number_or_null(s.mean());
  j["rms"] = number_or_null(s.rms());
  j["max_abs"] = number_or_null(s.max_abs);
  j["max"] = number_or_null(s.max_signed);
  j["t_max"] = s.t_max;
  j["noise"] = number_or_null(s.noise());
}

nlohmann::json event_json(const host::ReplayEvent& e) {
  nlohmann::json cands = nlohmann::json::array();
  for (const auto& c : e.candidates) {
    nlohmann::json j = {{"fault", c.fault}, {"score", c.score}};
    if (std::isfinite(c.size)) {
      j["size"] = c.size;
      j["size_lo"] = number_or_null(c.size_lo);
      j["size_hi"] = number_or_null(c.size_hi);
      j["size_text"] = c.size_text;
    }
    cands.push_back(std::move(j));
  }
  nlohmann::json j = {{"type", "event"}, {"t", e.t}, {"event", e.event}, {"consistent", e.consistent}, {"candidates", cands}};
  if (!e.why.empty()) j["why"] = e.why;
  return j;
}

std::string candidate_list(const host::ReplayEvent& e, std::size_t show) {
  std::string out;
  for (std::size_t j = 0; j < e.candidates.size() && j < show; ++j) {
    const host::ReplayCandidate& c = e.candidates[j];
    out += fmt::format("{}{} ({:.3f}{})", j ? ", " : "", c.fault, c.score, c.size_text.empty() ? "" : "; " + c.size_text);
  }
  const std::size_t more = static_cast<std::size_t>(e.consistent) > show ? static_cast<std::size_t>(e.consistent) - show : 0;
  if (more > 0) out += fmt::format(" and {} more", more);
  return out;
}

nlohmann::json envelope_json(const host::EnvelopeResult& e) {
  return {{"type", "envelope"}, {"checked", e.checked}, {"out", e.out}, {"unverified", e.unverified}, {"text", e.text}};
}

void print_events(const std::vector<host::ReplayEvent>& events, const std::string& final_status) {
  if (events.empty()) {
    fmt::print("\n  diagnosis: no fault detected (status {})\n", final_status);
    return;
  }
  fmt::print("\n  diagnosis (single-fault hypotheses, best first):\n");
  for (const auto& e : events) {
    if (e.event == "cleared") {
      fmt::print("    t = {:>9.3f} s  cleared: residuals back within their bounds\n", e.t);
    } else if (e.event == "isolated") {
      fmt::print("    t = {:>9.3f} s  isolated: {}\n", e.t, candidate_list(e, 3));
    } else if (e.event == "out_of_envelope") {
      fmt::print("    t = {:>9.3f} s  out of envelope: {}\n", e.t, e.why);
    } else if (e.event == "unverified") {
      fmt::print("    t = {:>9.3f} s  {}\n", e.t, e.why);
    } else if (e.event == "detected" && e.candidates.empty()) {
      fmt::print("    t = {:>9.3f} s  detected: {}; candidates from the first steady window\n", e.t,
                 e.why.empty() ? "residuals beyond their bounds" : e.why);
    } else if (e.event == "detected") {
      fmt::print("    t = {:>9.3f} s  detected: {} hypotheses consistent so far: {}\n", e.t, e.consistent, candidate_list(e, 4));
    } else {
      fmt::print("    t = {:>9.3f} s  {}: {}\n", e.t, e.event, candidate_list(e, 4));
    }
    if (!e.why.empty() && (e.event == "isolated" || e.event == "ambiguous" || e.event == "unexplained")) {
      fmt::print("                   ({})\n", e.why);
    }
  }
  fmt::print("    status at the end of the log: {}\n", final_status);
}

void print_json_diagnosis(const host::EnvelopeResult& envelope, const std::vector<host::ReplayEvent>& events,
                          const std::string& final_status, const nlohmann::json& more) {
  fmt::print("{}\n", envelope_json(envelope).dump());
  for (const auto& e : events) fmt::print("{}\n", event_json(e).dump());
  nlohmann::json d = {{"type", "diagnosis"}, {"status", final_status}, {"events", events.size()}};
  for (auto it = more.begin(); it != more.end(); ++it) d[it.key()] = it.value();
  fmt::print("{}\n", d.dump());
}

void print_observer_health(std::uint32_t health, std::size_t unhealthy_rows, std::uint32_t max_substeps,
                           std::uint64_t implicit_ticks) {
  const auto names = host::health_names(health);
  if (names.empty() && implicit_ticks > 0) {
    fmt::print("\n  observer health: ok (max {} steps per tick; {} stiff ticks by Rosenbrock steps)\n", max_substeps,
               implicit_ticks);
  } else if (names.empty()) {
    fmt::print("\n  observer health: ok (max {} RK4 substeps per tick)\n", max_substeps);
  } else {
    std::string joined;
    for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
    fmt::print("\n  observer health: {} on {} rows — results there are not trustworthy\n", joined, unhealthy_rows);
  }
}

}  // namespace hstmon::cli
