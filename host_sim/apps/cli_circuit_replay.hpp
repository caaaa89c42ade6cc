#pragma once
// `hstmon replay --circuit FILE [--params FILE] LOG`: a log of any circuit file through
// the circuit's monitor (circuit_replay.hpp): residuals and the fault matcher.
#include <memory>
#include <string>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// The options of replay that apply with --circuit.
struct CircuitReplayArgs {
  std::string log;
  std::string circuit;
  std::string params;        ///< circuit parameter file ("" = <stem>.params.json beside it, else the file's values)
  bool json = false;
  double tick = 0.0;         ///< [s]; 0 = the log's median period, at most 10 ms
  std::string init = "auto"; ///< auto | rest | steady
  bool diagnose = true;      ///< false: residuals only (--no-diagnosis)
  bool fit = true;           ///< false: the matcher's verdict alone, as on firmware (--matcher-only)
  bool interpret = false;    ///< true: the interpreter even on a circuit compiled in (--interpret)
  std::string residuals_csv; ///< --residuals: measured, model and residual per row ("" = none)
  std::string plot;          ///< --plot: figure of measured, model and residual (.svg/.png; "" = none)
  std::string report;        ///< --report: report.md and report.html in this directory ("" = none)
  host::ReadOptions read;    ///< --map, --separator, --lenient, --rate (cli_log_options.hpp)
};

/// The monitor's options for these arguments: tick, start, diagnosis, fit, trace, and the
/// committed headers' table builder (fdi::circuit_signature_table) for a circuit without a
/// table built beforehand.
circuit_tools::CircuitReplayOptions circuit_replay_options(const CircuitReplayArgs& a);

/// The fault table the matcher runs on and the verdict sentence reads, built once for c;
/// null where none can be built (no steady state at the nominal inputs: each replay then
/// tries its builder and says why not).
std::shared_ptr<const circuit_tools::CircuitFaultTable> replay_fault_table(const circuit_tools::LoadedCircuit& c);

/// Runs it and prints the result (human, or JSON lines); errors as file:line:column on
/// stderr. @return kExitOk, or kExitBadInput for an unusable circuit, parameter file or log
int run_circuit_replay(const CircuitReplayArgs& a);

}  // namespace hstmon::cli
