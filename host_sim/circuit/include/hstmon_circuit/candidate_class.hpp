#pragma once
/// @file candidate_class.hpp
/// The final verdict of a circuit replay said plainly: what the remaining candidates share
/// (fault_words.hpp: "a leak from line A") and what would tell them apart, e.g.
/// "a leak from line A: R_ext_a-, R_ip-, R_im- (a flow meter on drain_a would tell them apart)".
///
/// What would split them is chosen from the circuit's isolability (circuit_isolability.hpp):
///  - the candidates are grouped by the not-isolable relation: two stay together while no
///    observation the matcher reads contradicts one without the other;
///  - when the nominal point's sensors already split every pair, more settled evidence
///    would (the table tells them apart; the log did not show enough of it);
///  - else each single added channel of the sensor placement (rank_added_sensors) and a
///    change of operating point (operating_points.hpp) are judged by how many groups they
///    split the candidates into; the most wins, a change of operating point on a tie (it
///    needs no hardware), an added sensor ranked earlier on a tie between sensors;
///  - nothing in reach: neither splits any pair.

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_host/replay_event.hpp"

namespace hstmon::circuit_tools {

/// What the final candidates share and what would split them.
struct CandidateClass {
  std::vector<std::string> candidates;  ///< the candidates described, best first
  std::string description;  ///< what they share, "a leak from line A"; for one candidate, that fault in words
  /// What would tell them apart: "a flow meter on drain_a", "a change of operating point
  /// (T_L 50 %)", "more settled data at a steady operating point", "nothing in reach";
  /// "" for one candidate
  std::string split_by;
  int groups_now = 0;    ///< groups the candidates fall into with today's sensors at the nominal point
  int groups_split = 0;  ///< groups with `split_by` (= groups_now when nothing splits them)
  /// "<description>: <candidates> (<split_by> would tell them apart)"; "" without candidates
  std::string sentence;
};

/// The candidates a replay's final verdict names: the last event's first candidate when
/// that event is `isolated`, its consistent ones (its first `consistent`, at least one) when
/// it is `detected` or `ambiguous`; none after any other last event (cleared, unexplained,
/// out of envelope) or without events.
std::vector<std::string> verdict_candidates(const std::vector<host::ReplayEvent>& events);

/// The class of `candidates` (fault rows of c's table, best first; see the file comment),
/// each table made by `build` and read in full (SignatureParts::kFull). Candidates that
/// are no row of the nominal table stay a group of their own. `nominal`: c's table
/// (build.table), when the caller has it already (the replay's); else it is built here,
/// once. At the other operating points only the candidates' rows are built (build.rows).
/// @throws std::runtime_error as build.table for c itself (no steady state at the nominal inputs)
CandidateClass candidate_class(const LoadedCircuit& c, const std::vector<std::string>& candidates,
                               const FaultTableBuilders& build = steady_fault_tables(),
                               const CircuitFaultTable* nominal = nullptr);

}  // namespace hstmon::circuit_tools
