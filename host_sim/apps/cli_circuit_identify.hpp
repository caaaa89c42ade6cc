#pragma once
// `hstmon identify --circuit FILE --fit P1,P2 LOG...`: named parameters of any circuit
// fitted to its logs' steady operating points (hstmon_ident circuit_fit.hpp).
#include <string>
#include <vector>

#include "cli_circuit_args.hpp"

namespace hstmon::cli {

/// The options of identify that apply with --circuit.
/// params: the starting values.
struct CircuitIdentifyArgs : CircuitCommonArgs {
  std::vector<std::string> logs;
  std::vector<std::string> fit;    ///< parameter names
  std::string out;                 ///< parameter file to write ("" = none)
  double min_duration = 0.2;       ///< [s]
  std::size_t min_samples = 1;     ///< fewest rows in an operating point
  bool assume_steady = false;      ///< every held stretch is steady from its first row (DAS logs)
  std::size_t min_settings = 0;    ///< fewest distinct operating points accepted (0: what the fit needs)
  double noise_pressure = 0.0;     ///< σ of every pressure sensor for the weights [Pa]; 0 = the circuit file's
  double noise_speed = 0.0;        ///< σ of every speed sensor [rad/s]; 0 = the circuit file's
  std::string header;              ///< generated C++ header of the circuit at the fitted values ("" = none)
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk, kExitUsage, or kExitBadInput
int run_circuit_identify(const CircuitIdentifyArgs& a);

}  // namespace hstmon::cli
