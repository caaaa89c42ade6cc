// `hstmon gap --fit LOG_A --check LOG_B [--params FILE] [--json] [--report DIR]`: where the
// thesis model and the machine disagree (per channel and per balance equation), whether
// the machine is the model's kind at all (envelope), which unmodelled effect of the
// library explains it (fitted on LOG_A, judged on the withheld LOG_B), how far the gap
// shrinks, and what term beyond the library would close it. docs/gap.md describes the
// method and the output.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_circuit_gap.hpp"
#include "cli_commands.hpp"
#include "cli_log_options.hpp"
#include "hstmon_gap/gap.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/params_file.hpp"

namespace hstmon::cli {

namespace {

struct GapArgs {
  std::string fit, check, report;
  LogOptionArgs io;  // --map, --separator, --lenient, --rate, --params (both logs)
  bool json = false;
  bool refit = false;
  std::vector<std::string> effects;
  double max_step = 2.5e-4;
  std::string thesis_model = "specialised";  // --thesis-model: specialised | engine
  std::string circuit;  // --circuit: run_circuit_gap instead (cli_circuit_gap.hpp)
};

int run_gap_command(const GapArgs& a) {
  const std::optional<host::ReadOptions> ro = to_read_options(a.io, "gap");
  if (!ro) return kExitUsage;
  host::ParamsFileResult pf;
  if (!read_params_option(a.io.params, pf)) return kExitBadInput;
  const ThesisParams<double> params = pf.params.value_or(ThesisParams<double>{});
  const ThesisInputs<double> inputs = pf.inputs.value_or(ThesisInputs<double>{});
  gap::GapOptions o;
  o.refit_nominal = a.refit;
  o.sim.max_step = a.max_step;
  o.sim.thesis = a.thesis_model == "engine" ? ThesisImpl::kEngine : ThesisImpl::kSpecialised;
  if (!a.effects.empty()) {
    o.effects.clear();
    for (const auto& n : a.effects) {
      const auto e = gap::effect_from_name(n);
      if (!e) {
        fmt::print(stderr, "hstmon gap: error: unknown effect '{}'\n", n);
        return kExitUsage;
      }
      o.effects.push_back(*e);
    }
  }
  host::LogData logs[2];
  const std::string* paths[2] = {&a.fit, &a.check};
  for (int i = 0; i < 2; ++i) {
    logs[i] = read_log_reporting(*paths[i], *ro);
    // A lenient read keeps the rows before a bad one; gap fits on whole logs only.
    if (logs[i].error) return kExitBadInput;
  }
  const gap::GapResult r = gap::run_gap(logs[0], logs[1], params, inputs, o);
  if (!r.ok) {
    fmt::print(stderr, "hstmon gap: error: {}\n", capped(r.error));
    return kExitBadInput;
  }
  if (a.json) {
    fmt::print("{}\n", gap::to_json(r));
  } else {
    fmt::print("hstmon gap --fit {} --check {}\n\n{}", a.fit, a.check, gap::to_text(r));
  }
  if (!a.report.empty()) {
    std::string plot_warning;
    const std::string err = gap::write_report(r, a.report, a.fit, a.check, &plot_warning);
    if (!err.empty()) {
      fmt::print(stderr, "hstmon gap: error: report: {}\n", err);
      return kExitBadInput;
    }
    if (!plot_warning.empty()) fmt::print(stderr, "hstmon gap: warning: report without plots: {}\n", plot_warning);
    if (!a.json) fmt::print("report: {0}/report.md, {0}/report.html\n", a.report);
  }
  return kExitOk;
}

/// `hstmon gap`: the thesis rig's, or with --circuit the circuit's (cli_circuit_gap.hpp).
int run_gap_or_circuit_gap(const GapArgs& a, const CLI::App& cmd) {
  if (a.circuit.empty()) return run_gap_command(a);
  CircuitGapArgs c{{}, a.fit, a.check, a.effects, a.refit};
  if (!take_circuit_args(
          cmd,
          {{"--max-step",
            "the circuit gap compares steady operating points and simulates nothing, so there is no step to set"}},
          a, c)) {
    return kExitUsage;
  }
  return run_circuit_gap(c);
}

}  // namespace

void add_gap_command(CLI::App& app, int& exit_code) {
  const auto [cmd, args] = add_command<GapArgs>(app, exit_code, "gap",
                                                "Where model and machine disagree (channels, balance equations), which "
                                                "unmodelled effect explains it, how far the gap shrinks",
                                                run_gap_or_circuit_gap);
  cmd->add_option("--fit", args->fit,
                  "log to fit the effects on (CSV as for replay: the thesis rig's with p_sup and kp; with --circuit, "
                  "the circuit's input and sensor columns)")
      ->required();
  cmd->add_option("--check", args->check, "withheld log to judge the fitted effects on")->required();
  add_log_options(
      *cmd, args->io,
      "nominal parameter file (default Table 2.2; with --circuit the circuit's, default <stem>.params.json)");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the human report");
  cmd->add_option(
      "--report", args->report,
      "directory for report.md, report.html (one self-contained page) and the plots (PNG; with --circuit figure.svg)");
  cmd->add_flag("--refit-nominal", args->refit,
                "re-fit kf and Rf + Rbl together with each effect; with --circuit every uncertain parameter, each "
                "move charged against its stated uncertainty");
  cmd->add_option("--effects", args->effects,
                  "restrict the library to these effects (names; with --circuit a candidate's name, e.g. leak(p_b), or "
                  "a kind: leak, friction, torque_loss, offset, parameter)")
      ->delimiter(',');
  cmd->add_option("--max-step", args->max_step,
                  "largest simulator step [s] (the thesis rig's tool; the circuit gap compares steady operating "
                  "points and simulates nothing)")
      ->capture_default_str();
  cmd->add_option("--thesis-model", args->thesis_model,
                  "the thesis rig's equations: specialised (hand-written, the default: about 7x faster) or engine "
                  "(thesis.json compiled); docs/gap.md")
      ->check(CLI::IsMember({"specialised", "engine"}));
  cmd->add_option("--circuit", args->circuit,
                  "the gap of this circuit file (docs/circuits.md): candidates derived from the circuit, judged on "
                  "steady operating points; --params is then its parameter file");
}

}  // namespace hstmon::cli
