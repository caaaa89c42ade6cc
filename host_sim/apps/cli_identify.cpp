// `hstmon identify LOG... --out FILE [--header FILE.hpp] [--json] [--report DIR]`: steady
// windows → steady-state regression of the thesis model → estimates with intervals,
// correlations, identifiability and the Table 2.3 validation; writes the parameter file and
// optionally a generated C++ header. `--paper FILE.csv` fits pump B's curve and the valve
// port areas of the paper rig; `--studies` runs its parameter studies (Figs. 7–9). With
// `--circuit FILE` the fit is the circuit's (cli_circuit_identify.hpp) and the paper
// table's estimates join its output, beside the circuit's own values.
// docs/identification.md describes the method and the formats.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "cli_circuit_identify.hpp"
#include "cli_commands.hpp"
#include "cli_identify_html.hpp"
#include "cli_identify_paper.hpp"
#include "cli_identify_report.hpp"
#include "cli_log_options.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/params_file.hpp"
#include "hstmon_ident/identified_outputs.hpp"
#include "hstmon_ident/operating_points.hpp"
#include "hstmon_ident/plots.hpp"
#include "hstmon_ident/steady_windows.hpp"
#include "hstmon_ident/thesis_fit.hpp"

namespace hstmon::cli {

namespace {

namespace id = hstmon::ident;

using identify::IdentifyArgs;
using identify::num;
using identify::plot_or_warn;
using identify::Report;
using identify::run_paper;
using identify::run_studies;

const char* const kThesisChannel[4] = {"Pmi", "Pmo", "Ppp", "ωm"};

// The steady windows of every log (reported, and listed in js["windows"]) as operating points.
// kExitOk, or the exit code after the error is printed.
int read_operating_points(const IdentifyArgs& a, const host::ReadOptions& ro, const ThesisInputs<double>& defaults,
                          Report& rep, nlohmann::json& js, std::vector<id::OperatingPoint>& points,
                          std::vector<std::string>& settings) {
  id::SteadyWindowOptions wo;
  wo.min_duration = a.min_duration;
  wo.min_samples = a.min_samples;
  wo.assume_steady = a.assume_steady;
  id::OperatingPointOptions po;
  po.defaults = defaults;
  po.setting_per_window = a.setting_per_window;
  nlohmann::json jwin = nlohmann::json::array();
  for (const std::string& path : a.logs) {
    const host::LogData log = read_log_reporting(path, ro);
    if (log.error) return kExitBadInput;
    const id::SteadyWindowResult w = id::find_steady_windows(log, wo);
    if (w.error) {
      fmt::print(stderr, "{}\n", capped(*w.error));
      return kExitBadInput;
    }
    if (w.windows.empty()) {
      fmt::print(stderr,
                 "{}: error: no steady window ({} rows; every run of samples drifts or is shorter than {} samples / "
                 "{:g} s — try --assume-steady for logs recorded only at steady state)\n",
                 path, log.rows(), a.assume_steady ? 1 : a.min_samples, a.assume_steady ? 0.0 : a.min_duration);
      return kExitBadInput;
    }
    rep("{}: {} rows, {} steady windows, {} samples not steady\n", path, log.rows(), w.windows.size(),
        w.rejected_samples);
    for (const auto& win : w.windows) {
      rep("  t = {:>9.4g} … {:<9.4g} s  n = {:<6} {}\n", win.t0, win.t1, win.samples(),
          win.assumed ? "(steadiness assumed)" : "");
      nlohmann::json jw = {{"log", path}, {"t0", win.t0}, {"t1", win.t1}, {"samples", win.samples()}, {"assumed", win.assumed}};
      for (std::size_t k = 0; k < host::kSignalCount; ++k) {
        if (!w.measured[k]) continue;
        const auto s = static_cast<host::Signal>(k);
        jw[std::string(host::signal_name(s))] = {{"mean", num(win.stats[k].mean)}, {"scatter", num(win.stats[k].scatter)},
                                                 {"slope", num(win.stats[k].slope)}};
      }
      jwin.push_back(jw);
    }
    id::append_operating_points(log, w, po, points, settings);
  }
  js["windows"] = jwin;
  return kExitOk;
}

// The fit's settings, noise, sizes and estimates; the estimates as JSON.
nlohmann::json report_parameters(const id::ThesisFitResult& fit, const std::vector<std::string>& settings,
                                 Report& rep) {
  rep("\nPRV settings (each gets its own kp):\n");
  for (std::size_t s = 0; s < settings.size(); ++s) rep("  [{}] {}\n", s + 1, settings[s]);
  rep("\nnoise per channel (weights):\n");
  for (std::size_t c = 0; c < 4; ++c) {
    rep("  {:<4} {:>10.4g} {:<6} ({})\n", kThesisChannel[c], c == 3 ? fit.noise[c] * 30.0 / M_PI : fit.noise[c] * 1e-5,
        c == 3 ? "rpm" : "bar", fit.noise_source[c]);
  }
  rep("\nfit: {} operating points, {} scalar samples, {} unknowns, dof {:g}; s² = {:.4g} (≈ 1 when the noise "
      "model fits); t(0.975) = {:.4g}\n",
      fit.points.size(), fit.samples, fit.fitted.size(), fit.dof, fit.s2, fit.t_value);
  rep("Levenberg–Marquardt: {} ({} evaluations); Jacobian rank {} of {}, condition {:.3g}\n\n", fit.lm_status,
      fit.evaluations, fit.rank, fit.fitted.size(), fit.condition);
  rep("  {:<8} {:>13} {:>11} {:>27}  {}\n", "param", "estimate", "SE", "95 % interval", "unit");
  nlohmann::json jp = nlohmann::json::array();
  for (const auto& e : fit.params) {
    if (e.status == id::ParamStatus::kNotIdentifiable) {
      rep("  {:<8} {:>13.6g} {:>11} {:>27}  {}  NOT IDENTIFIABLE — held at prior\n", e.name, e.value, "—", "—", e.unit);
    } else {
      rep("  {:<8} {:>13.6g} {:>11.3g} [{:>12.6g}, {:>12.6g}]  {}\n", e.name, e.value, e.se, e.ci_lo, e.ci_hi, e.unit);
    }
    jp.push_back({{"name", e.name},
                  {"unit", e.unit},
                  {"value", num(e.value)},
                  {"prior", num(e.prior)},
                  {"se", num(e.se)},
                  {"se_log", num(e.se_log)},
                  {"ci", {num(e.ci_lo), num(e.ci_hi)}},
                  {"sensitivity_sigma", num(e.sensitivity)},
                  {"identifiable", e.status == id::ParamStatus::kEstimated},
                  {"note", e.note}});
  }
  for (const auto& e : fit.params) {
    if (e.status == id::ParamStatus::kNotIdentifiable) rep("  {}: {}\n", e.name, e.note);
  }
  rep("  Rf and Rbl act only as their sum (Rf + Rbl)·ωm in eq. 2.8: one parameter; written split in the prior's "
      "ratio (Rf = {:.6g}, Rbl = {:.6g}).\n",
      fit.fitted_params.Rf, fit.fitted_params.Rbl);
  return jp;
}

// The correlation of the estimates (ln-parameters), as a table and as JSON rows.
nlohmann::json report_correlation(const id::ThesisFitResult& fit, Report& rep) {
  rep("\ncorrelation of the estimates (ln-parameters):\n  {:>8}", "");
  for (const auto& n : fit.fitted) rep(" {:>7}", n);
  rep("\n");
  nlohmann::json jc = nlohmann::json::array();
  for (std::size_t i = 0; i < fit.fitted.size(); ++i) {
    rep("  {:>8}", fit.fitted[i]);
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t j = 0; j < fit.fitted.size(); ++j) {
      rep(" {:>7.3f}", fit.correlation(i, j));
      row.push_back(num(fit.correlation(i, j)));
    }
    jc.push_back(row);
    rep("\n");
  }
  return jc;
}

// The Table 2.3 validation, as a table and as JSON.
nlohmann::json report_validation(const id::ThesisFitResult& fit, Report& rep) {
  rep("\nvalidation (Table 2.3 form; error = (model − data)/data, negative: model below data):\n");
  rep("  {:<8} {:>8} {:>14} {:>12}\n", "Variable", "points", "Average Error", "RMS Error");
  nlohmann::json jv = nlohmann::json::array();
  for (const auto& v : fit.validation) {
    rep("  {:<8} {:>8} {:>13.3f}% {:>11.3f}%\n", v.signal, v.points, v.avg_error_pct, v.rms_error_pct);
    jv.push_back({{"signal", v.signal}, {"points", v.points}, {"avg_error_pct", num(v.avg_error_pct)},
                  {"rms_error_pct", num(v.rms_error_pct)}});
  }
  return jv;
}

// Figs. 2.5–2.7 form into the report directory: each pressure against speed, measured and model.
void plot_validation(const std::string& report_dir, const id::ThesisFitResult& fit, Report& rep) {
  for (std::size_t c = 0; c < 3; ++c) {
    id::PlotSeries meas{"measured (window means)", {}, {}, true}, model{"model, fitted parameters", {}, {}, true};
    for (std::size_t w = 0; w < fit.points.size(); ++w) {
      const auto& p = fit.points[w];
      if (!std::isfinite(p.y[c]) || !std::isfinite(p.y[3])) continue;
      meas.x.push_back(p.y[3] * 30.0 / M_PI);
      meas.y.push_back(p.y[c] * 1e-5);
      model.x.push_back(fit.predicted[w][3] * 30.0 / M_PI);
      model.y.push_back(fit.predicted[w][c] * 1e-5);
    }
    if (meas.x.empty()) continue;
    const std::string file = report_dir + "/validation_" + std::string(kThesisChannel[c]) + ".svg";
    const std::string title = fmt::format("{}: experiment and model at steady state", kThesisChannel[c]);
    plot_or_warn(rep, file, title,
                 id::plot_xy(file, title, "speed [rpm]", fmt::format("{} [bar]", kThesisChannel[c]), {meas, model}));
  }
}

int run_thesis(const IdentifyArgs& a, Report& rep, nlohmann::json& js) {
  host::ParamsFileResult pf;
  const std::optional<host::ReadOptions> ro = to_read_options(a.io, "identify");
  if (!ro) return kExitUsage;
  if (!read_params_option(a.io.params, pf)) return kExitBadInput;
  const ThesisParams<double> prior = pf.params.value_or(ThesisParams<double>{});
  const ThesisInputs<double> defaults = pf.inputs.value_or(ThesisInputs<double>{});
  std::vector<id::OperatingPoint> points;
  std::vector<std::string> settings;
  rep("hstmon identify — steady-state regression of the thesis model (seed 000 §2.3)\n\n");
  if (const int code = read_operating_points(a, *ro, defaults, rep, js, points, settings); code != kExitOk) return code;

  id::ThesisFitOptions fo;
  fo.prior = prior;
  fo.min_settings = a.min_settings;
  if (a.noise_pressure > 0.0) fo.noise[0] = fo.noise[1] = fo.noise[2] = a.noise_pressure;
  if (a.noise_speed > 0.0) fo.noise[3] = a.noise_speed;
  const id::ThesisFitResult fit = id::fit_thesis_steady(points, settings, fo);
  if (!fit.ok()) {
    // One log named: the fit is over all of them, and a list of many would fill the screen.
    const std::string files =
        a.logs.size() == 1 ? a.logs[0] : fmt::format("{} (and {} more logs)", a.logs[0], a.logs.size() - 1);
    fmt::print(stderr, "{}\n", capped(fmt::format("{}: error: {}", files, *fit.error)));
    return kExitBadInput;
  }

  const nlohmann::json jp = report_parameters(fit, settings, rep);
  const nlohmann::json jc = report_correlation(fit, rep);
  const nlohmann::json jv = report_validation(fit, rep);
  for (const auto& n : fit.notes) rep("note: {}\n", n);
  js["thesis"] = {{"parameters", jp},
                  {"fitted", fit.fitted},
                  {"correlation", jc},
                  {"validation", jv},
                  {"settings", settings},
                  {"s2", num(fit.s2)},
                  {"dof", num(fit.dof)},
                  {"samples", fit.samples},
                  {"condition", num(fit.condition)},
                  {"rank", fit.rank},
                  {"noise", {num(fit.noise[0]), num(fit.noise[1]), num(fit.noise[2]), num(fit.noise[3])}},
                  {"lm_status", fit.lm_status},
                  {"notes", fit.notes}};

  if (const auto err = id::write_identified_params(a.out, fit)) {
    fmt::print(stderr, "{}\n", *err);
    return kExitBadInput;
  }
  rep("\nwrote parameter file {} (hstmon replay --params {})\n", a.out, a.out);
  if (!a.header.empty()) {
    if (const auto err = id::write_params_header(a.header, fit)) {
      fmt::print(stderr, "{}\n", *err);
      return kExitBadInput;
    }
    rep("wrote generated header {}\n", a.header);
  }
  if (!a.report.empty()) plot_validation(a.report, fit, rep);
  return kExitOk;
}

int run_identify(const IdentifyArgs& a) {
  if (a.logs.empty() && a.paper.empty() && !a.studies) {
    fmt::print(stderr, "hstmon identify: error: give LOG files, --paper FILE.csv or --studies\n");
    return kExitUsage;
  }
  if (!a.logs.empty() && a.out.empty()) {
    fmt::print(stderr, "hstmon identify: error: --out FILE is required with LOG files\n");
    return kExitUsage;
  }
  if (!a.report.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.report, ec);
    if (ec) {
      fmt::print(stderr, "{}: error: cannot create report directory: {}\n", a.report, ec.message());
      return kExitBadInput;
    }
  }
  Report rep;
  rep.quiet = a.json;
  rep.dir = a.report;
  nlohmann::json js = {{"type", "identify"}};
  int rc = kExitOk;
  double worst = 0.0;  // no circuit: nothing to compare with
  if (!a.logs.empty()) rc = run_thesis(a, rep, js);
  if (rc == kExitOk && !a.paper.empty()) rc = run_paper(a, nullptr, rep, js, worst);
  if (rc == kExitOk && a.studies) run_studies(rep, js);
  if (rc != kExitOk) return rc;
  if (a.json) fmt::print("{}\n", js.dump(2));
  if (!a.report.empty()) {
    std::ofstream(a.report + "/report.txt") << rep.text;
    std::ofstream(a.report + "/report.json") << js.dump(2) << "\n";
    if (const std::string err = write_identify_html(a.report + "/report.html", js, rep.text, rep.figures); !err.empty()) {
      fmt::print(stderr, "hstmon identify: error: {}\n", err);
      return kExitBadInput;
    }
  }
  return kExitOk;
}

