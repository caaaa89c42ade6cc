#pragma once
/// @file fault_table_builders.hpp
/// How the circuit tools get a circuit's fault table. circuit_tools cannot call fdi (fdi
/// depends on it), so the table the monitor runs (fdi::circuit_signature_table: the steady
/// magnitudes and directions with the causal graph's slopes and orders) comes in as
/// builders; circuit_fault_table's steady-state table is the default. One table in three
/// shapes, so that a caller needing part of it pays for that part only:
///  - the whole table of a circuit;
///  - some of its rows (the final candidates' at another operating point: candidate_class.hpp);
///  - the table of the circuit with each channel sensor placement tries (added_sensors.hpp),
///    in one call, so that a builder can share across them what the added channel does not
///    change (fdi's simulates each fault's transient once for several added channels).
/// Every shape gives, row for row and bit for bit, what the whole-table builder gives for
/// that circuit.

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/added_sensors.hpp"
#include "hstmon_circuit/circuit_faults.hpp"

namespace hstmon::circuit_tools {

/// Builds a circuit's whole fault table: circuit_fault_table (steady-state only) or
/// fdi::circuit_signature_table (the monitor's, with slopes and orders).
/// @throws std::runtime_error when the circuit has no steady state at its nominal inputs
using FaultTableBuilder = CircuitFaultTable (*)(const LoadedCircuit&);

/// Builds the rows of the named faults ("R_ip-", with their sign) and every sensor row of a
/// circuit's table, each as the whole table has it; the named faults without a row are in
/// its `undetectable` as there; a name that is no fault of the circuit is left out.
/// @throws std::runtime_error as the whole-table builder
using FaultRowsBuilder = CircuitFaultTable (*)(const LoadedCircuit& c, const std::vector<std::string>& faults);

/// Builds, for each of `added`, the whole table of c with that channel appended
/// (with_added_sensor): element k for added[k], empty where that table cannot be built.
using AddedSensorTablesBuilder =
    std::vector<std::optional<CircuitFaultTable>> (*)(const LoadedCircuit& c, const std::vector<AddedSensor>& added);

/// circuit_fault_table of c with each of `added` appended (an AddedSensorTablesBuilder).
std::vector<std::optional<CircuitFaultTable>> circuit_fault_tables_with_each(const LoadedCircuit& c,
                                                                             const std::vector<AddedSensor>& added);

/// The three shapes of one table (see the file comment), all of the same table. A default
/// set is circuit_fault_table's (steady-state signs and directions; slopes `?`, orders 0),
/// so that no member is ever null.
struct FaultTableBuilders {
  FaultTableBuilder table = circuit_fault_table;                               ///< the whole table
  FaultRowsBuilder rows = circuit_fault_rows;                                  ///< some of its rows
  AddedSensorTablesBuilder with_each_sensor = circuit_fault_tables_with_each;  ///< the table with each added channel
};

/// circuit_fault_table's table in its three shapes (= FaultTableBuilders{}).
FaultTableBuilders steady_fault_tables();

}  // namespace hstmon::circuit_tools
