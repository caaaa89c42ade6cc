// `hstmon identify --circuit`: prints the operating points found, the fitted parameters
// with their standard errors and the residuals before and after, in σ of each sensor.
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

void print_json(const circuit_tools::LoadedCircuit& c, const ident::CircuitFitResult& r) {
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
    points.push_back({{"log", p.log}, {"t0", p.t0}, {"t1", p.t1}, {"rows", p.n}, {"before", before}, {"after", after}});
  }
  const nlohmann::json j = {{"type", "identify"},   {"circuit", c.file.name},  {"parameters", params},
                            {"points", points},     {"rms_before", r.rms_before}, {"rms_after", r.rms_after},
                            {"status", r.status},   {"notes", r.notes}};
  fmt::print("{}\n", j.dump());
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
  o.source_note = "hstmon identify --circuit " + a.circuit + " --fit " + fitted_names + " (" +
                  std::to_string(r.points.size()) + " operating points)";
  std::string error;
  const std::string text = circuit_tools::circuit_header(ident::fitted_circuit(c, r), o, error);
  if (text.empty()) return error;
  std::ofstream f(a.header);
  f << text;
  return f ? std::string() : "cannot write " + a.header;
}

}  // namespace

int run_circuit_identify(const CircuitIdentifyArgs& a) {
  if (a.logs.empty() || a.fit.empty()) {
    fmt::print(stderr, "hstmon identify --circuit: give LOG files and --fit PARAM[,PARAM...]\n");
    return kExitUsage;
  }
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    fmt::print(stderr, "{}\n", err->to_string());
    return kExitBadInput;
  }
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
  const ident::CircuitFitResult r = ident::fit_circuit(with_noise(a, c), logs, o);
  if (r.error) {
    fmt::print(stderr, "hstmon identify --circuit {}: {}\n", a.circuit, *r.error);
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
  const ident::CircuitIdentifyRun run{a.circuit, a.logs, a.out, a.header};
  const std::string text = ident::circuit_identify_text(run, c, r);
  return finish_circuit_command(
      "identify", a, text, [&] { print_json(c, r); }, [&] { return ident::circuit_identify_report(run, c, r, text); });
}

}  // namespace hstmon::cli
