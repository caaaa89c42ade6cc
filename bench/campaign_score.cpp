// Scoring of one monitored fault run by its events (campaign_score.hpp).
#include "campaign_score.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hstmon_campaign {

bool is_decision(const std::string& e) { return e == "isolated" || e == "ambiguous" || e == "unexplained"; }

namespace {

// A matcher score (a cosine) as an angle [rad].
double angle(double c) { return std::acos(std::fmin(1.0, std::fmax(-1.0, c))); }

// Whether decision e isolates the truth or its class (Scored::isolated_class): a candidate
// is alike when it is in the class or ties the truth's weight (hypotheses that act as one).
bool isolates(const hstmon::host::ReplayEvent& e, const std::string& truth, const std::vector<std::string>& cls) {
  if (e.candidates.empty() || (e.event != "isolated" && e.event != "ambiguous")) return false;
  const auto it =
      std::find_if(e.candidates.begin(), e.candidates.end(), [&](const auto& c) { return c.fault == truth; });
  const auto alike = [&](const hstmon::host::ReplayCandidate& c) {
    if (c.fault == truth || std::find(cls.begin(), cls.end(), c.fault) != cls.end()) return true;
    return it != e.candidates.end() && std::fabs(c.score - it->score) <= 1e-6 * std::fmax(1.0, it->score);
  };
  if (e.event == "isolated") return alike(e.candidates[0]);
  return std::all_of(e.candidates.begin(), e.candidates.end(), alike);
}

// The decisions of a run, as if nothing came after the last of them (score() adds a clear).
Scored score_decisions(const std::vector<hstmon::host::ReplayEvent>& events, const std::string& truth, double t_fault,
                       double tie_margin, const std::vector<std::string>& truth_class) {
  Scored s;
  const double eps = 1e-9;
  const hstmon::host::ReplayEvent* last_decision = nullptr;
  const hstmon::host::ReplayEvent* last_with_cands = nullptr;
  for (const auto& e : events) {
    if (e.t < t_fault - eps) {
      if (e.event == "detected") ++s.false_events;
      continue;
    }
    if (e.event == "detected" && !s.detected) {
      s.detected = true;
      s.delay = e.t - t_fault;
    }
    if (is_decision(e.event)) {
      last_decision = &e;
      if (!e.candidates.empty() && e.candidates[0].fault.rfind("sensor_", 0) == 0 && truth.rfind("sensor_", 0) != 0) {
        s.called_sensor = true;
      }
    }
    if ((e.event == "isolated" || e.event == "detected" || e.event == "ambiguous") && !e.candidates.empty()) {
      last_with_cands = &e;
    }
  }
  if (last_with_cands) {
    const auto& cands = last_with_cands->candidates;
    for (const auto& c : cands) s.in_last = s.in_last || c.fault == truth;
    s.best_in_last = cands[0].fault == truth;
    const double a0 = angle(cands[0].score);
    for (const auto& c : cands) {
      if (angle(c.score) - a0 <= tie_margin) s.last_set.push_back(c.fault);
    }
    char b[48];
    std::snprintf(b, sizeof b, " at %.3f s:", last_with_cands->t);
    s.last = last_with_cands->event + b;
    for (const auto& c : cands) {
      std::snprintf(b, sizeof b, " %.2f", c.score);
      s.last += " " + c.fault + b;
    }
  }
  if (!last_decision) return s;
  s.decided = true;
  const auto& e = *last_decision;
  if (e.candidates.empty() || e.event == "unexplained") return s;
  s.best = e.candidates[0].fault;
  const double a0 = angle(e.candidates[0].score);
  for (std::size_t j = 0; j < e.candidates.size(); ++j) {
    if (j > 0 && !(angle(e.candidates[j].score) - a0 < tie_margin)) continue;
    ++s.set_size;
    s.in_set = s.in_set || e.candidates[j].fault == truth;
  }
  s.isolated_as_truth = e.event == "isolated" && s.best == truth;
  s.size = std::nan("");
  for (const auto& c : e.candidates) {
    if (c.fault == truth) s.size = c.size;
  }
  // The first decision of the run's final stretch of decisions that all isolate the truth.
  for (auto it = events.rbegin(); it != events.rend() && it->t >= t_fault - eps; ++it) {
    if (!is_decision(it->event)) continue;
    if (!isolates(*it, truth, truth_class)) break;
    s.isolated_class = true;
    s.isolation_delay = it->t - t_fault;
  }
  return s;
}

}  // namespace

Scored score(const std::vector<hstmon::host::ReplayEvent>& events, const std::string& truth, double t_fault,
             double tie_margin, const std::vector<std::string>& truth_class, bool clear_names_nothing) {
  Scored s = score_decisions(events, truth, t_fault, tie_margin, truth_class);
  // A fault persists to the end of the run: a last word "cleared" is wrong, and under
  // score_circuit.py's rule it names nothing, whatever came before.
  s.cleared_at_end = !events.empty() && events.back().t >= t_fault - 1e-9 && events.back().event == "cleared";
  if (s.cleared_at_end && clear_names_nothing) {
    s.in_last = s.best_in_last = s.in_set = s.isolated_as_truth = s.isolated_class = false;
  }
  return s;
}

}  // namespace hstmon_campaign
