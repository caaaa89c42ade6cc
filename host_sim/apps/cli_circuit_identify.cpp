// `hstmon identify`: prints the operating points found, the fitted parameters with their
// standard errors, those held, and the residuals before and after, in σ of each sensor.
#include "cli_circuit_identify.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_commands.hpp"
#include "cli_events.hpp"
#include "hstmon_circuit/circuit_header.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "hstmon_ident/circuit_identify_report.hpp"

namespace hstmon::cli {

namespace {

// The fit as the JSON object's fields (parameters, points with their window inputs, RMS).
nlohmann::json fit_json(const circuit_tools::LoadedCircuit& c, const ident::CircuitFitResult& r) {
  nlohmann::json params = nlohmann::json::array();
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    params.push_back({{"name", r.names[j]},
                      {"start", r.start[j]},
                      {"value", r.value[j]},
                      {"rel_se", number_or_null(r.rel_se[j])},
                      {"moved", static_cast<bool>(r.moved[j])},
                      {"uncertainty", r.uncertainty[j]},
                      {"prior_uncertainty", r.prior_uncertainty[j]},
                      {"pinned", static_cast<bool>(r.pinned[j])}});
  }
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : r.points) {
    nlohmann::json before = nlohmann::json::array(), after = nlohmann::json::array();
    for (double v : p.before) before.push_back(number_or_null(v));
    for (double v : p.after) after.push_back(number_or_null(v));
    nlohmann::json jp = {{"log", p.log}, {"t0", p.t0},       {"t1", p.t1},
                         {"rows", p.n},  {"before", before}, {"after", after}};
    if (!r.window_inputs.empty()) {
      nlohmann::json w = nlohmann::json::object();
      for (std::size_t k = 0; k < r.window_inputs.size() && k < p.window_value.size(); ++k) {
        w[r.window_inputs[k]] = {{"start", number_or_null(p.window_start[k])},
                                 {"value", number_or_null(p.window_value[k])},
                                 {"se", number_or_null(p.window_se[k])}};
      }
      jp["window_inputs"] = w;
    }
    points.push_back(jp);
  }
  nlohmann::json held = nlohmann::json::array();
  for (const auto& h : r.held) held.push_back({{"name", h.name}, {"value", h.value}, {"why", h.why}});
  nlohmann::json correlation = nlohmann::json::array();
  for (const auto& row : r.correlation) {
    nlohmann::json jr = nlohmann::json::array();
    for (double v : row) jr.push_back(number_or_null(v));
    correlation.push_back(jr);
  }
  nlohmann::json agreement = nlohmann::json::array();
  for (const auto& g : ident::channel_agreement(c, r)) {
    agreement.push_back({{"channel", g.channel}, {"points", g.points}, {"mean", g.mean}, {"rms", g.rms}});
  }
  nlohmann::json j = {
      {"parameters", params},   {"held", held},     {"default_fit", r.default_fit}, {"correlation", correlation},
      {"agreement", agreement}, {"points", points}, {"rms_before", r.rms_before},   {"rms_after", r.rms_after},
      {"status", r.status},     {"notes", r.notes}};
  if (!r.window_inputs.empty()) j["window_inputs"] = r.window_inputs;
  return j;
}

// One JSON object: the fit's fields (when there were logs) and the sections' keys.
void print_json(const circuit_tools::LoadedCircuit& c, const ident::CircuitFitResult* r, const IdentifySections& s) {
  nlohmann::json j = {{"type", "identify"}, {"circuit", c.file.name}};
  if (r != nullptr) j.update(fit_json(c, *r));
  j.update(s.json);
  fmt::print("{}\n", j.dump());
}

