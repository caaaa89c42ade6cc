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
  std::size_t min_samples = 1;     ///< fewest rows in an operating point
  bool assume_steady = false;      ///< every held stretch is steady from its first row (DAS logs)
  std::size_t min_settings = 0;    ///< fewest distinct operating points accepted (0: what the fit needs)
  double noise_pressure = 0.0;     ///< σ of every pressure sensor for the weights [Pa]; 0 = the circuit file's
  double noise_speed = 0.0;        ///< σ of every speed sensor [rad/s]; 0 = the circuit file's
  std::string header;              ///< generated C++ header of the circuit at the fitted values ("" = none)
  host::ReadOptions read;          ///< --map, --separator, --lenient, --rate (cli_log_options.hpp)
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk, kExitUsage, or kExitBadInput
int run_circuit_identify(const CircuitIdentifyArgs& a);

}  // namespace hstmon::cli
