#pragma once
// `hstmon gap --circuit FILE --fit LOG --check LOG`: the gap tool on any circuit file
// (hstmon_gap circuit_gap.hpp): candidates derived from the circuit, fitted on one log,
// judged on the withheld one.
#include <string>
#include <vector>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// The options of gap that apply with --circuit.
struct CircuitGapArgs {
  std::string circuit;
  std::string params;  ///< "" = <stem>.params.json beside it
  std::string fit, check;
  bool json = false;
  std::string report;      ///< report folder ("" = none): report.md, report.html, figure.svg
  std::vector<std::string> effects;  ///< --effects: candidate names or kinds ("" = all; circuit_gap.hpp)
  host::ReadOptions read;  ///< --map, --separator, --lenient, --rate (cli_log_options.hpp)
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk or kExitBadInput
int run_circuit_gap(const CircuitGapArgs& a);

}  // namespace hstmon::cli
