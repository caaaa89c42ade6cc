#pragma once
// Sub-commands of the `hstmon` CLI. Each registers itself on the CLI11 app and returns
// the callback's exit code through `exit_code`.
#include <CLI/CLI.hpp>

namespace hstmon::cli {

/// Exit codes of the hstmon CLI.
enum ExitCode : int {
  kExitOk = 0,         ///< done
  kExitUsage = 1,      ///< bad command line
  kExitBadInput = 2,   ///< a log or parameter file could not be used (message names file:line:column)
};

/// `hstmon replay LOG ...`
void add_replay_command(CLI::App& app, int& exit_code);
void add_identify_command(CLI::App& app, int& exit_code);  ///< `hstmon identify LOG... --out FILE`
void add_gap_command(CLI::App& app, int& exit_code);  ///< `hstmon gap --fit LOG_A --check LOG_B`

}  // namespace hstmon::cli
