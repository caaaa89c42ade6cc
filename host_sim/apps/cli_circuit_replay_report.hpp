#pragma once
// The figure and the report of `hstmon replay --circuit … --plot/--report`: a circuit
// replay seen through the shared plot (hstmon_plot/residual_plot.hpp) and report writer
// (cli_replay_report.hpp), channels in the circuit's sensor order and each sensor's unit.
#include <string>

#include "cli_circuit_replay.hpp"
#include "cli_replay_report.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_replay.hpp"

namespace hstmon::cli {

/// The replay's trace for plot_replay(): one row of panels per sensor, in the sensor's
/// unit from the circuit file (SI where it gives none). Refers to c and r (keep them).
PlotTrace circuit_plot_trace(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitReplayResult& r);

/// "model bound at the last row's inputs (the parameter that leads it): p_s ±2.83 bar
/// (Pc 30 %), …" over the measured channels, in each sensor's unit; "" when there is none.
std::string bound_lead_sentence(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitReplayResult& r);

/// The replay's report for write_replay_report(). Refers to c and r (keep them).
ReplayReport circuit_replay_report(const CircuitReplayArgs& a, const circuit_tools::LoadedCircuit& c,
                                   const circuit_tools::CircuitReplayResult& r);

}  // namespace hstmon::cli