// With --circuit: --paper and --studies as sections of the circuit's output (text, JSON
// keys "paper" and "studies", tables and panels of its report), the table's estimates
// beside the circuit's values.
int circuit_paper_sections(const IdentifyArgs& a, const circuit_tools::LoadedCircuit& c, bool panels,
                           IdentifySections& out) {
  Report rep;
  rep.quiet = true;  // the circuit command prints everything at its end
  rep.dir = panels ? a.report : std::string();
  rep.panels = &out.panels;
  double worst = 0.0;
  std::string verdict;
  if (!a.paper.empty()) {
    if (const int rc = run_paper(a, &c, rep, out.json, worst); rc != kExitOk) return rc;
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

/// `hstmon identify`: the thesis rig's, or with --circuit the circuit's (cli_circuit_identify.hpp).
int run_identify_or_circuit_identify(IdentifyArgs a, const CLI::App& cmd) {
  a.cd_given = cmd.count("--cd") > 0;
  a.rho_given = cmd.count("--rho") > 0;
  if (a.studies && a.report.empty()) {
    fmt::print(stderr, "hstmon identify: error: --studies needs --report DIR for its plots\n");
    return kExitUsage;
  }
  if (a.circuit.empty()) {
    for (const char* opt : {"--fit", "--window-input"}) {
      if (cmd.count(opt) > 0) {
        fmt::print(stderr, "hstmon identify: error: {} goes with --circuit\n", opt);
        return kExitUsage;
      }
    }
    return run_identify(a);
  }
  CircuitIdentifyArgs c;
  if (!take_circuit_args(cmd, {}, a, c)) return kExitUsage;
  c.logs = a.logs;
  c.fit = a.fit;
  c.out = a.out;
  if (cmd.count("--min-duration") > 0) c.min_duration = a.min_duration;
  if (cmd.count("--min-samples") > 0) c.min_samples = a.min_samples;
  if (cmd.count("--min-settings") > 0) c.min_settings = a.min_settings;
  c.assume_steady = a.assume_steady;
  c.noise_pressure = a.noise_pressure;
  c.noise_speed = a.noise_speed;
  c.header = a.header;
  c.setting_per_window = a.setting_per_window || !a.window_inputs.empty();
  c.window_inputs = a.window_inputs;
  if (!a.paper.empty() || a.studies) {
    c.sections = [&a](const circuit_tools::LoadedCircuit& lc, bool panels, IdentifySections& out) {
      return circuit_paper_sections(a, lc, panels, out);
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
      "Fit model parameters to the steady states in logs (the thesis rig, or with --circuit any circuit); "
      "paper-rig pump curve, port areas and parameter studies",
      run_identify_or_circuit_identify);
  cmd->add_option("logs", args->logs,
                  "logs (CSV as for replay) with steady operating points: the thesis rig's, or with --circuit the "
                  "circuit's");
  cmd->add_option("--out", args->out,
                  "parameter file to write (JSON, read by replay --params); with --circuit the circuit's parameter "
                  "file at the fitted values");
  cmd->add_option("--header", args->header,
                  "also write a generated C++ header (constexpr ThesisParams; with --circuit the circuit at the "
                  "fitted values)");
  cmd->add_flag("--json", args->json, "print the results as JSON instead of the human report");
  cmd->add_option("--report", args->report,
                  "directory for the report: report.html (one self-contained page) and the plots; the thesis rig "
                  "adds report.txt, report.json and SVG files, a circuit report.md, figure.svg and plots.gp");
  add_log_options(*cmd, args->io,
                  "parameter file: the thesis rig's known Dm, Dp and start values (default Table 2.2); with --circuit "
                  "the circuit's (default <stem>.params.json beside it)",
                  "--params,--prior");
  cmd->add_option("--min-duration", args->min_duration,
                  "shortest steady window [s] (default 1; with --circuit 0.2, after the settle time)");
  cmd->add_option("--min-samples", args->min_samples,
                  "fewest samples in a steady window (default 3; with --circuit 1)");
  cmd->add_flag("--assume-steady", args->assume_steady,
                "accept windows of one sample (DAS logs recorded only at steady state)");
  cmd->add_flag("--setting-per-window", args->setting_per_window,
                "give every steady window its own load setting: the thesis rig's own kp, even when the log has a "
                "kp column; with --circuit its own value of each input the logs lack (or of --window-input), "
                "fitted with --fit");
  add_name_list(*cmd, "--window-input", args->window_inputs,
                "with --circuit: an input fitted per steady window (repeatable; implies --setting-per-window); "
                "its logged values only start the fit");
  cmd->add_option("--min-settings", args->min_settings,
                  "fewest PRV settings (loads) accepted (default 3; with --circuit: distinct held input settings, "
                  "default what the fit needs)");
  for (const auto& [name, sigma, what] :
       {std::tuple{"--noise-pressure", &args->noise_pressure, "pressure noise σ [Pa]"},
        std::tuple{"--noise-speed", &args->noise_speed, "speed noise σ [rad/s]"}}) {
    cmd->add_option(
        name, *sigma,
        std::string(what) + " for the weights (default: from the window scatter; with --circuit the sensors' noise)");
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
  cmd->add_option("--circuit", args->circuit,
                  "fit parameters of this circuit file (docs/circuits.md) to the logs' steady operating points");
  add_name_list(*cmd, "--fit", args->fit, "with --circuit: parameters to fit, by name (comma separated, repeatable)");
}

}  // namespace hstmon::cli
