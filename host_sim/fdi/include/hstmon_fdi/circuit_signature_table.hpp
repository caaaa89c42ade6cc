#pragma once
/// @file circuit_signature_table.hpp
/// The fault-signature table of any circuit with its transient part: the rows, magnitudes
/// and directions of circuit_tools::circuit_fault_table (numeric steady solves), and per
/// channel the slope and order of the circuit's temporal causal graph (circuit_tcg.hpp) —
/// forward propagation of the fault at the nominal operating point, the qualitative graph
/// first and, where opposite paths meet, the graph weighted by the operating-point gains
/// (as the thesis rig's hand-made table did). It is what `hstmon replay --circuit`
/// runs on and what `hstmon-fdi table` writes into the committed headers.
///
/// What the table promises must hold for the nonlinear engine, not only for the graph: the
/// prediction is compared with the engine's own first non-zero derivative at 0+ for a
/// ±10 % fault (circuit_crosscheck.hpp) at the nominal point and at the default cases
/// (first input × 0.8 and × 1.2).
///  - A slope is kept only where graph, engine and the steady-state magnitude agree (slope =
///    magnitude, or both 0); else kQualAny. The matcher reads the slope at a channel's alarm
///    onset: a channel the fault moves by less than 1 σ (or by a size-dependent sign)
///    alarms, if at all, later in a transient, with whatever sign it has there. A kept
///    slope must also survive a noiseless simulation of the fault (simulate_circuit, ±10 %
///    and ±30 % where the faulted circuit has a steady state, 3 slowest time constants): on
///    that channel no excursion against the slope may reach a threshold T ≥ 1 σ before one
///    with it does (the closed loop's p_c dips before it rises under n_e+).
///  - A row keeps the graph's orders only when the engine's orders equal them on every
///    channel at every point and the row's most visible channel (largest |direction|) is on
///    its fastest path (smallest order among the responding channels); otherwise all its
///    orders are 0, which the matcher's order test accepts whatever alarms first.
///  - A fault not on the graph (a valve shut at the operating point, a laminar transition)
///    keeps kQualAny and orders 0.
/// Each row's reasons are in CircuitFaultTable::remarks; docs/fdi.md §10 has the campaign
/// figures behind the rules. A circuit whose graph cannot be derived gets the steady-state
/// table with a note saying so.
///
/// The same table comes in the other shapes the circuit tools read (fault_table_builders.hpp):
/// some of its rows, each built alone (a row reads only its own fault's solves, engine
/// readings and runs), and the tables of sensor placement, whose fault transients are
/// simulated once for several added channels (the channels a circuit measures do not change
/// how it moves; each reading is the engine's output for its own channel).

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/added_sensors.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/fault_table_builders.hpp"

namespace hstmon::fdi {

/// Highest derivative order the table's graph propagation and engine check look at [-].
inline constexpr int kCircuitTableMaxOrder = 6;

/// Builds c's table at its nominal values (see the file comment).
/// @throws std::runtime_error as circuit_tools::circuit_fault_table (no steady state at the
///         nominal inputs)
circuit_tools::CircuitFaultTable circuit_signature_table(const circuit_tools::LoadedCircuit& c);

/// The rows of circuit_signature_table(c) for the named faults ("R_ip-", with their sign)
/// and every sensor row, bit for bit with their remarks, building only those (a
/// circuit_tools::FaultRowsBuilder): the named faults without a row are in `undetectable`; a
/// name that is no fault of c is left out.
/// @throws std::runtime_error as circuit_signature_table
circuit_tools::CircuitFaultTable circuit_signature_rows(const circuit_tools::LoadedCircuit& c,
                                                        const std::vector<std::string>& faults);

/// circuit_signature_table of c with each of `added` appended in turn (sensor placement, a
/// circuit_tools::AddedSensorTablesBuilder): element k is circuit_signature_table(
/// with_added_sensor(c, added[k])), bit for bit, or empty where that throws. The fault
/// transients that check the slopes, most of a table's cost, are simulated once for as many
/// added channels as c has room for (host::CircuitCap::kChannels). All empty when c has no
/// room for a channel.
std::vector<std::optional<circuit_tools::CircuitFaultTable>> circuit_signature_tables_with_each(
    const circuit_tools::LoadedCircuit& c, const std::vector<circuit_tools::AddedSensor>& added);

/// This table in the three shapes the circuit tools take (circuit_signature_table,
/// circuit_signature_rows, circuit_signature_tables_with_each).
circuit_tools::FaultTableBuilders signature_fault_tables();

}  // namespace hstmon::fdi
