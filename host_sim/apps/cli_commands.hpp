#pragma once
// Sub-commands of the `hstmon` CLI. Each registers itself on the CLI11 app and returns
// the callback's exit code through `exit_code`.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <initializer_list>
#include <string>

#include "hstmon_host/params_file.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::cli {

/// Exit codes of the hstmon CLI.
enum ExitCode : int {
  kExitOk = 0,         ///< done
  kExitUsage = 1,      ///< bad command line
  kExitBadInput = 2,   ///< a log or parameter file could not be used (message names file:line:column)
};

/// Reads a command's parameter file option into pf. An empty path reads nothing (pf stays
/// empty, the caller keeps its defaults). On an error prints it (file:line:column) and
/// returns false: the command then exits with kExitBadInput.
inline bool read_params_option(const std::string& path, host::ParamsFileResult& pf) {
  if (path.empty()) return true;
  pf = host::read_params_file(path);
  if (!pf.error) return true;
  fmt::print(stderr, "{}\n", pf.error->to_string());
  return false;
}

/// An option of the thesis rig's own analyses that has no meaning for a circuit, and why.
struct ThesisOnlyOption {
  const char* option;
  const char* why;  ///< the sentence after "does not go with --circuit: "
};

/// With --circuit: false (after "hstmon CMD: error: OPT does not go with --circuit: WHY")
/// when one of `options` was given on cmd; the command then exits kExitUsage.
inline bool refuse_with_circuit(const CLI::App& cmd, std::initializer_list<ThesisOnlyOption> options) {
  for (const ThesisOnlyOption& o : options) {
    if (cmd.count(o.option) > 0) {
      fmt::print(stderr, "hstmon {}: error: {} does not go with --circuit: {}\n", cmd.get_name(), o.option, o.why);
      return false;
    }
  }
  return true;
}

/// sim::write_circuit_report for `hstmon <command> --circuit … --report dir`, saying on
/// stderr why the figure is missing ("dir: note: no figure: …") or why the report could
/// not be written ("hstmon <command>: error: …").
/// @return false when the report could not be written
inline bool report_written(const char* command, const std::string& dir, const sim::CircuitReport& r) {
  std::string warning;
  const std::string err = sim::write_circuit_report(dir, r, warning);
  if (!warning.empty()) fmt::print(stderr, "{}: note: no figure: {}\n", dir, warning);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon {}: error: {}\n", command, err);
    return false;
  }
  return true;
}

/// `hstmon replay LOG ...`
void add_replay_command(CLI::App& app, int& exit_code);
void add_identify_command(CLI::App& app, int& exit_code);  ///< `hstmon identify LOG... --out FILE`
void add_gap_command(CLI::App& app, int& exit_code);  ///< `hstmon gap --fit LOG_A --check LOG_B`
void add_fleet_command(CLI::App& app, int& exit_code);  ///< `hstmon fleet SUMMARY.jsonl...` (drifting machines)

}  // namespace hstmon::cli
