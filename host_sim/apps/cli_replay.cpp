// `hstmon replay LOG [--params FILE] [--json] ...`: replays a log through the observer
// and prints per-channel residual statistics (human table, or JSON lines).
#include <fmt/format.h>
#include <fmt/os.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "cli_circuit_replay.hpp"
#include "cli_commands.hpp"
#include "cli_events.hpp"
#include "cli_fleet_replay.hpp"
#include "cli_log_options.hpp"
#include "cli_log_replay.hpp"
#include "cli_replay_report.hpp"
#include "cli_validators.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_writer.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_host/params_file.hpp"
#include "hstmon_host/replay.hpp"

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
  std::string thesis_model = "specialised";  // --thesis-model: specialised | engine
  bool no_progress = false;
  bool no_diagnosis = false;
  bool matcher_only = false;  // --matcher-only (circuit replay): no fit of the steady windows
  std::string circuit;  // --circuit: run_circuit_replay instead (cli_circuit_replay.hpp)
  bool summary = false;       // --summary: one JSON line per log (cli_fleet_replay.hpp)
  unsigned jobs = 0;          // --jobs
  std::string machine_from = "parent";
};

struct Display {
  const char* label;  // human label
  const char* name;   // canonical channel name
  const char* unit;   // display unit
  double scale;       // SI → display
};
const Display kDisplay[4] = {{"Pmi", "p_mi", "bar", 1e-5},
                             {"Pmo", "p_mo", "bar", 1e-5},
                             {"Ppp", "p_pp", "bar", 1e-5},
                             {"ωm", "w_m", "rpm", 60.0 / (2.0 * M_PI)}};

// A progress line on stderr, only when stderr is a terminal and the log is long.
struct Progress {
  bool on = false;
  void operator()(double f) const {
    if (on) std::fprintf(stderr, "\rreplaying… %3.0f %%", 100.0 * f);
  }
  void done() const {
    if (on) std::fprintf(stderr, "\r%24s\r", "");
  }
};

void print_json(const ReplayArgs& a, const host::ReplayResult& r) {
  fmt::print("{}\n", replay_head_json(a.log, r).dump());
  for (int c = 0; c < 4; ++c) {
    const auto& s = r.channels[static_cast<std::size_t>(c)];
    nlohmann::json j = {{"type", "residual"}, {"channel", kDisplay[c].name}, {"unit", c == 3 ? "rad/s" : "Pa"},
                        {"measured", r.measured[static_cast<std::size_t>(c)]}, {"n", s.n}};
    add_residual_stats(j, s);
    fmt::print("{}\n", j.dump());
  }
  print_json_diagnosis(r.envelope, r.events, r.final_status);
}

const char* start_words(InitialState k) {
  switch (k) {
    case InitialState::kMeasured: return "from the measured state";
    case InitialState::kSteady: return "at steady state";
    case InitialState::kRest: return "at rest";
  }
  return "?";
}


void print_human(const ReplayArgs& a, const host::ReplayResult& r) {
  fmt::print("hstmon replay {}\n", a.log);
  fmt::print("  {} rows, t = {:.6g} … {:.6g} s; observer tick {:.3g} ms, {} ticks, started {}\n", r.rows, r.t_first,
             r.t_last, r.tick * 1e3, r.ticks, start_words(r.start));
  fmt::print("  start-up hold-off {} (the model's transient from its initial state)\n",
             host::duration_text(r.startup_hold));
  for (const auto& n : r.notes) fmt::print("  note: {}\n", n);
  fmt::print("\n  residual = measured − model; noise = scatter estimated from successive samples\n");
  fmt::print("  {:<12} {:>11} {:>11} {:>11} {:>11} {:>10}\n", "channel", "mean", "RMS", "noise", "peak", "at t [s]");
  for (int c = 0; c < 4; ++c) {
    const auto& s = r.channels[static_cast<std::size_t>(c)];
    const std::string label = fmt::format("{} [{}]", kDisplay[c].label, kDisplay[c].unit);
    if (!r.measured[static_cast<std::size_t>(c)]) {
      fmt::print("  {:<12} {:>11}\n", label, "not in log");
      continue;
    }
    const double k = kDisplay[c].scale;
    fmt::print("  {:<12} {:>11.4g} {:>11.4g} {:>11.4g} {:>11.4g} {:>10.6g}\n", label, s.mean() * k, s.rms() * k,
               s.noise() * k, s.max_signed * k, s.t_max);
  }
  std::string beyond;
  for (int c = 0; c < 4; ++c) {
    const auto& s = r.channels[static_cast<std::size_t>(c)];
    // A mean beyond 5 noise levels is no sensor scatter: the model and the machine disagree.
    if (s.n > 1 && std::fabs(s.mean()) > 5.0 * s.noise() + 1e-12) {
      beyond += fmt::format("{}{}{}", beyond.empty() ? "" : ", ", kDisplay[c].label, s.mean() > 0 ? "+" : "−");
    }
  }
  if (beyond.empty()) {
    fmt::print("\n  residual means are within the sensor noise on every measured channel\n");
  } else {
    fmt::print("\n  residual means beyond 5× noise: {} (measured above (+) or below (−) the model)\n", beyond);
  }
  if (!a.no_diagnosis) fmt::print("\n  envelope: {}\n", r.envelope.text);
  print_events(r.events, r.final_status);
  print_observer_health(r.health, r.unhealthy_rows, r.max_substeps);
}

