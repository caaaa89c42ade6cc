#pragma once
/// @file circuit_signature_table.hpp
/// The fault-signature table of any circuit with its transient part: the rows, magnitudes
/// and directions of circuit_tools::circuit_fault_table (numeric steady solves), and per
/// channel the slope and order of the circuit's temporal causal graph (circuit_tcg.hpp) —
/// forward propagation of the fault at the nominal operating point, the qualitative graph
/// first and, where opposite paths meet, the graph weighted by the operating-point gains
/// (as the thesis rig's table, signature_table.hpp). It is what `hstmon replay --circuit`
/// runs on and what `hstmon-fdi table` writes into the committed headers.
///
/// What the table promises must hold for the nonlinear engine, not only for the graph: the
/// prediction is compared with the engine's own first non-zero derivative at 0+ for a
/// ±10 % fault (circuit_crosscheck.hpp) at the nominal point and at the default cases
/// (first input × 0.8 and × 1.2). A slope is left kQualAny where
///  - the engine disagrees with the graph at one of these points,
///  - the fault is not on the graph (a valve shut at the operating point, a laminar
///    transition), or the graph finds no path up to max_order while the steady state moves,
///  - the slope is opposite to a definite steady-state magnitude (the sign at the alarm
///    onset then depends on the fault's size and the threshold).
/// Orders are kept for a row only when the engine's orders equal the graph's on every
/// responding channel at every point; otherwise the row's orders are all 0 (the matcher's
/// order test then accepts any first channel: order 0 everywhere says nothing).
/// Each row's reasons are in CircuitFaultTable::remarks.

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::fdi {

/// Highest derivative order the table's graph propagation and engine check look at [-].
inline constexpr int kCircuitTableMaxOrder = 6;

/// Builds c's table at its nominal values (see the file comment).
/// @throws std::runtime_error as circuit_tools::circuit_fault_table, or when the nominal
///         point has no steady state; std::invalid_argument when the bond graph's
///         causality fails (message names the element)
circuit_tools::CircuitFaultTable circuit_signature_table(const circuit_tools::LoadedCircuit& c);

}  // namespace hstmon::fdi
