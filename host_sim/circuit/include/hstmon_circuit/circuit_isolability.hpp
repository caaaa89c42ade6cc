#pragma once
/// @file circuit_isolability.hpp
/// Which faults of a circuit its sensors can detect and tell apart, and which added
/// sensor would tell more apart (`hstmon-fdi isolability|sensors --circuit`), from the
/// circuit's fault table (circuit_faults.hpp: steady-state signatures at the nominal
/// inputs).
///
/// Two hypotheses are not isolable when no observation can contradict one without the
/// other: their magnitude symbols are never opposite (+ against −, or a structural 0 —
/// the fault cannot move that channel at all — against a ±; a merely small 0 is what a
/// smaller fault of the other kind shows) and their directions are parallel (cosine ≥ 1 − 1e-6: the same steady
/// residual up to its size, e.g. a pump's displacement and its stroke, which enter only as
/// their product). A sensor row and a fault that moves its channel alone are not isolable
/// either. Hypotheses whose directions differ by less than ≈ 11° (cosine ≥ 0.98) are
/// isolable in principle but weakly: sensor noise and model error reorder them. Classes
/// are the connected sets of the not-isolable relation. Faults that move no channel by
/// one σ are undetectable at the nominal point.
///
/// Sensor placement: every pressure node, free shaft and element flow not yet measured is
/// tried as one added channel (its σ that of the circuit's sensors of the same quantity,
/// else 1 % of the envelope); candidates are ranked by how many of today's classes they
/// split, then by how many undetectable faults they make detectable, then by how many
/// weak pairs they make clear.

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_faults.hpp"

namespace hstmon::circuit_tools {

/// Detectability and isolability of one sensor set.
struct Isolability {
  std::vector<std::string> faults;               ///< table rows, in order
  std::vector<std::vector<int>> isolable;        ///< [i][j]: 1 isolable, 0 not, 2 weakly (matrix over faults)
  std::vector<std::vector<std::string>> classes; ///< not-isolable classes of two or more
  std::vector<std::pair<std::string, std::string>> weak;  ///< weakly isolable pairs (outside a common class)
  std::vector<std::string> undetectable;         ///< no channel moves by 1 σ at 30 %
};

/// Isolability of c's table.
Isolability circuit_isolability(const CircuitFaultTable& t);

/// One candidate sensor's effect.
struct SensorCandidate {
  std::string name;                     ///< "p(Pmi)", "w(motor)", "q(dcv)"
  int classes_split = 0;                ///< of today's classes, how many it splits
  int made_detectable = 0;              ///< of today's undetectable faults, how many it makes detectable
  int weak_cleared = 0;                 ///< of today's weak pairs, how many it makes clear
  std::vector<std::vector<std::string>> classes;  ///< the classes with it
};

/// Every candidate sensor of c, best first (see the file comment).
/// @throws std::runtime_error as circuit_fault_table
std::vector<SensorCandidate> rank_added_sensors(const LoadedCircuit& c);

}  // namespace hstmon::circuit_tools
