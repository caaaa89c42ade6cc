// `hstmon gap --circuit`: prints where the gap lies (mean residual per channel), every
// candidate effect's fitted magnitude with its fit and check residual, and the verdict.
#include "cli_circuit_gap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_commands.hpp"
#include "cli_events.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_gap/circuit_gap.hpp"
#include "hstmon_gap/circuit_gap_report.hpp"

namespace hstmon::cli {

namespace {

// "equations": per balance equation its availability and statistics (SI), the located one,
// and the discovered terms (null when none).
void put_equations(const gap::CircuitGapResult& r, nlohmann::json& j) {
  nlohmann::json eqs = nlohmann::json::array();
  for (std::size_t e = 0; e < r.equations_fit.size(); ++e) {
    const gap::EquationStats& f = r.equations_fit[e];
    const bool check = e < r.equations_check.size() && r.equations_check[e].available;
    eqs.push_back({{"equation", f.equation},
                   {"unit", f.unit},
                   {"available", f.available && check},
                   {"missing", e < r.equations_missing.size() ? r.equations_missing[e] : ""},
                   {"mean_fit", f.available ? number_or_null(f.mean) : nlohmann::json(nullptr)},
                   {"rms_w_fit", f.available ? number_or_null(f.rms_w) : nlohmann::json(nullptr)},
                   {"rms_w_check", check ? number_or_null(r.equations_check[e].rms_w) : nlohmann::json(nullptr)}});
  }
  j["equations"] = eqs;
  j["located_equation"] = r.located_equation.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.located_equation);
  if (!r.discovery) {
    j["discovery"] = nullptr;
    return;
  }
  const gap::CircuitDiscovery& d = *r.discovery;
  nlohmann::json terms = nlohmann::json::array();
  for (const auto& t : d.terms) {
    terms.push_back({{"form", t.form},
                     {"unit", t.unit},
                     {"coefficient", number_or_null(t.coefficient)},
                     {"std_error", number_or_null(t.std_error)}});
  }
  j["discovery"] = {{"equation", d.equation},
                    {"terms", terms},
                    {"shrink_fit", number_or_null(d.shrink_fit)},
                    {"shrink_check", number_or_null(d.shrink_check)},
                    {"reading", d.reading}};
}

void print_json(const circuit_tools::LoadedCircuit& c, const gap::CircuitGapResult& r) {
  nlohmann::json noise = nlohmann::json::object();
  for (std::size_t ch = 0; ch < r.noise_fit.size() && ch < c.file.sensors.size(); ++ch) {
    noise[c.file.sensors[ch].name] = {{"fit", r.noise_fit[ch]}, {"check", r.noise_check[ch]}};
  }
  nlohmann::json where = nlohmann::json::object();
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) where[r.channels[ch]] = number_or_null(r.mean_fit[ch]);
  nlohmann::json ranked = nlohmann::json::array();
  for (const auto& e : r.ranked) {
    ranked.push_back({{"effect", e.effect.name}, {"magnitude", number_or_null(e.magnitude)}, {"unit", gap::effect_unit(c, e.effect)},
                      {"rms_fit", number_or_null(e.rms_fit)}, {"rms_check", number_or_null(e.rms_check)},
                      {"z_check", number_or_null(e.z_check)}});
  }
  nlohmann::json j = {{"type", "gap"},
                      {"circuit", c.file.name},
                      {"fit_points", r.fit_points},
                      {"check_points", r.check_points},
                      {"rms_fit", r.rms_fit},
                      {"rms_check", number_or_null(r.rms_check)},
                      {"mean_residual_fit", where},
                      {"ranked", ranked},
                      {"verdict", r.verdict},
                      {"z_fit", number_or_null(r.z_fit)},
                      {"z_check", number_or_null(r.z_check)},
                      {"noise", noise},
                      {"evidence_missing", r.evidence_missing},
                      {"notes", r.notes}};
  put_equations(r, j);
  fmt::print("{}\n", j.dump());
}

}  // namespace

int run_circuit_gap(const CircuitGapArgs& a) {
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    fmt::print(stderr, "{}\n", err->to_string());
    return kExitBadInput;
  }
  gap::CircuitGapOptions o;
  o.effects = a.effects;
  o.refit_nominal = a.refit_nominal;
  std::string effects_error;
  (void)gap::chosen_effects(c, o.effects, effects_error);
  if (!effects_error.empty()) {  // a usage error: said before the logs are read
    fmt::print(stderr, "hstmon gap: error: {}\n", effects_error);
    return kExitUsage;
  }
  circuit_tools::CircuitLog logs[2];
  const std::string* paths[2] = {&a.fit, &a.check};
  for (int i = 0; i < 2; ++i) {
    logs[i] = circuit_tools::read_circuit_log(*paths[i], c.file, a.read);
    for (const auto& n : logs[i].notes) fmt::print(stderr, "{}\n", n);
    if (logs[i].error) {
      fmt::print(stderr, "{}\n", logs[i].error->to_string());
      return kExitBadInput;
    }
  }
  const gap::CircuitGapResult r = gap::circuit_gap(c, logs[0], logs[1], o);
  if (r.error) {
    fmt::print(stderr, "hstmon gap --circuit {}: {}\n", a.circuit, *r.error);
    return kExitBadInput;
  }
  const gap::CircuitGapRun run{a.circuit, a.fit, a.check};
  const std::string text = gap::circuit_gap_text(run, c, r);
  return finish_circuit_command(
      "gap", a, text, [&] { print_json(c, r); }, [&] { return gap::circuit_gap_report(run, c, r, text); });
}

}  // namespace hstmon::cli