// The window inputs fitted per operating point, as text and as a report table.
std::string window_inputs_text(const circuit_tools::LoadedCircuit& c, const ident::CircuitFitResult& r,
                               sim::ReportTable& t) {
  if (r.window_inputs.empty()) return {};
  t = {"Window inputs fitted per operating point (setting per window)", {"#", "t [s]"}, {}};
  std::string s = "\n  window inputs fitted per operating point (start → fitted ± standard error):\n";
  std::vector<host::DisplayUnit> unit;
  for (const auto& name : r.window_inputs) {
    const int i = c.file.input_index(name);
    unit.push_back(host::display_unit(c.file.inputs[static_cast<std::size_t>(i)].quantity));
    t.header.push_back(name + " [" + unit.back().unit + "]");
  }
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const auto& p = r.points[k];
    std::vector<std::string> row{std::to_string(k + 1), fmt::format("{:.3f} … {:.3f}", p.t0, p.t1)};
    s += fmt::format("  {:>3}  t = {:>8.3f} … {:<8.3f} s", k + 1, p.t0, p.t1);
    for (std::size_t q = 0; q < r.window_inputs.size() && q < p.window_value.size(); ++q) {
      const host::DisplayUnit& d = unit[q];
      const std::string cell = fmt::format("{:.5g} → {:.5g} ± {:.2g}", d.of(p.window_start[q]), d.of(p.window_value[q]),
                                           std::fabs(d.of(p.window_se[q])));
      s += fmt::format("   {} {} {}", r.window_inputs[q], cell, d.unit);
      row.push_back(cell);
    }
    s += "\n";
    t.rows.push_back(std::move(row));
  }
  return s;
}

// --noise-pressure / --noise-speed: c with the weights' σ for every sensor of that quantity
// (the fit weighs with it; the header keeps the circuit file's sensors).
circuit_tools::LoadedCircuit with_noise(const CircuitIdentifyArgs& a, const circuit_tools::LoadedCircuit& c) {
  circuit_tools::LoadedCircuit out = c;
  for (host::CircuitSensor& s : out.file.sensors) {
    if (s.quantity == host::CircuitQuantity::kPressure && a.noise_pressure > 0.0) s.noise = a.noise_pressure;
    if (s.quantity == host::CircuitQuantity::kSpeed && a.noise_speed > 0.0) s.noise = a.noise_speed;
  }
  return out;
}

// The header's namespace: its file stem as a C++ identifier ("my-stand.hpp" → my_stand).
std::string header_namespace(const std::string& path) {
  std::string n = std::filesystem::path(path).stem().string();
  for (char& ch : n) {
    if (std::isalnum(static_cast<unsigned char>(ch)) == 0) ch = '_';
  }
  if (n.empty() || std::isdigit(static_cast<unsigned char>(n.front())) != 0) n = "circuit_" + n;
  return n;
}

// --header: the circuit at the fitted values (and their uncertainty), as
// hstmon-circuit-header writes it.
std::string write_header(const CircuitIdentifyArgs& a, const circuit_tools::LoadedCircuit& c,
                         const ident::CircuitFitResult& r) {
  circuit_tools::CircuitHeaderOptions o;
  o.name = header_namespace(a.header);
  std::string fitted_names;
  for (const auto& n : r.names) fitted_names += (fitted_names.empty() ? "" : ",") + n;
  o.source_note = "hstmon identify, " + c.file.path + ", --fit " + fitted_names + " (" +
                  std::to_string(r.points.size()) + " operating points)";
  std::string error;
  const std::string text = circuit_tools::circuit_header(ident::fitted_circuit(c, r), o, error);
  if (text.empty()) return error;
  std::ofstream f(a.header);
  f << text;
  return f ? std::string() : "cannot write " + a.header;
}

}  // namespace