// Worth a progress line: more than about 200 000 rows (16 MB of text).
bool log_is_long(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  return !ec && bytes > (std::uintmax_t{16} << 20);
}

// Residual CSV in display units (bar, rpm) through the host port's writer; rows where a
// channel is absent carry "nan" there.
std::string write_residual_csv(const std::string& path, const host::ReplayResult& r) {
  std::vector<host::CsvColumn> cols = {host::column_for(host::Signal::kT, "s")};
  for (int c = 0; c < 4; ++c) {
    const auto q = c == 3 ? host::Quantity::kSpeed : host::Quantity::kPressure;
    const std::string n = kDisplay[c].name;
    cols.push_back({n, q, kDisplay[c].unit});
    cols.push_back({n + "_hat", q, kDisplay[c].unit});
    cols.push_back({"r_" + n, q, kDisplay[c].unit});
  }
  cols.push_back({"health", host::Quantity::kNone, ""});
  host::CsvWriter w;
  if (auto err = w.open(path, cols)) return err->to_string();
  std::vector<double> row(cols.size());
  for (const auto& tr : r.trace) {
    row[0] = tr.t;
    for (std::size_t c = 0; c < 4; ++c) {
      row[1 + 3 * c] = tr.y[c];
      row[2 + 3 * c] = tr.y_hat[c];
      row[3 + 3 * c] = tr.r[c];
    }
    row[13] = static_cast<double>(tr.health);
    if (!w.write_row(row)) break;
  }
  const auto err = w.close();
  return err ? err->to_string() : std::string();
}

