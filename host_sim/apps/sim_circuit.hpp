#pragma once
/// @file sim_circuit.hpp
/// hstmon-sim --circuit FILE: a synthetic log of any circuit file (circuit_sim.hpp).

#include <cstdint>
#include <string>
#include <vector>

namespace hstmon::sim_app {

/// The command line of hstmon-sim --circuit.
struct CircuitSimArgs {
  std::string circuit;              ///< circuit file
  std::string params;               ///< parameter file ("" = <stem>.params.json beside it, else the file's values)
  double duration = 0.0;            ///< [s]; 0 = 10 s
  double rate = 0.0;                ///< [Hz]; 0 = 100 Hz
  std::uint64_t seed = 1;
  std::string out = "-";
  std::string start;                ///< "rest" | "steady" ("" = steady)
  bool no_noise = false;
  std::vector<std::string> steps;   ///< "INPUT=VALUE@T"
  std::vector<std::string> faults;  ///< "PARAM=FACTOR@T"
  std::string inputs;               ///< a log whose input columns drive the run ("" = none; circuit_schedule.hpp)
};

/// Runs it. @return 0, 1 on a bad option, 2 on a bad circuit/parameter file (message
/// file:line:column on stderr) or a failed simulation
int run_circuit_sim(const CircuitSimArgs& a);

}  // namespace hstmon::sim_app
