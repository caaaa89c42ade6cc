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
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace hstmon::cli {

namespace {

struct ReplayArgs {
  std::string log;                // the one log (single-log output)
  std::vector<std::string> logs;  // as given: files or folders (several: summary lines)
  LogOptionArgs io;  // --map, --separator, --lenient, --rate, --params
  bool json = false;
  std::string residuals_csv;
  std::string plot;
  std::string report;  // --report DIR (cli_replay_report.hpp)
  double tick = 0.0;
  std::string init = "auto";
  bool no_progress = false;  // --no-progress: scripts pass it; the replay writes no progress line
  bool no_diagnosis = false;
  bool matcher_only = false;  // --matcher-only (circuit replay): no fit of the steady windows
  std::string circuit;        // --circuit ("" = the built-in thesis rig)
  bool summary = false;       // --summary: one JSON line per log (cli_fleet_replay.hpp)
  unsigned jobs = 0;          // --jobs
  std::string machine_from = "parent";
};

// Several logs, a folder or --summary: one summary line per log (cli_fleet_replay.hpp).
bool wants_summaries(const ReplayArgs& a) {
  std::error_code ec;
  return a.summary || a.logs.size() > 1 || std::filesystem::is_directory(a.logs.front(), ec);
}

int run_summaries(const ReplayArgs& a) {
  const char* single_only[] = {"--residuals", "--plot", "--report"};
  const std::string given[] = {a.residuals_csv, a.plot, a.report};
  for (int i = 0; i < 3; ++i) {
    if (!given[i].empty()) {
      fmt::print(stderr, "hstmon replay: error: {} takes one log (not with several logs, a folder or --summary)\n",
                 single_only[i]);
      return kExitUsage;
    }
  }
  FleetReplayArgs f;
  const std::optional<host::ReadOptions> ro = to_read_options(a.io, "replay");
  if (!ro) return kExitUsage;
  f.read = *ro;
  std::string err;
  f.machine = parse_machine_rule(a.machine_from, err);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon replay: error: --machine-from {}\n", err);
    return kExitUsage;
  }
  const host::InitMode init =
      a.init == "rest" ? host::InitMode::kRest : a.init == "steady" ? host::InitMode::kSteady : host::InitMode::kAuto;
  // One circuit for every log: loaded once, its monitor built per log.
  auto c = std::make_shared<circuit_tools::LoadedCircuit>();
  if (auto load_error = circuit_tools::load_circuit(a.circuit, a.io.params, *c)) {
    fmt::print(stderr, "{}\n", load_error->to_string());
    return kExitBadInput;
  }
  f.circuit_replay.tick = a.tick;
  f.circuit_replay.init = init;
  f.circuit_replay.diagnose = !a.no_diagnosis;
  f.circuit_replay.fit = !a.matcher_only;
  // The table every log runs on, built once; a circuit it cannot be built for is replayed
  // log by log, each saying why (residuals only).
  f.circuit_replay.fault_table = fdi::circuit_signature_table;
  if (f.circuit_replay.diagnose) {
    try {
      f.circuit_table = std::make_shared<const circuit_tools::CircuitFaultTable>(fdi::circuit_signature_table(*c));
    } catch (const std::exception&) {
      f.circuit_table.reset();
    }
  }
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
  cmd->add_flag("--json", args->json, "One JSON object per line instead of the human summary");
  cmd->add_option("--residuals", args->residuals_csv, "Write measured, model and residual per row to this CSV");
  cmd->add_option("--plot", args->plot, "Write a plot (.svg or .png) of measured, model and residual");
  cmd->add_option("--report", args->report,
                  "Write report.md and report.html (one self-contained page: verdict, residuals, events, plot) to this directory");
  cmd->add_option("--tick", args->tick, "Observer tick [s] (default: the log's sample period, at most 0.01)")
      ->check(positive_number());
  cmd->add_option("--init", args->init, "Initial state: auto (from the first row's measurements), rest or steady")
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
  cmd->add_option(
      "--circuit", args->circuit,
      "The machine's circuit file (docs/circuits.md; default: the thesis rig, examples/circuits/thesis.json, "
      "built in): residuals and the fault matcher on the table generated from it");
  cmd->add_flag("--summary", args->summary,
                "One JSON summary line per log (implied by several logs or a folder; docs/fleet.md)");
  cmd->add_option("--jobs", args->jobs, "Logs replayed at once with --summary (default: all cores)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--machine-from", args->machine_from,
                  "Machine of a log in its summary line: parent (its folder; default), stem (file name without "
                  "extension) or regex:PATTERN (first capture group, on the path)");
  cmd->callback([args, cmd, &exit_code]() {
    args->log = args->logs.front();
    if (wants_summaries(*args)) {
      exit_code = run_summaries(*args);
      return;
    }
    const std::optional<host::ReadOptions> ro = to_read_options(args->io, "replay");
    if (!ro) {
      exit_code = kExitUsage;
      return;
    }
    CircuitReplayArgs c;
    c.read = *ro;
    c.log = args->log;
    c.circuit = args->circuit;
    c.params = args->io.params;
    c.json = args->json;
    c.tick = args->tick;
    c.init = args->init;
    c.diagnose = !args->no_diagnosis;
    c.fit = !args->matcher_only;
    c.residuals_csv = args->residuals_csv;
    c.plot = args->plot;
    c.report = args->report;
    exit_code = run_circuit_replay(c);
  });
}

}  // namespace hstmon::cli
