#pragma once
/// @file circuit_isolability.hpp
/// Which faults of a circuit its sensors can detect and tell apart, and which added
/// sensor would tell more apart (`hstmon-fdi isolability|sensors --circuit`), from a fault
/// table of the circuit — the one the monitor runs (fdi::circuit_signature_table: the
/// steady magnitudes and directions of circuit_faults.hpp plus the slopes and orders of
/// the circuit's causal graph), which the caller builds: circuit_tools cannot call fdi
/// (fdi depends on it), so the table, or its builder, is a parameter.
///
/// Two hypotheses are isolable when some observation the matcher (fault_matcher.hpp) reads
/// contradicts one without the other. Three kinds, each reported (Isolability::split):
///  - *steady*: a magnitude symbol is opposite (+ against −, or a structural 0 — the fault
///    cannot move that channel at all — against a ±; a merely small 0 is what a smaller
///    fault of the other kind shows), or the directions are not parallel (cosine below
///    1 − 1e-6; parallel: the same steady residual up to its size, e.g. a pump's
///    displacement and its stroke, which enter only as their product). A sensor row and a
///    fault that moves its channel alone are not isolable this way, and weakly when the
///    fault's direction is within ≈ 11° of that channel (the matcher scores a sensor row
///    by the deviation's share on its channel);
///  - *slope*: on some channel both rows' slopes are known (not `?`) and differ — the
///    matcher reads the sign at the channel's alarm onset, and a predicted 0 is
///    contradicted by any alarm there;
///  - *order*: both rows' orders are known (not all 0, the table's "any order") and under
///    one fault, whose first-alarming channels are its fastest responding ones, the
///    other's order test fails: none of those channels has the other row's smallest
///    order among the channels the fault moves (± magnitude) or moves first
///    (order_slack 0, the monitor's).
/// Sensor rows are judged on the steady rule alone: their slopes and orders are not the
/// graph's, and their 0s are the structural zeros it already reads (a fault that moves
/// another channel by a share too small to alarm there leaves a sensor row standing).
/// The table decides what is known: the monitor's keeps a slope or a row's orders only
/// where they hold for the nonlinear engine (docs/fdi.md §10), and the steady-state table
/// (circuit_fault_table, or SignatureParts::kSteadyOnly) has none.
/// A pair only the steady directions split, within ≈ 11° (cosine ≥ 0.98), is isolable
/// weakly: sensor noise and model error reorder them. Classes are the connected sets of the
/// not-isolable relation. Faults that move no channel by one σ are undetectable at the
/// nominal point.
///
/// Sensor placement: every pressure node, free shaft and element flow not yet measured is
/// tried as one added channel (added_sensors.hpp: its σ that of the circuit's sensors of the
/// same quantity, else 1 % of the envelope); the caller's table builder makes the table with
/// it (fdi::circuit_signature_table derives the added channel's slopes and orders from the
/// same causal graph); candidates are ranked by how many of today's classes they split,
/// then by how many undetectable faults they make detectable, then by how many weak pairs
/// they make clear.

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/fault_table_builders.hpp"

namespace hstmon::circuit_tools {

/// What tells a pair apart: bits of Isolability::split (see the file comment).
enum SplitBy : unsigned {
  kSplitSteady = 1u,      ///< magnitudes, or directions more than ≈ 11° apart
  kSplitSlope = 2u,       ///< a channel's slope at its alarm onset
  kSplitOrder = 4u,       ///< which channels alarm first
  kSplitSteadyWeak = 8u,  ///< only directions within ≈ 11° (weakly isolable on their own)
};

/// Which parts of the table's signatures the relation reads.
enum class SignatureParts {
  kFull,        ///< magnitudes, directions, slopes and orders: what the matcher reads
  kSteadyOnly,  ///< magnitudes and directions alone (the steady-state relation)
};

/// Detectability and isolability of one sensor set.
struct Isolability {
  std::vector<std::string> faults;               ///< table rows, in order
  std::vector<std::vector<int>> isolable;        ///< [i][j]: 1 isolable, 0 not, 2 weakly (only the steady directions split, within 11°)
  std::vector<std::vector<unsigned>> split;      ///< [i][j]: SplitBy bits of what splits the pair (0: not isolable, and on the diagonal)
  std::vector<std::vector<std::string>> classes; ///< not-isolable classes of two or more
  std::vector<std::pair<std::string, std::string>> weak;  ///< weakly isolable pairs (outside a common class)
  std::vector<std::string> undetectable;         ///< no channel moves by 1 σ at 30 %
};

/// Isolability of a circuit's table t (see the file comment).
Isolability circuit_isolability(const CircuitFaultTable& t, SignatureParts parts = SignatureParts::kFull);

/// One candidate sensor's effect.
struct SensorCandidate {
  std::string name;                     ///< "p(Pmi)", "w(motor)", "q(dcv)"
  int classes_split = 0;                ///< of today's classes, how many it splits
  int made_detectable = 0;              ///< of today's undetectable faults, how many it makes detectable
  int weak_cleared = 0;                 ///< of today's weak pairs, how many it makes clear
  std::vector<std::vector<std::string>> classes;  ///< the classes with it
};

/// Every candidate sensor of c, best first (see the file comment), each judged on the table
/// `build` makes for c with it (build.with_each_sensor), read as `parts` says, against
/// today's: `today` when given (c's table by build.table, already built), else build.table(c).
/// @throws std::runtime_error as build.table for c itself (no steady state at the nominal inputs)
std::vector<SensorCandidate> rank_added_sensors(const LoadedCircuit& c,
                                                const FaultTableBuilders& build = steady_fault_tables(),
                                                SignatureParts parts = SignatureParts::kFull,
                                                const CircuitFaultTable* today = nullptr);

}  // namespace hstmon::circuit_tools
