// `hstmon replay LOG [--circuit FILE] [--params FILE] [--json] ...`: replays a log through
// the monitor of a circuit (the built-in thesis rig unless --circuit names another) and
// prints per-channel residual statistics and the diagnosis (cli_circuit_replay.hpp), or
// one summary line per log for several logs (cli_fleet_replay.hpp).
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "cli_circuit_replay.hpp"
#include "cli_commands.hpp"
#include "cli_fleet_replay.hpp"
#include "cli_log_options.hpp"
#include "cli_validators.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::cli {

namespace {

struct ReplayArgs {
  std::vector<std::string> logs;  // as given: files or folders (several: summary lines)
  LogOptionArgs io;               // --map, --separator, --lenient, --rate, --params
  CircuitReplayArgs run;          // the replay's own options (the log, read and params set last)
  bool no_progress = false;       // --no-progress: scripts pass it; the replay writes no progress line
  bool no_diagnosis = false;      // --no-diagnosis: run.diagnose = false
  bool matcher_only = false;      // --matcher-only: run.fit = false
  bool summary = false;           // --summary: one JSON line per log (cli_fleet_replay.hpp)
  unsigned jobs = 0;              // --jobs
  std::string machine_from = "parent";
};

// Several logs, a folder or --summary: one summary line per log (cli_fleet_replay.hpp).
bool wants_summaries(const ReplayArgs& a) {
  std::error_code ec;
  return a.summary || a.logs.size() > 1 || std::filesystem::is_directory(a.logs.front(), ec);
}

int run_summaries(const ReplayArgs& a) {
  const char* single_only[] = {"--residuals", "--plot", "--report"};
  const std::string given[] = {a.run.residuals_csv, a.run.plot, a.run.report};
  for (int i = 0; i < 3; ++i) {
    if (!given[i].empty()) {
      fmt::print(stderr, "hstmon replay: error: {} takes one log (not with several logs, a folder or --summary)\n",
                 single_only[i]);
      return kExitUsage;
    }
  }
  FleetReplayArgs f;
  f.read = a.run.read;
  std::string err;
  f.machine = parse_machine_rule(a.machine_from, err);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon replay: error: --machine-from {}\n", err);
    return kExitUsage;
  }
  // One circuit for every log: loaded once, its monitor built per log.
  auto c = std::make_shared<circuit_tools::LoadedCircuit>();
  if (auto load_error = circuit_tools::load_circuit(a.run.circuit, a.run.params, *c)) {
    fmt::print(stderr, "{}\n", load_error->to_string());
    return kExitBadInput;
  }
  f.circuit_replay = circuit_replay_options(a.run);
  if (a.run.diagnose) f.circuit_table = replay_fault_table(*c);
  f.circuit = std::move(c);
  f.jobs = a.jobs;
  const std::vector<std::string> logs = expand_logs(a.logs);
  if (logs.empty()) {
    fmt::print(stderr, "hstmon replay: error: no logs (*.csv, *.tsv, *.txt) in {}\n", a.logs.front());
    return kExitBadInput;
  }
  return run_fleet_replay(logs, f);
}

}  // namespace

void add_replay_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = app.add_subcommand("replay", "Replay a sensor log through the observer and report residuals");
  cmd->add_option("LOG", args->logs,
                  "CSV log (t[s] plus the circuit's input and sensor columns; the thesis rig's: p_sup, p_s, p_bp, kp, "
                  "p_mi, p_mo, p_pp, w_m); several logs or a folder: one JSON summary line per log (docs/fleet.md)")
      ->required();
  cmd->add_flag("--json", args->run.json, "One JSON object per line instead of the human summary");
  cmd->add_option("--residuals", args->run.residuals_csv, "Write measured, model and residual per row to this CSV");
  cmd->add_option("--plot", args->run.plot, "Write a plot (.svg or .png) of measured, model and residual");
  cmd->add_option(
      "--report", args->run.report,
      "Write report.md and report.html (one self-contained page: verdict, residuals, events, plot) to this directory");
  cmd->add_option("--tick", args->run.tick, "Observer tick [s] (default: the log's sample period, at most 0.01)")
      ->check(positive_number());
  cmd->add_option("--init", args->run.init, "Initial state: auto (from the first row's measurements), rest or steady")
      ->check(CLI::IsMember({"auto", "rest", "steady"}));
  add_log_options(*cmd, args->io,
                  "The circuit's parameter file (default: <stem>.params.json beside the circuit file; for the built-in "
                  "thesis rig its Table 2.2 values)");
  cmd->add_flag("--no-progress", args->no_progress,
                "No progress line on stderr (accepted for scripts: the replay writes none)");
  cmd->add_flag("--no-diagnosis", args->no_diagnosis, "Residuals only: do not run the fault matcher");
  cmd->add_flag("--matcher-only", args->matcher_only,
                "Report the fault matcher's verdict alone, as the firmware monitor does: no step "
                "detection at held inputs, no fit of the steady windows after a detection (docs/circuits.md)");
  cmd->add_flag("--interpret", args->run.interpret,
                "Run the circuit engine's interpreter even where the circuit is compiled into the program (the "
                "shipped circuits: the same numbers, slower; docs/circuits.md)");
  cmd->add_option(
      "--circuit", args->run.circuit,
      "The machine's circuit file (docs/circuits.md; default: the thesis rig, examples/circuits/thesis.json, "
      "built in): residuals and the fault matcher on the table generated from it");
  cmd->add_flag("--summary", args->summary,
                "One JSON summary line per log (implied by several logs or a folder; docs/fleet.md)");
  cmd->add_option("--jobs", args->jobs, "Logs replayed at once with --summary (default: all cores)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--machine-from", args->machine_from,
                  "Machine of a log in its summary line: parent (its folder; default), stem (file name without "
                  "extension) or regex:PATTERN (first capture group, on the path)");
  cmd->callback([args, &exit_code]() {
    const std::optional<host::ReadOptions> ro = to_read_options(args->io, "replay");
    if (!ro) {
      exit_code = kExitUsage;
      return;
    }
    CircuitReplayArgs& run = args->run;
    run.read = *ro;
    run.log = args->logs.front();
    run.params = args->io.params;
    run.diagnose = !args->no_diagnosis;
    run.fit = !args->matcher_only;
    exit_code = wants_summaries(*args) ? run_summaries(*args) : run_circuit_replay(run);
  });
}

}  // namespace hstmon::cli
