// `hstmon identify [--circuit FILE] [--fit P,...] LOG... [--out FILE] [--header FILE.hpp]
// [--json] [--report DIR]`: the circuit's (default: the built-in thesis.json) parameters
// fitted to the logs' steady operating points (cli_circuit_identify.hpp), with estimates,
// intervals, correlations, what the points cannot determine, and the agreement per channel
// in the form of Table 2.3. `--paper FILE.csv` fits pump B's curve and the valve port
// areas of the paper rig, beside a --circuit's compensated pump and orifices; `--studies`
// runs its parameter studies (Figs. 7–9). docs/identification.md describes the method.
#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "cli_circuit_identify.hpp"
#include "cli_commands.hpp"
#include "cli_identify_paper.hpp"
#include "cli_identify_report.hpp"
#include "cli_log_options.hpp"

namespace hstmon::cli {

namespace {

using identify::IdentifyArgs;
using identify::Report;
using identify::run_paper;
using identify::run_studies;

// --paper and --studies as sections of the command's output (text, JSON keys "paper" and
// "studies", tables and panels of its report), the table's estimates beside the values of
// `beside` (the circuit named with --circuit; nullptr: the table alone).
int paper_sections(const IdentifyArgs& a, const circuit_tools::LoadedCircuit* beside, bool panels,
                   IdentifySections& out) {
  Report rep;
  rep.quiet = true;  // the circuit command prints everything at its end
  rep.panels = panels ? &out.panels : nullptr;
  double worst = 0.0;
  std::string verdict;
  if (!a.paper.empty()) {
    if (const int rc = run_paper(a, beside, rep, out.json, worst); rc != kExitOk) return rc;
    const bool compared = out.json["paper"].contains("circuit") && out.json["paper"]["circuit"].contains("pump");
    verdict = fmt::format(
        "paper table {} analysed{}", std::filesystem::path(a.paper).filename().string(),
        compared ? fmt::format(" (pump curve: largest difference from the circuit file's {:.3g} %)", worst) : "");
  }
  if (a.studies) {
    run_studies(rep, out.json);
    verdict += std::string(verdict.empty() ? "" : "; ") + "the paper's parameter studies (Figs. 7–9) run";
  }
  out.text = rep.text;
  out.tables = std::move(rep.tables);
  out.verdict = verdict;
  return kExitOk;
}

/// `hstmon identify`: the fit of the circuit's parameters (the built-in thesis.json unless
/// --circuit names one), with the paper sections after it.
int run_identify_command(IdentifyArgs a, const CLI::App& cmd) {
  a.cd_given = cmd.count("--cd") > 0;
  a.rho_given = cmd.count("--rho") > 0;
  if (a.studies && a.report.empty()) {
    fmt::print(stderr, "hstmon identify: error: --studies needs --report DIR for its plots\n");
    return kExitUsage;
  }
  CircuitIdentifyArgs c;
  if (!take_circuit_args(cmd, {}, a, c)) return kExitUsage;
  c.logs = a.logs;
  c.fit = a.fit;
  c.out = a.out;
  c.min_duration = a.min_duration;
  c.min_samples = a.min_samples;
  c.min_settings = a.min_settings;
  c.assume_steady = a.assume_steady;
  c.noise_pressure = a.noise_pressure;
  c.noise_speed = a.noise_speed;
  c.header = a.header;
  c.setting_per_window = a.setting_per_window || !a.window_inputs.empty();
  c.window_inputs = a.window_inputs;
  if (!a.paper.empty() || a.studies) {
    // The paper table is compared with a circuit the user names, not with the default one.
    const bool beside = cmd.count("--circuit") > 0;
    c.sections = [&a, beside](const circuit_tools::LoadedCircuit& lc, bool panels, IdentifySections& out) {
      return paper_sections(a, beside ? &lc : nullptr, panels, out);
    };
  }
  return run_circuit_identify(c);
}

// An option of names, comma separated or repeated (`--fit A,B --fit C`), that never takes
// the positional logs after it.
void add_name_list(CLI::App& cmd, const std::string& name, std::vector<std::string>& out, const std::string& help) {
  cmd.add_option(name, out, help)
      ->delimiter(',')
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace

void add_identify_command(CLI::App& app, int& exit_code) {
  const auto [cmd, args] = add_command<IdentifyArgs>(
      app, exit_code, "identify",
      "Fit a circuit's parameters (default: the built-in thesis.json) to the steady operating points of logs; "
      "paper-rig pump curve, port areas and parameter studies",
      run_identify_command);
  cmd->add_option("logs", args->logs, "logs (CSV as for replay) with steady operating points");
  cmd->add_option("--circuit", args->circuit,
                  "circuit file (docs/circuits.md) whose parameters are fitted; default: the thesis rig (thesis.json)");
  add_name_list(*cmd, "--fit", args->fit,
                "parameters to fit, by name (comma separated, repeatable); default: the circuit's losses and "
                "openings (resistances, conductances, dampings, orifices, areas). Those the points cannot determine "
                "are held at their start values, with the reason");
  cmd->add_option("--out", args->out,
                  "parameter file to write: the circuit's values with the fitted ones (read by --params)");
  cmd->add_option("--header", args->header, "also write a generated C++ header of the circuit at the fitted values");
  cmd->add_flag("--json", args->json, "print the results as JSON instead of the text");
  cmd->add_option("--report", args->report, "directory for the report: report.html, report.md, figure.svg, plots.gp");
  add_log_options(*cmd, args->io,
                  "the circuit's parameter file: the start values (default <stem>.params.json beside it)",
                  "--params,--prior");
  cmd->add_option("--min-duration", args->min_duration, "shortest steady operating point after the settle time [s]")
      ->capture_default_str();
  cmd->add_option("--min-samples", args->min_samples, "fewest rows in an operating point")->capture_default_str();
  cmd->add_flag("--assume-steady", args->assume_steady,
                "every held stretch is steady from its first row (DAS logs recorded only at steady state)");
  cmd->add_flag("--setting-per-window", args->setting_per_window,
                "give every operating point its own value of each input the logs lack (or of --window-input), "
                "fitted with --fit");
  add_name_list(*cmd, "--window-input", args->window_inputs,
                "an input fitted per operating point (repeatable; implies --setting-per-window), e.g. the thesis "
                "rig's PRV setting kp; its logged values only start the fit");
  cmd->add_option("--min-settings", args->min_settings,
                  "fewest distinct held input settings accepted (default 0: what the fit needs)");
  for (const auto& [name, sigma, what] :
       {std::tuple{"--noise-pressure", &args->noise_pressure, "σ of every pressure sensor [Pa]"},
        std::tuple{"--noise-speed", &args->noise_speed, "σ of every speed sensor [rad/s]"}}) {
    cmd->add_option(name, *sigma, std::string(what) + " for the weights (default: the circuit file's sensors)");
  }
  cmd->add_option("--paper", args->paper,
                  "paper-rig table (kind,label,p,q): pump curve and DCV/PRV port areas; with --circuit also beside "
                  "the circuit's compensated pump and its orifices named dcv/prv");
  cmd->add_option("--cd", args->cd,
                  "discharge coefficient for the port areas (with --circuit: the orifice's Cd unless given)")
      ->capture_default_str();
  cmd->add_option("--rho", args->rho,
                  "oil density [kg/m^3] for the port areas (with --circuit: the orifice's rho unless given)")
      ->capture_default_str();
  cmd->add_flag("--studies", args->studies,
                "run the paper's parameter studies (Figs. 7-9, Table I model) into --report DIR");
}

}  // namespace hstmon::cli
