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
#include "cli_log_options.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/params_file.hpp"
#include "hstmon_ident/identified_outputs.hpp"
#include "hstmon_ident/operating_points.hpp"
#include "hstmon_ident/paper_circuit.hpp"
#include "hstmon_ident/paper_studies.hpp"
#include "hstmon_ident/paper_tables.hpp"
#include "hstmon_ident/plots.hpp"
#include "hstmon_ident/port_area.hpp"
#include "hstmon_ident/pump_curve_fit.hpp"
#include "hstmon_ident/steady_windows.hpp"
#include "hstmon_ident/thesis_fit.hpp"

namespace hstmon::cli {

namespace {

namespace id = hstmon::ident;

struct IdentifyArgs {
  std::vector<std::string> logs;
  std::string out;
  std::string header;
  bool json = false;
  std::string report;
  LogOptionArgs io;  // --map, --separator, --lenient, --rate, --params (alias --prior)
  double min_duration = 1.0;
  std::size_t min_samples = 3;
  bool assume_steady = false;
  bool setting_per_window = false;
  std::size_t min_settings = 3;
  double noise_pressure = 0.0;
  double noise_speed = 0.0;
  std::string paper;
  double cd = 0.61;
  double rho = 870.0;
  bool studies = false;
  bool cd_given = false, rho_given = false;  // --cd, --rho on the command line (else a circuit's own)
  std::vector<std::string> window_inputs;    // --window-input: inputs fitted per steady window (--circuit)
  std::string circuit;             // --circuit: run_circuit_identify instead (cli_circuit_identify.hpp)
  std::vector<std::string> fit;
};

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Appends to the report text and echoes it to stdout unless JSON is on; collects the plots
// for report.html. With --circuit (`panels` set) the plots become panels of the circuit
// report's one figure and the tables join its tables: one report folder, one page.
struct Report {
  bool quiet = false;
  std::string text;
  std::vector<ReportFigure> figures;
  std::string dir;                                  // the report folder ("" = no plots)
  std::vector<sim::ReportPanel>* panels = nullptr;  // --circuit: plots go here, not to SVG files
  std::vector<sim::ReportTable> tables;             // --circuit: the report's tables
  template <typename... A>
  void operator()(fmt::format_string<A...> f, A&&... a) {
    const std::string s = fmt::format(f, std::forward<A>(a)...);
    text += s;
    if (!quiet) fmt::print("{}", s);
  }
  bool plots() const { return !dir.empty(); }
  void plot(const std::string& stem, const std::string& title, const std::string& xlabel, const std::string& ylabel,
            const std::vector<id::PlotSeries>& series);
};

void plot_or_warn(Report& rep, const std::string& file, const std::string& caption, const std::string& err) {
  if (err.empty()) {
    rep.figures.push_back({file, caption});
  } else {
    fmt::print(stderr, "hstmon identify: warning: {}\n", err);
  }
}

// y of a line series at x (its x ascending): linear between its points, NaN outside them.
double line_at(const id::PlotSeries& s, double x) {
  const auto it = std::lower_bound(s.x.begin(), s.x.end(), x);
  if (it == s.x.end()) return std::nan("");
  const auto i = static_cast<std::size_t>(it - s.x.begin());
  if (*it == x) return s.y[i];
  if (i == 0) return std::nan("");
  return s.y[i - 1] + (s.y[i] - s.y[i - 1]) * (x - s.x[i - 1]) / (s.x[i] - s.x[i - 1]);
}

// A plot as one panel of the circuit report's figure: the panel's x are every series' x
// (sorted, once each); a data series has NaN where it has no point, a line is interpolated
// (gnuplot leaves NaN out, so a line would otherwise break at another series' x).
sim::ReportPanel panel_of(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                          const std::vector<id::PlotSeries>& series) {
  sim::ReportPanel p{title, xlabel, ylabel, {}, {}};
  for (const auto& s : series) p.x.insert(p.x.end(), s.x.begin(), s.x.end());
  std::sort(p.x.begin(), p.x.end());
  p.x.erase(std::unique(p.x.begin(), p.x.end()), p.x.end());
  for (const auto& s : series) {
    sim::ReportSeries out{s.label, {}, s.points ? "points pt 7 ps 0.6" : "lines lw 2"};
    out.y.reserve(p.x.size());
    for (double x : p.x) {
      if (!s.points) {
        out.y.push_back(line_at(s, x));
        continue;
      }
      const auto it = std::find(s.x.begin(), s.x.end(), x);
      out.y.push_back(it == s.x.end() ? std::nan("") : s.y[static_cast<std::size_t>(it - s.x.begin())]);
    }
    p.series.push_back(std::move(out));
  }
  return p;
}

void Report::plot(const std::string& stem, const std::string& title, const std::string& xlabel,
                  const std::string& ylabel, const std::vector<id::PlotSeries>& series) {
  if (!plots()) return;
  if (panels != nullptr) {
    panels->push_back(panel_of(title, xlabel, ylabel, series));
    return;
  }
  const std::string file = dir + "/" + stem + ".svg";
  plot_or_warn(*this, file, title, id::plot_xy(file, title, xlabel, ylabel, series));
}

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

// The circuit's pump-curve parameters beside the fitted ones (paper_circuit.hpp): text,
// a table row per parameter and JSON; the largest |difference| [%] goes to `worst`.
nlohmann::json compare_pump_with_circuit(const id::PumpCurveFit& f, const std::array<double, 5>& v,
                                         const circuit_tools::LoadedCircuit& c, Report& rep, double& worst) {
  nlohmann::json out = nlohmann::json::array();
  const auto pumps = id::circuit_pump_curves(c);
  if (pumps.empty()) {
    rep("  circuit {}: no compensated_pump element to compare the curve with\n", c.file.name);
    return out;
  }
  for (const auto& p : pumps) {
    rep("\n  beside circuit {}'s {} (difference = (fitted − circuit)/circuit):\n", c.file.name, p.element);
    rep("  {:<5} {:<16} {:>12} {:>12} {:>11}  {}\n", "", "circuit value of", "circuit", "fitted", "difference",
        "circuit inside the 95 % interval");
    sim::ReportTable t{
        "Pump curve beside circuit " + c.file.name + "'s " + p.element,
        {"parameter", "circuit value of", "circuit", "fitted", "difference", "circuit inside the 95 % interval"},
        {}};
    nlohmann::json jp = nlohmann::json::array();
    for (std::size_t k = 0; k < 5; ++k) {
      const id::CircuitNumber& n = p.params[k];
      if (!n.given()) continue;
      const double d = id::percent_difference(v[k], n.value);
      const bool inside = f.ci_lo[k] <= n.value && n.value <= f.ci_hi[k];
      if (std::isfinite(d)) worst = std::max(worst, std::fabs(d));
      const std::string of = n.name + (n.input ? " (input)" : "");
      rep("  {:<5} {:<16} {:>12.6g} {:>12.6g} {:>+10.3g}%  {}\n", id::pump_curve_param_names()[k], of, n.value, v[k], d,
          inside ? "yes" : "no");
      t.rows.push_back({id::pump_curve_param_names()[k], of, fmt::format("{:.6g}", n.value),
                        fmt::format("{:.6g}", v[k]), fmt::format("{:+.3g} %", d), inside ? "yes" : "no"});
      jp.push_back({{"name", id::pump_curve_param_names()[k]},
                    {"circuit_name", n.name},
                    {"input", n.input},
                    {"circuit", num(n.value)},
                    {"fitted", num(v[k])},
                    {"difference_pct", num(d)},
                    {"inside_ci", inside}});
    }
    rep.tables.push_back(std::move(t));
    out.push_back({{"element", p.element}, {"parameters", jp}});
  }
  return out;
}

// Pump B's curve from the table's pump rows: text, plot, JSON into jpaper["pump_curve"]
// (and ["circuit"]["pump"] beside the circuit's compensated pump).
int report_pump_curve(const IdentifyArgs& a, const id::PaperTables& t, const circuit_tools::LoadedCircuit* circuit,
                      Report& rep, nlohmann::json& jpaper, double& worst) {
  const id::PumpCurveFit f = id::fit_pump_curve(t.pump);
  if (!f.ok()) {
    fmt::print(stderr, "{}: error: {}\n", a.paper, *f.error);
    return kExitBadInput;
  }
  rep("\npump B flow–pressure curve ({} samples, RMS residual {:.4g} l/min, condition {:.3g}):\n", f.n, f.rms * 6e4,
      f.condition);
  const std::array<double, 5> v{f.params.Q0, f.params.R, f.params.Pc, f.params.Pk, f.params.Pmax};
  const std::array<const char*, 5> unit{"m^3/s", "Pa*s/m^3", "Pa", "Pa", "Pa"};
  sim::ReportTable tab{"Pump curve (paper table)", {"parameter", "estimate", "SE", "95 % interval", "unit"}, {}};
  nlohmann::json jp = nlohmann::json::array();
  for (std::size_t k = 0; k < 5; ++k) {
    const char* name = id::pump_curve_param_names()[k];
    rep("  {:<5} {:>12.6g} ± {:<10.3g} [{:>12.6g}, {:>12.6g}] {}{}\n", name, v[k], f.se[k], f.ci_lo[k], f.ci_hi[k],
        unit[k], f.identifiable[k] ? "" : "  NOT IDENTIFIABLE from these data");
    tab.rows.push_back({name, fmt::format("{:.6g}", v[k]), fmt::format("{:.3g}", f.se[k]),
                        fmt::format("[{:.6g}, {:.6g}]", f.ci_lo[k], f.ci_hi[k]),
                        std::string(unit[k]) + (f.identifiable[k] ? "" : " (not identifiable)")});
    jp.push_back({{"name", name},
                  {"value", num(v[k])},
                  {"se", num(f.se[k])},
                  {"ci", {num(f.ci_lo[k]), num(f.ci_hi[k])}},
                  {"unit", unit[k]},
                  {"identifiable", f.identifiable[k]}});
  }
  rep.tables.push_back(std::move(tab));
  jpaper["pump_curve"] = {{"parameters", jp}, {"rms", num(f.rms)}, {"samples", f.n}};
  if (circuit != nullptr) jpaper["circuit"]["pump"] = compare_pump_with_circuit(f, v, *circuit, rep, worst);
  if (rep.plots()) {
    PumpCurve<double> c;
    c.make(f.params);
    id::PlotSeries data{"data", {}, {}, true}, model{"fitted 3-region curve", {}, {}, false};
    double pmax = 0.0;
    for (const auto& s : t.pump) {
      data.x.push_back(s.p * 1e-5);
      data.y.push_back(s.q * 6e4);
      pmax = std::max(pmax, s.p);
    }
    for (int i = 0; i <= 400; ++i) {
      const double p = pmax * i / 400.0;
      model.x.push_back(p * 1e-5);
      model.y.push_back(c.flow(p) * 6e4);
    }
    rep.plot("pump_curve", "Pump B flow vs pressure (Fig. 3/4)", "P [bar]", "Q [l/min]", {data, model});
  }
  return kExitOk;
}

// Cd and ρ for one kind's port areas: --cd / --rho when given, else (with a circuit) the
// first orifice of that name's, else the defaults. `said`: where they came from.
void port_cd_rho(const IdentifyArgs& a, const std::vector<id::CircuitOrificeValues>& orifices, double& cd, double& rho,
                 std::string& said) {
  cd = a.cd;
  rho = a.rho;
  said.clear();
  if (orifices.empty()) return;
  const id::CircuitOrificeValues& o = orifices.front();
  if (!a.cd_given && o.cd.given() && std::isfinite(o.cd.value)) {
    cd = o.cd.value;
    said += fmt::format("Cd from {}'s {}", o.element, o.cd.name);
  }
  if (!a.rho_given && o.rho.given() && std::isfinite(o.rho.value)) {
    rho = o.rho.value;
    said += fmt::format("{}ρ from {}'s {}", said.empty() ? "" : ", ", o.element, o.rho.name);
  }
}

// One fitted opening beside the circuit's orifices of that kind: "" when there is none,
// else the text cell; JSON rows into jc. The circuit's value is its nominal opening: the
// differences say which table opening that is (if any).
std::string compare_port_with_circuit(const id::PortAreaFit& f, double rho,
                                      const std::vector<id::CircuitOrificeValues>& orifices, nlohmann::json& jc) {
  std::string cell;
  for (const auto& o : orifices) {
    const bool by_k = o.k.given();
    const double fitted = by_k ? f.cd_area * std::sqrt(2.0 / rho) : f.area;
    const id::CircuitNumber& n = by_k ? o.k : o.area;
    if (!n.given()) continue;
    const double d = id::percent_difference(fitted, n.value);
    cell += fmt::format("{}{} {}: {:+.3g} %", cell.empty() ? "" : "; ", o.element, by_k ? "k" : "A", d);
    jc.push_back({{"opening", f.label},
                  {"element", o.element},
                  {"quantity", by_k ? "k" : "area"},
                  {"circuit_name", n.name},
                  {"input", n.input},
                  {"circuit", num(n.value)},
                  {"fitted", num(fitted)},
                  {"difference_pct", num(d)}});
  }
  return cell;
}

// One kind's port areas ("dcv" or "prv"): text, plot, JSON into jpaper[kind] (and
// ["circuit"][kind] beside the circuit's orifices of that name).
int report_port_areas(const IdentifyArgs& a, const std::string& kind, const id::PaperTables& t,
                      const circuit_tools::LoadedCircuit* circuit, Report& rep, nlohmann::json& jpaper) {
  const auto& groups = kind == "dcv" ? t.dcv : t.prv;
  if (groups.empty()) return kExitOk;
  const std::string name = kind == "dcv" ? "DCV" : "PRV";
  const auto orifices = circuit != nullptr ? id::circuit_orifices_named(*circuit, kind)
                                           : std::vector<id::CircuitOrificeValues>{};
  double cd = a.cd, rho = a.rho;
  std::string said;
  port_cd_rho(a, orifices, cd, rho, said);
  rep("\n{} port areas from Q = Cd·A·√(2|ΔP|/ρ) (line through the origin; Cd = {:g}, ρ = {:g} kg/m³{}):\n", name, cd,
      rho, said.empty() ? "" : ": " + said);
  for (const auto& o : orifices) {
    const id::CircuitNumber& n = o.k.given() ? o.k : o.area;
    rep("  circuit {}'s {}: {} = {:.5g} {}{}\n", circuit->file.name, o.element, n.name, n.value,
        o.k.given() ? "m³/(s·√Pa)" : "m²", n.input ? " (the input's nominal value)" : "");
  }
  if (circuit != nullptr && orifices.empty())
    rep("  circuit {}: no orifice named {} to compare with\n", circuit->file.name, kind);
  const bool compare = !orifices.empty();
  rep("  {:<8} {:>4} {:>12} {:>10} {:>27} {:>8}{}\n", "opening", "n", "A [m²]", "SE", "95 % interval", "R²",
      compare ? "  beside the circuit" : "");
  sim::ReportTable tab{name + " port areas (paper table)", {"opening", "n", "A [m²]", "SE", "95 % interval", "R²"}, {}};
  if (compare) tab.header.push_back("difference from the circuit");
  nlohmann::json ja = nlohmann::json::array(), jc = nlohmann::json::array();
  std::vector<id::PlotSeries> series;
  for (const auto& [label, samples] : groups) {
    const id::PortAreaFit f = id::fit_port_area(label, samples, cd, rho);
    if (!f.ok()) {
      fmt::print(stderr, "{}: error: {} {}\n", a.paper, name, *f.error);
      return kExitBadInput;
    }
    const std::string cmp = compare ? compare_port_with_circuit(f, rho, orifices, jc) : "";
    rep("  {:<8} {:>4} {:>12.5g} {:>10.3g} [{:>12.5g}, {:>12.5g}] {:>8.5f}{}{}\n", label, f.n, f.area, f.area_se,
        f.ci_lo, f.ci_hi, f.r2, compare ? "  " : "", cmp);
    tab.rows.push_back({label, std::to_string(f.n), fmt::format("{:.5g}", f.area), fmt::format("{:.3g}", f.area_se),
                        fmt::format("[{:.5g}, {:.5g}]", f.ci_lo, f.ci_hi), fmt::format("{:.5f}", f.r2), cmp});
    ja.push_back({{"opening", label},
                  {"n", f.n},
                  {"area", num(f.area)},
                  {"se", num(f.area_se)},
                  {"ci", {num(f.ci_lo), num(f.ci_hi)}},
                  {"cd_area", num(f.cd_area)},
                  {"r2", num(f.r2)}});
    id::PlotSeries d{label + " data", {}, {}, true}, l{label + " fit", {}, {}, false};
    double xmax = 0.0;
    for (const auto& s : samples) {
      const double x = std::copysign(std::sqrt(2.0 * std::fabs(s.dp) / rho), s.dp);
      d.x.push_back(x);
      d.y.push_back(s.q * 6e4);
      xmax = std::max(xmax, std::fabs(x));
    }
    l.x = {0.0, xmax};
    l.y = {0.0, f.cd_area * xmax * 6e4};
    series.push_back(d);
    series.push_back(l);
  }
  rep.tables.push_back(std::move(tab));
  jpaper[kind] = ja;
  if (compare) jpaper["circuit"][kind] = jc;
  rep.plot(kind + "_port_areas", fmt::format("{}: flow vs sqrt(2|dP|/rho) (Fig. {})", name, kind == "dcv" ? 5 : 6),
           "sqrt(2|dP|/rho) [m/s]", "Q [l/min]", series);
  return kExitOk;
}

// --paper: the table's pump curve and port areas into js["paper"]; with a circuit each
// beside the circuit's values. `worst`: the pump curve's largest difference from the
// circuit's compensated pump [%] (the port areas are openings, the circuit's one setting).
int run_paper(const IdentifyArgs& a, const circuit_tools::LoadedCircuit* circuit, Report& rep, nlohmann::json& js,
              double& worst) {
  const id::PaperTables t = id::read_paper_tables(a.paper);
  if (t.error) {
    fmt::print(stderr, "{}\n", t.error->to_string());
    return kExitBadInput;
  }
  rep("\nhstmon identify --paper {} — seed 001 §IV estimates{}\n", a.paper,
      circuit != nullptr ? " beside circuit " + circuit->file.name + "'s values" : "");
  nlohmann::json jpaper = nlohmann::json::object();
  if (!t.pump.empty()) {
    if (const int rc = report_pump_curve(a, t, circuit, rep, jpaper, worst); rc != kExitOk) return rc;
  }
  for (const char* kind : {"dcv", "prv"}) {
    if (const int rc = report_port_areas(a, kind, t, circuit, rep, jpaper); rc != kExitOk) return rc;
  }
  js["paper"] = jpaper;
  return kExitOk;
}

void run_studies(Report& rep, nlohmann::json& js) {
  const std::vector<double> K{3e10, 1e11, 3e11, 1e12};
  const std::vector<double> A{3.86e-6, 4.29e-6, 4.43e-6, 4.77e-6, 5e-6};
  // Long enough for the softest K to settle (the last sample is taken as the final value).
  const std::vector<id::ParameterStudy> studies{id::study_speed_vs_bulk_stiffness(K, 12.0, 5e-3),
                                                id::study_speed_vs_dcv_area(A),
                                                id::study_pump_pressure_vs_bulk_stiffness(K, 12.0, 2e-3)};
  rep("\nparameter studies of seed 001 (paper model, Table I, from rest):\n");
  nlohmann::json jst = nlohmann::json::array();
  for (const auto& s : studies) {
    rep("  {}\n  {:<24} {:>10} {:>10} {:>10} {:>12} {:>12}\n", s.title, "value", "final", "peak", "t_peak [s]",
        "t_90% [s]", "settle 2% [s]");
    sim::ReportTable tab{
        "Parameter study: " + s.title,
        {"value", "final [" + s.unit + "]", "peak [" + s.unit + "]", "t_peak [s]", "t_90% [s]", "settle 2% [s]"},
        {}};
    nlohmann::json jc = nlohmann::json::array();
    std::vector<id::PlotSeries> series;
    for (const auto& c : s.curves) {
      rep("  {:<24} {:>10.5g} {:>10.5g} {:>10.4g} {:>12.4g} {:>12.4g}   [{}]\n", c.label, c.final_value * s.scale,
          c.peak * s.scale, c.t_peak, c.rise_time, c.settling_time, s.unit);
      tab.rows.push_back({c.label, fmt::format("{:.5g}", c.final_value * s.scale),
                          fmt::format("{:.5g}", c.peak * s.scale), fmt::format("{:.4g}", c.t_peak),
                          fmt::format("{:.4g}", c.rise_time), fmt::format("{:.4g}", c.settling_time)});
      jc.push_back({{"label", c.label}, {"value", c.value}, {"final", c.final_value}, {"peak", c.peak},
                    {"t_peak", c.t_peak}, {"rise_time", c.rise_time}, {"settling_time", c.settling_time}});
      id::PlotSeries ps{c.label, c.t, {}, false};
      for (double y : c.y) ps.y.push_back(y * s.scale);
      series.push_back(std::move(ps));
    }
    rep.tables.push_back(std::move(tab));
    jst.push_back({{"name", s.name}, {"output", s.output}, {"curves", jc}});
    rep.plot(s.name, s.title, "t [s]",
             fmt::format("{} [{}]", s.output == "w_m" ? "motor speed" : "pump pressure", s.unit), series);
  }
  js["studies"] = jst;
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
