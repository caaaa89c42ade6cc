#pragma once
/// @file circuit_sim.hpp
/// Synthetic logs of any circuit (hstmon-sim --circuit): the engine's full equations
/// (no node taken quasi-steady) integrated by host_sim's Rosenbrock-4 (StiffIntegrator,
/// the reference of tests/circuit), inputs piecewise constant and met exactly at their
/// steps, every sample a hard stop; the outputs go through the sensor chain (white noise
/// and range clipping from the circuit's sensors section, no lag, no ADC). A sample that
/// falls on a step reads the volumes far faster than the sampling (those an observer at
/// this period takes quasi-steady) settled: no transducer follows their microseconds.

#include <cstdint>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"

namespace hstmon::circuit_tools {

/// What to simulate.
struct CircuitSimOptions {
  double duration = 10.0;          ///< run length [s] > 0
  double rate = 100.0;             ///< sample rate [Hz] > 0
  std::uint64_t seed = 1;          ///< noise seed
  bool from_rest = false;          ///< start at rest; false: at the steady state of the t = 0 inputs
  bool noise = true;               ///< false: sensor noise off (clipping kept)
  std::vector<InputStep> steps;    ///< input steps on top of the nominal inputs
};

/// Simulates c and returns the log: every input column and every sensor column, SI.
/// @throws std::runtime_error for more than 1e7 samples, when the circuit's values are not physical, there is no
///         steady state to start from, or the integration fails
CircuitLog simulate_circuit(const LoadedCircuit& c, const CircuitSimOptions& o);

}  // namespace hstmon::circuit_tools
