#pragma once
// `hstmon gap --circuit FILE --fit LOG --check LOG`: the gap tool on any circuit file
// (hstmon_gap circuit_gap.hpp): candidates derived from the circuit, fitted on one log,
// judged on the withheld one.
#include <string>
#include <vector>

#include "cli_circuit_args.hpp"

namespace hstmon::cli {

/// The options of gap that apply with --circuit.
struct CircuitGapArgs : CircuitCommonArgs {
  std::string fit, check;
  std::vector<std::string> effects;  ///< --effects: candidate names or kinds ("" = all; circuit_gap.hpp)
  bool refit_nominal = false;        ///< --refit-nominal (CircuitGapOptions::refit_nominal)
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk or kExitBadInput
int run_circuit_gap(const CircuitGapArgs& a);

}  // namespace hstmon::cli
