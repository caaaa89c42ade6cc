#pragma once
/// @file circuit_equations.hpp
/// Analytical redundancy relations of any circuit (`gap --circuit`'s "where, by balance
/// equation"; equations.hpp is the thesis rig's hand-written set): the engine's balance
/// equations (CircuitModel::unknowns_net) evaluated on the measured signals alone — the
/// flow balance at every volume node and the torque balance on every free shaft. An effect
/// the model lacks unbalances the equation it enters and leaves the others at noise.
///
/// Imbalance, positive for a loss the model lacks (the thesis equations' convention):
///   flow:<node>     Σ model flows into the node at the measured signals − C·dp/dt   [m³/s]
///   torque:<shaft>  Σ model torques on the shaft at the measured signals − J·dω/dt  [N·m]
/// with C = 1/K the node's capacitance [m³/Pa] and J the shaft's inertia [kg·m²]. (The
/// per-channel residual of the circuit gap is measured − model, the other way round: a
/// leak shows there as a pressure below the model, here as a positive imbalance.)
///
/// An equation is available when every full-vector entry it reads — its own node or shaft
/// and every node or shaft reached through an element touching it — is measured by a
/// pressure or speed channel present in the log, or is fixed (a boundary's pressure, a
/// driven shaft's speed: from the log's inputs row by row, else the values').
///
/// Signals are smoothed as the thesis rig's equations are (local_fit.hpp): a local linear
/// fit over ±5 ms (2 … 25 samples each side) gives each measured entry's value and slope;
/// a window never straddles an input change, leaves out row 0, and is dropped where a
/// measured signal bends within it. The channels' noise σ is propagated to each row's
/// imbalance to first order: σ² = Σ_j (∂g/∂z_j · σ_j/√N)² + (C · σ/√Σ(t − t̄)²)².
#include <cstddef>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_gap/equations.hpp"

namespace hstmon::gap {

/// One balance equation of a circuit.
struct CircuitEquation {
  std::string name;        ///< "flow:<node>" or "torque:<shaft>"
  std::string unit;        ///< "m^3/s" or "N*m"
  int z = 0;               ///< full-vector entry: node index, or HostCircuitModel::kNodes + shaft index
  int unknown = 0;         ///< its row in CircuitModel::unknowns_net (volume nodes, then free shafts)
  bool shaft = false;      ///< a torque balance
  std::vector<int> reads;  ///< full-vector entries the equation reads, itself first
};

/// The balance equations of c, volume nodes in node order, then free shafts.
std::vector<CircuitEquation> circuit_equations(const circuit_tools::LoadedCircuit& c);

/// One log's balance equations evaluated at the rows where the smoothing holds.
struct CircuitArrData {
  std::vector<CircuitEquation> equations;
  std::vector<bool> available;  ///< per equation
  std::vector<std::string>
      missing;  ///< per equation: what it lacks ("p_mi (not in the log)", "pressure of Pmo (no sensor)"), "" when available
  std::vector<std::size_t> rows;      ///< log rows (window centres)
  std::vector<double> t_since_start;  ///< per row [s]
  /// Per row, the full vector: measured entries smoothed, fixed ones from the row's inputs,
  /// others 0 (read by no available equation) [Pa, rad/s]; and the measured entries' slopes (0 elsewhere) [Pa/s, rad/s²].
  std::vector<std::vector<double>> z, zdot;
  std::vector<std::vector<double>> r;      ///< per equation, per row: imbalance [SI] (0 where unavailable)
  std::vector<std::vector<double>> sigma;  ///< per equation, per row: its propagated noise [SI]
  int half_window = 0;                     ///< smoothing half-width [samples]
};

/// Evaluates c's balance equations on log.
/// @param noise  σ per sensor channel [SI] (circuit_point_set's, at least the sensor's stated σ)
CircuitArrData evaluate_circuit_arrs(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log,
                                     const std::vector<double>& noise);

/// Per-equation statistics (mean, RMS, noise, RMS/noise; no load split), in equation
/// order; located_equation() (equations.hpp) picks the located one from them.
std::vector<EquationStats> circuit_equation_stats(const CircuitArrData& a);

}  // namespace hstmon::gap
