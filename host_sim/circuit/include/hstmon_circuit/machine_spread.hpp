#pragma once
/// @file machine_spread.hpp
/// A machine off its circuit file, as every built machine is: the parameters the monitor
/// treats as uncertain (circuit_faults.hpp moves_steady_state) each off by a uniform
/// relative error. The simulator runs it (hstmon-sim --circuit --param-error) and the
/// campaign draws one per run, while the monitor keeps the file's values.

#include <random>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// c with every uncertain parameter times 1 + U[−spread, spread], drawn from rng in
/// parameter order (the same rng state gives the same machine).
/// @param spread  relative error bound [-], ≥ 0
LoadedCircuit spread_machine(const LoadedCircuit& c, double spread, std::mt19937_64& rng);

}  // namespace hstmon::circuit_tools