namespace {

// Usage errors of the option combination; kExitOk when it is runnable.
int check_usage(const CircuitIdentifyArgs& a) {
  const char* why = nullptr;
  if (a.logs.empty() && !a.sections) {
    why = "give LOG files (and --fit PARAM[,PARAM...]), or --paper FILE.csv / --studies";
  } else if (a.logs.empty() && (!a.fit.empty() || !a.out.empty() || !a.header.empty() || a.setting_per_window)) {
    why = "--fit, --out, --header and --setting-per-window are about the fit to LOG files: give them";
  }
  if (why == nullptr) return kExitOk;
  fmt::print(stderr, "hstmon identify: error: {}\n", why);
  return kExitUsage;
}

// Reads the logs and fits; kExitOk, or the exit code after the message.
int fit_logs(const CircuitIdentifyArgs& a, const circuit_tools::LoadedCircuit& c, ident::CircuitFitResult& r) {
  std::vector<circuit_tools::CircuitLog> logs;
  for (const std::string& path : a.logs) {
    circuit_tools::CircuitLog log = circuit_tools::read_circuit_log(path, c.file, a.read);
    for (const auto& n : log.notes) fmt::print(stderr, "{}\n", n);
    if (log.error) {
      fmt::print(stderr, "{}\n", log.error->to_string());
      return kExitBadInput;
    }
    logs.push_back(std::move(log));
  }
  ident::CircuitFitOptions o;
  o.fit = a.fit;
  o.min_duration = a.min_duration;
  o.min_samples = a.min_samples;
  o.assume_steady = a.assume_steady;
  o.min_settings = a.min_settings;
  o.setting_per_window = a.setting_per_window;
  o.window_inputs = a.window_inputs;
  r = ident::fit_circuit(with_noise(a, c), logs, o);
  if (r.error) {
    // One log named: the fit is over all of them, and a list of many would fill the screen.
    const std::string files = a.logs.size() == 1 ? a.logs[0]
                                                 : fmt::format("{} (and {} more logs)", a.logs[0], a.logs.size() - 1);
    fmt::print(stderr, "{}: error: {}\n", files, *r.error);
    return kExitBadInput;
  }
  if (!a.out.empty()) {
    std::ofstream f(a.out);
    f << ident::fitted_values_json(c, r);
    if (!f) {
      fmt::print(stderr, "hstmon identify: cannot write {}\n", a.out);
      return kExitBadInput;
    }
  }
  if (!a.header.empty()) {
    if (const std::string err = write_header(a, c, r); !err.empty()) {
      fmt::print(stderr, "hstmon identify: error: --header {}: {}\n", a.header, err);
      return kExitBadInput;
    }
  }
  return kExitOk;
}

// The report: the fit's (when there were logs) with the window inputs and the sections
// after it, one figure for all panels.
sim::CircuitReport make_report(const ident::CircuitIdentifyRun& run, const circuit_tools::LoadedCircuit& c,
                               const ident::CircuitFitResult* r, const sim::ReportTable& windows,
                               const IdentifySections& s, const std::string& text) {
  sim::CircuitReport rep;
  if (r != nullptr) {
    rep = ident::circuit_identify_report(run, c, *r, text);
    if (!windows.rows.empty()) rep.tables.insert(rep.tables.begin() + 1, windows);
  } else {
    rep.title = "hstmon identify report: " + c.file.name;
    rep.tone = sim::VerdictTone::kNeutral;
    rep.text = text;
  }
  if (!s.verdict.empty()) rep.verdict += (rep.verdict.empty() ? "" : "; ") + s.verdict;
  rep.tables.insert(rep.tables.end(), s.tables.begin(), s.tables.end());
  if (!s.panels.empty()) {
    rep.figure_caption += std::string(rep.panels.empty() ? "" : "; then ") +
                          "the paper table's fits and the parameter studies";
    rep.panels.insert(rep.panels.end(), s.panels.begin(), s.panels.end());
  }
  return rep;
}

}  // namespace

int run_circuit_identify(const CircuitIdentifyArgs& a) {
  if (const int rc = check_usage(a); rc != kExitOk) return rc;
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    fmt::print(stderr, "{}\n", err->to_string());
    return kExitBadInput;
  }
  // The sections first: a bad table stops the command before any file is written.
  IdentifySections sections;
  if (a.sections) {
    if (const int rc = a.sections(c, !a.report.empty(), sections); rc != kExitOk) return rc;
  }
  ident::CircuitFitResult fit;
  const bool fitted = !a.logs.empty();
  if (fitted) {
    if (const int rc = fit_logs(a, c, fit); rc != kExitOk) return rc;
  }
  const ident::CircuitIdentifyRun run{a.circuit, a.logs, a.out, a.header};
  sim::ReportTable windows;
  const std::string text =
      (fitted ? ident::circuit_identify_text(run, c, fit) + window_inputs_text(c, fit, windows)
              : std::string("hstmon identify: no LOG files, no fit: the paper rig's analyses only\n")) +
      sections.text;
  const ident::CircuitFitResult* r = fitted ? &fit : nullptr;
  return finish_circuit_command(
      "identify", a, text, [&] { print_json(c, r, sections); },
      [&] { return make_report(run, c, r, windows, sections, text); });
}

}  // namespace hstmon::cli
