#pragma once
/// @file campaign_score.hpp
/// Scoring of one monitored fault run by its matcher events, shared by the thesis rig's
/// campaign (fault_campaign.cpp) and the campaign for any circuit (circuit_campaign.cpp),
/// so both count as ../shared/validation/score_monitor.py does.

#include <string>
#include <vector>

#include "hstmon_host/replay_event.hpp"

namespace hstmon_campaign {

/// True for the matcher's decisions: "isolated", "ambiguous", "unexplained".
bool is_decision(const std::string& event);

/// Scoring of one fault run.
struct Scored {
  int false_events = 0;      ///< detections before the fault
  bool detected = false;     ///< a detection at or after the fault
  double delay = 0.0;        ///< first detection − fault [s]
  bool decided = false;      ///< isolated/ambiguous/unexplained after the fault
  bool in_set = false;       ///< truth in the last decision's set (candidates within the tie margin of the best)
  bool in_last = false;      ///< truth among the last event's candidates (score_monitor.py's rule)
  bool best_in_last = false; ///< truth the first of those candidates
  std::vector<std::string> last_set;  ///< those candidates within the tie margin of their best
  std::string last;          ///< that event as text ("isolated at 4.460 s: Rplkg+ 0.96 …"; "" if none)
  bool isolated_as_truth = false;  ///< last decision isolated with the truth best
  /// The last decision isolates the truth or its class: `isolated` with the truth among the
  /// candidates that tie with the first (a group that acts as one) or the first in the
  /// truth's class, or `ambiguous` with every candidate in such a tie or in that class and
  /// the truth among them (the rule of ../shared/validation/circuits/score_circuit.py).
  bool isolated_class = false;
  double isolation_delay = 0.0;  ///< from the fault to the first of the decisions that all isolate it so [s]
  double size = 0.0;             ///< the truth's fitted size in the last decision (factor or offset; NaN if none)
  bool cleared_at_end = false;   ///< the run's last event, after the fault, is "cleared" (nothing named)
  bool called_sensor = false;      ///< a decision after the fault named a sensor fault best (parameter faults)
  int set_size = 0;
  std::string best;          ///< best candidate of the last decision ("" if none)
};

/// Scores the events of a run whose fault `truth` starts at t_fault [s]; tie_margin [rad].
/// @param truth_class the faults the sensors cannot tell from the truth (the truth among them
///        or not; empty: only the truth and the candidates that tie with it)
/// @param clear_names_nothing a run whose last event is `cleared` names nothing (the rule of
///        score_circuit.py and score_paper.py); false: the last decision stands whatever
///        follows (score_monitor.py's rule). cleared_at_end is set either way.
Scored score(const std::vector<hstmon::host::ReplayEvent>& events, const std::string& truth, double t_fault,
             double tie_margin, const std::vector<std::string>& truth_class = {}, bool clear_names_nothing = false);

}  // namespace hstmon_campaign
