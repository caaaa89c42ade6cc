// `hstmon identify --paper TABLE [--studies]`: the paper rig's table analysis (pump curve,
// DCV/PRV port areas from √ΔP–Q lines) and parameter studies (Table I), with --circuit
// beside the circuit's compensated pump and orifices (cli_identify_paper.hpp).
#include "cli_identify_paper.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "cli_commands.hpp"
#include "hstmon_ident/paper_circuit.hpp"
#include "hstmon_ident/paper_studies.hpp"
#include "hstmon_ident/paper_tables.hpp"
#include "hstmon_ident/port_area.hpp"
#include "hstmon_ident/pump_curve_fit.hpp"

namespace hstmon::cli::identify {

namespace {

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
    rep.plot("Pump B flow vs pressure (Fig. 3/4)", "P [bar]", "Q [l/min]", {data, model});
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
  rep.plot(fmt::format("{}: flow vs sqrt(2|dP|/rho) (Fig. {})", name, kind == "dcv" ? 5 : 6), "sqrt(2|dP|/rho) [m/s]",
           "Q [l/min]", series);
  return kExitOk;
}

}  // namespace

// `worst` covers the pump curve only: the port areas are openings, the circuit has one setting.
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
      jc.push_back({{"label", c.label},
                    {"value", c.value},
                    {"final", c.final_value},
                    {"peak", c.peak},
                    {"t_peak", c.t_peak},
                    {"rise_time", c.rise_time},
                    {"settling_time", c.settling_time}});
      id::PlotSeries ps{c.label, c.t, {}, false};
      for (double y : c.y) ps.y.push_back(y * s.scale);
      series.push_back(std::move(ps));
    }
    rep.tables.push_back(std::move(tab));
    jst.push_back({{"name", s.name}, {"output", s.output}, {"curves", jc}});
    rep.plot(s.title, "t [s]", fmt::format("{} [{}]", s.output == "w_m" ? "motor speed" : "pump pressure", s.unit),
             series);
  }
  js["studies"] = jst;
}

}  // namespace hstmon::cli::identify