int run_replay(const ReplayArgs& a) {
  const std::optional<host::ReadOptions> ro = to_read_options(a.io, "replay");
  if (!ro) return kExitUsage;

  host::ParamsFileResult pf;
  if (!read_params_option(a.io.params, pf)) return kExitBadInput;
  const ThesisParams<double> params = pf.params.value_or(ThesisParams<double>{});
  const ThesisInputs<double> inputs = pf.inputs.value_or(ThesisInputs<double>{});

  host::ReplayOptions opt;
  opt.tick = a.tick;
  opt.init = a.init == "rest" ? host::InitMode::kRest : a.init == "steady" ? host::InitMode::kSteady : host::InitMode::kAuto;
  opt.keep_trace = !a.residuals_csv.empty() || !a.plot.empty() || !a.report.empty();
  opt.diagnose = !a.no_diagnosis;
  opt.thesis = a.thesis_model == "engine" ? ThesisImpl::kEngine : ThesisImpl::kSpecialised;
  if (pf.sensors) opt.sensors = *pf.sensors;
  // The log is streamed (cli_log_replay.hpp): read and replayed chunk by chunk.
  Progress progress;
  progress.on = !a.no_progress && ::isatty(STDERR_FILENO) && log_is_long(a.log);
  std::function<void(double)> on_chunk;
  if (progress.on) on_chunk = [&progress](double f) { progress(f); };
  const LogReplay lr = replay_log_file(a.log, *ro, params, inputs, opt, on_chunk);
  progress.done();
  print_log_messages(a.log, lr.notes, lr.error);
  const host::ReplayResult& r = lr.result;
  if (lr.error) {
    if (!a.io.lenient || r.rows == 0) return kExitBadInput;
    fmt::print(stderr, "{}: note: --lenient: replaying the {} valid rows before the error\n", a.log, r.rows);
  }
  // A log of another machine: nothing compared is not "within noise".
  if (r.rows > 0 && std::none_of(r.measured.begin(), r.measured.end(), [](bool m) { return m; })) {
    fmt::print(stderr,
               "{}: error: none of the thesis rig's channels (p_mi, p_mo, p_pp, w_m) is in the log, so nothing can "
               "be compared and nothing is diagnosed; name its columns with --map (e.g. --map p_mi=P1), or replay it "
               "through its own machine's circuit file with --circuit FILE (docs/circuits.md)\n",
               a.log);
    return kExitBadInput;
  }

  if (a.json) {
    print_json(a, r);
  } else {
    print_human(a, r);
  }
  int rc = lr.error ? kExitBadInput : kExitOk;
  if (!a.residuals_csv.empty()) {
    const std::string err = write_residual_csv(a.residuals_csv, r);
    if (!err.empty()) {
      fmt::print(stderr, "{}\n", err);
      rc = kExitBadInput;
    } else if (!a.json) {
      fmt::print("  residuals written to {}\n", a.residuals_csv);
    }
  }
  ReplayReport report = thesis_replay_report(a.log, r, !a.no_diagnosis);
  if (lr.error) report.read_error = lr.error->to_string();
  if (!write_plot_and_report(a.plot, a.report, report, a.json)) rc = kExitBadInput;
  return rc;
}

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
  if (!a.circuit.empty()) {
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
    // The table `replay --circuit` runs on, built once for all the logs; a circuit it
    // cannot be built for is replayed log by log, each saying why (residuals only).
    f.circuit_replay.fault_table = fdi::circuit_signature_table;
    if (f.circuit_replay.diagnose) {
      try {
        f.circuit_table = std::make_shared<const circuit_tools::CircuitFaultTable>(fdi::circuit_signature_table(*c));
      } catch (const std::exception&) {
        f.circuit_table.reset();
      }
    }
    f.circuit = std::move(c);
  } else {
    host::ParamsFileResult pf;
    if (!read_params_option(a.io.params, pf)) return kExitBadInput;
    f.params = pf.params.value_or(ThesisParams<double>{});
    f.inputs = pf.inputs.value_or(ThesisInputs<double>{});
    f.replay.tick = a.tick;
    f.replay.init = init;
    f.replay.diagnose = !a.no_diagnosis;
    f.replay.thesis = a.thesis_model == "engine" ? ThesisImpl::kEngine : ThesisImpl::kSpecialised;
    if (pf.sensors) f.replay.sensors = *pf.sensors;
  }
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
                  "CSV log (t[s] plus any of p_sup, p_s, p_bp, kp, p_mi, p_mo, p_pp, w_m); several logs or a folder: "
                  "one JSON summary line per log (docs/fleet.md)")
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
  add_log_options(*cmd, args->io, "JSON parameter file (default: thesis Table 2.2)");
  cmd->add_option("--thesis-model", args->thesis_model,
                  "The thesis rig's equations: specialised (hand-written, the default: about 2.3x faster) or engine "
                  "(thesis.json compiled); the same results to 1e-9 (docs/circuits.md)")
      ->check(CLI::IsMember({"specialised", "engine"}));
  cmd->add_flag("--no-progress", args->no_progress, "Never show the progress line");
  cmd->add_flag("--no-diagnosis", args->no_diagnosis, "Residuals only: do not run the fault matcher");
  cmd->add_flag("--matcher-only", args->matcher_only,
                "With --circuit: report the fault matcher's verdict alone, as the firmware monitor does: no step "
                "detection at held inputs, no fit of the steady windows after a detection (docs/circuits.md)");
  cmd->add_option("--circuit", args->circuit,
                  "Replay through the monitor of this circuit file (docs/circuits.md): residuals and the fault matcher "
                  "on the circuit's generated table; --params is then its parameter file (default: <stem>.params.json "
                  "beside it)");
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
    if (args->circuit.empty()) {
      exit_code = run_replay(*args);
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
