#pragma once
/// @file sim_compare.hpp
/// hstmon-sim --inputs LOG --compare: how far a re-simulated run is from the measured one,
/// per sensor channel, row by row.

#include <string>

#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/circuit_file.hpp"

namespace hstmon::sim_app {

/// Per sensor channel of c, over the rows both logs hold at the same time: the mean, RMS
/// and largest magnitude of the residual measured − simulated, in the unit the circuit
/// file gives the channel (bar, rpm, …), and the time of the largest. A channel the
/// measured log lacks is said to be absent. One line per channel after a heading.
std::string compare_text(const host::CircuitFile& c, const circuit_tools::CircuitLog& measured,
                         const circuit_tools::CircuitLog& simulated);

}  // namespace hstmon::sim_app
