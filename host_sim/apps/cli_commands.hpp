#pragma once
// Sub-commands of the `hstmon` CLI. Each registers itself on the CLI11 app and returns
// the callback's exit code through `exit_code`.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "cli_circuit_args.hpp"
#include "cli_log_options.hpp"
#include "hstmon_host/params_file.hpp"
#include "hstmon_plot/circuit_report.hpp"

namespace hstmon::cli {

/// Exit codes of the hstmon CLI.
enum ExitCode : int {
  kExitOk = 0,         ///< done
  kExitUsage = 1,      ///< bad command line
  kExitBadInput = 2,   ///< a log or parameter file could not be used (message names file:line:column)
};

/// Registers subcommand `name` (help text `description`) on app. Its options fill the
/// returned Args, owned by its callback, which stores run(args, cmd)'s exit code in exit_code.
/// @return the subcommand, for its options, and the arguments they fill
template <class Args, class Run>
std::pair<CLI::App*, Args*> add_command(CLI::App& app, int& exit_code, const std::string& name,
                                        const std::string& description, Run run) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(name, description);
  cmd->callback([args, cmd, run, &exit_code]() { exit_code = run(*args, *cmd); });
  return {cmd, args.get()};
}

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

/// With --circuit: c from the command's arguments args (circuit, io, json, report), unless
/// one of `thesis_only` was given on cmd or the log options are bad (after the message).
/// @return false: the command then exits kExitUsage
template <class Args>
bool take_circuit_args(const CLI::App& cmd, std::initializer_list<ThesisOnlyOption> thesis_only, const Args& args,
                       CircuitCommonArgs& c) {
  if (!refuse_with_circuit(cmd, thesis_only)) return false;
  const std::optional<host::ReadOptions> ro = to_read_options(args.io, cmd.get_name().c_str());
  if (!ro) return false;
  c.read = *ro;
  c.circuit = args.circuit;
  c.params = args.io.params;
  c.json = args.json;
  c.report = args.report;
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

/// The end of `hstmon <command> --circuit …`: prints the result, print_json() with --json
/// or else text, then writes report() to a.report unless that is "" (report_written).
/// @return kExitOk, or kExitBadInput when the report could not be written
template <class PrintJson, class MakeReport>
int finish_circuit_command(const char* command, const CircuitCommonArgs& a, const std::string& text,
                           const PrintJson& print_json, const MakeReport& report) {
  if (a.json) {
    print_json();
  } else {
    fmt::print("{}", text);
  }
  if (!a.report.empty() && !report_written(command, a.report, report())) return kExitBadInput;
  return kExitOk;
}

/// `hstmon replay LOG ...`
void add_replay_command(CLI::App& app, int& exit_code);
void add_identify_command(CLI::App& app, int& exit_code);  ///< `hstmon identify LOG... --out FILE`
void add_gap_command(CLI::App& app, int& exit_code);  ///< `hstmon gap --fit LOG_A --check LOG_B`
void add_fleet_command(CLI::App& app, int& exit_code);  ///< `hstmon fleet SUMMARY.jsonl...` (drifting machines)

}  // namespace hstmon::cli
