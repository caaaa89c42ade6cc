#pragma once
// `hstmon identify --circuit FILE --fit P1,P2 LOG...`: named parameters of any circuit
// fitted to its logs' steady operating points (hstmon_ident circuit_fit.hpp).
#include <string>
#include <vector>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// The options of identify that apply with --circuit.
struct CircuitIdentifyArgs {
  std::vector<std::string> logs;
  std::string circuit;
  std::string params;              ///< starting values ("" = <stem>.params.json beside it)
  std::vector<std::string> fit;    ///< parameter names
  std::string out;                 ///< parameter file to write ("" = none)
  std::string report;              ///< report folder ("" = none): report.md, report.html, figure.svg
  bool json = false;
  double min_duration = 0.2;       ///< [s]
  host::ReadOptions read;          ///< --map, --separator, --lenient, --rate (cli_log_options.hpp)
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk, kExitUsage, or kExitBadInput
int run_circuit_identify(const CircuitIdentifyArgs& a);

}  // namespace hstmon::cli
