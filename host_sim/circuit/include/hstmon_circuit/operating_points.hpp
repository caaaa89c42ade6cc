#pragma once
/// @file operating_points.hpp
/// Isolability across operating points (`hstmon-fdi isolability --circuit`): what a change
/// of operating point can split that the nominal point cannot.
///
/// The points span the circuit's input envelope around its nominal inputs (the parameter
/// file's): the nominal point, then each input with a non-zero nominal value at 50 % and
/// 150 % of it, one input at a time (a fraction's 150 % held within ±1), every fraction
/// reversed (a displacement command of the other sign: the machine's other direction), and,
/// when the circuit has both, every fraction and every torque input reversed together (the
/// drive the other way with a load that opposes the motion: the other line carries the
/// load). A point without a steady state is left out.
///
/// A pair of table rows that is not isolable at the nominal point (circuit_isolability.hpp:
/// entry 0 or 2) is split by a change of operating point when, at some other point where
/// both have a row (or one is undetectable),
///  - the pair is isolable there (entry 1), or
///  - one of them shows there and the other is undetectable there (a case drain from a
///    line that the drive the other way holds at charge pressure), or
///  - both are parameter rows and their responses scale differently between the nominal
///    point and there: the ratio of their noise-scaled direction lengths changes by more than
///    a factor 1.25 (a fault of one fixed size explains the two points as one row but not as
///    the other: a leak grows with the pressure across it, a delivery loss with the
///    displacement × speed).

#include <string>
#include <utility>
#include <vector>

#include "hstmon_circuit/circuit_isolability.hpp"

namespace hstmon::circuit_tools {

/// One operating point: the circuit's inputs there.
struct OperatingPoint {
  std::string name;                        ///< "nominal", "T_L 50 %", "eps 150 %", "eps reversed"
  host::HostCircuitModel::Inputs inputs{};  ///< SI, by input index
};

/// The points of c (see the file comment), nominal first; every one, with or without a
/// steady state.
std::vector<OperatingPoint> operating_points(const LoadedCircuit& c);

/// What a change of operating point splits (see the file comment).
struct OperatingPointSplit {
  std::vector<std::string> points;  ///< the points whose table was built (a steady state there), nominal first
  std::vector<std::pair<std::string, std::string>> pairs;  ///< rows not isolable at nominal, split elsewhere
  std::vector<std::string> where;   ///< per pair, the first point that splits it
  /// Classes of two or more left across the points: the nominal not-isolable relation
  /// (isolable entry 0, as Isolability::classes) without the pairs split elsewhere, joined
  /// transitively
  std::vector<std::vector<std::string>> classes;
};

/// Pairs of c's rows split by a change of operating point, each table made by `build` at
/// each point of operating_points(c) and read as `parts` says. With `only` non-empty, only
/// pairs of those rows are judged, and each point's table holds only their rows (and every
/// sensor row: build.rows) — the same pairs, points and classes, for a fraction of the
/// solves. `nominal`: c's table at the nominal point (build.table), when the caller has
/// already built it; it is then not built again.
/// @throws std::runtime_error as `build` for c itself (no steady state at the nominal inputs)
OperatingPointSplit split_by_operating_point(const LoadedCircuit& c,
                                             const FaultTableBuilders& build = steady_fault_tables(),
                                             SignatureParts parts = SignatureParts::kFull,
                                             const std::vector<std::string>& only = {},
                                             const CircuitFaultTable* nominal = nullptr);

}  // namespace hstmon::circuit_tools
