#pragma once
// `hstmon identify --circuit FILE --fit P1,P2 LOG...`: named parameters of any circuit
// fitted to its logs' steady operating points (hstmon_ident circuit_fit.hpp), with the
// paper rig's table analysis and studies as further sections of the same output.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_circuit_args.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::cli {

/// What identify adds to a circuit's output besides the fit: the paper rig's table
/// analysis and parameter studies (cli_identify.cpp), computed once the circuit is loaded.
struct IdentifySections {
  std::string text;                                ///< after the fit's text
  nlohmann::json json = nlohmann::json::object();  ///< keys added to the JSON object ("paper", "studies")
  std::vector<sim::ReportTable> tables;            ///< after the fit's tables in the report
  std::vector<sim::ReportPanel> panels;            ///< after the fit's panels, in the report's figure
  std::string verdict;                             ///< a clause of the report's verdict
};

/// Fills `out` for circuit c; `panels`: the report wants plots. kExitOk, or the exit code
/// after the message.
using IdentifySectionsFn =
    std::function<int(const circuit_tools::LoadedCircuit& c, bool panels, IdentifySections& out)>;

/// The options of identify that apply with --circuit.
/// params: the starting values.
struct CircuitIdentifyArgs : CircuitCommonArgs {
  std::vector<std::string> logs;   ///< none: only the sections
  std::vector<std::string> fit;    ///< parameter names (needed with logs)
  std::string out;                 ///< parameter file to write ("" = none)
  double min_duration = 0.2;       ///< [s]
  std::size_t min_samples = 1;     ///< fewest rows in an operating point
  bool assume_steady = false;      ///< every held stretch is steady from its first row (DAS logs)
  std::size_t min_settings = 0;    ///< fewest distinct operating points accepted (0: what the fit needs)
  double noise_pressure = 0.0;     ///< σ of every pressure sensor for the weights [Pa]; 0 = the circuit file's
  double noise_speed = 0.0;        ///< σ of every speed sensor [rad/s]; 0 = the circuit file's
  std::string header;              ///< generated C++ header of the circuit at the fitted values ("" = none)
  /// Each operating point gets its own value of the window inputs, fitted with `fit`
  /// (CircuitFitOptions::setting_per_window).
  bool setting_per_window = false;
  std::vector<std::string> window_inputs;  ///< those inputs by name; empty: the inputs the logs lack
  IdentifySectionsFn sections;             ///< empty: none
};

/// Runs it and prints the result; errors as file:line:column on stderr.
/// @return kExitOk, kExitUsage, or kExitBadInput
int run_circuit_identify(const CircuitIdentifyArgs& a);

}  // namespace hstmon::cli
