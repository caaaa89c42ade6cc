// The text and report of `gap --circuit` (circuit_gap_report.hpp).
#include "hstmon_gap/circuit_gap_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hstmon_host/circuit_units.hpp"

namespace hstmon::gap {

namespace {

// At most this many candidates in the figure (the table lists every one).
constexpr std::size_t kDrawn = 10;

// A candidate's magnitude as an engineer reads it: an offset in its sensor's display unit,
// a parameter's change in %, a leak in (L/min)/bar, friction and torque in SI.
std::string magnitude_text(const circuit_tools::LoadedCircuit& c, const CircuitEffectResult& e) {
  if (!std::isfinite(e.magnitude)) return "not fitted";
  using Kind = CircuitEffect::Kind;
  using Q = host::CircuitQuantity;
  switch (e.effect.kind) {
    case Kind::kOffset:
      if (e.effect.index >= 0 && static_cast<std::size_t>(e.effect.index) < c.file.sensors.size()) {
        const host::CircuitSensor& s = c.file.sensors[static_cast<std::size_t>(e.effect.index)];
        return host::display_unit(s.quantity, s.unit).text(e.magnitude, 3, true);
      }
      break;
    case Kind::kParam:
      return fmt::format("{:+.3g} %", 100.0 * e.magnitude);
    case Kind::kLeak:
      return host::display_unit(Q::kConductance).text(e.magnitude);
    case Kind::kFriction:
      return host::display_unit(Q::kDamping).text(e.magnitude);
    case Kind::kTorqueLoss:
      return host::display_unit(Q::kTorque).text(e.magnitude);
  }
  return fmt::format("{:.4g} {}", e.magnitude, effect_unit(c, e.effect));
}

// An RMS [σ] or its shrink, or why there is none: a candidate whose fitted size leaves the
// model without a steady state at some operating point has no residual there.
std::string rms_text(double rms) { return std::isfinite(rms) ? fmt::format("{:.3g}", rms) : "no steady state"; }
std::string shrink_text(double rms, double base) {
  if (!std::isfinite(rms)) return "—";
  const double pct = 100.0 * (1.0 - rms / base);
  return base > 0.0 ? fmt::format("{:.0f} %", std::fabs(pct) < 0.5 ? 0.0 : pct) : "";
}

sim::ReportTable where_table(const circuit_tools::LoadedCircuit& c, const CircuitGapResult& r) {
  sim::ReportTable t{"Where the gap lies (fit log)", {"channel", "mean measured − model [σ]", "σ fit log", "σ check log"}, {}};
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const auto q = c.file.sensors[ch].quantity;
    t.rows.push_back({r.channels[ch], std::isfinite(r.mean_fit[ch]) ? fmt::format("{:+.3g}", r.mean_fit[ch]) : "not logged",
                      ch < r.noise_fit.size() ? host::engineering_text(q, r.noise_fit[ch]) : "",
                      ch < r.noise_check.size() ? host::engineering_text(q, r.noise_check[ch]) : ""});
  }
  return t;
}

sim::ReportTable candidate_table(const circuit_tools::LoadedCircuit& c, const CircuitGapResult& r) {
  sim::ReportTable t{"Candidate effects, best on the check log first",
                {"#", "candidate", "size (fit log)", "fit RMS [σ]", "check RMS [σ]", "check shrinks by",
                 "check beyond noise and uncertainty [σ]"},
                {}};
  for (std::size_t k = 0; k < r.ranked.size(); ++k) {
    const auto& e = r.ranked[k];
    t.rows.push_back({std::to_string(k + 1), e.effect.name, magnitude_text(c, e), rms_text(e.rms_fit),
                      rms_text(e.rms_check), shrink_text(e.rms_check, r.rms_check), rms_text(e.z_check)});
  }
  return t;
}

sim::ReportPanel candidate_panel(const CircuitGapResult& r) {
  sim::ReportPanel p{"The check log's residual with each candidate (numbers as in the table)", "candidate",
                "check log RMS [σ]", {}, {}};
  sim::ReportSeries with{"with the candidate's fitted size", {}, "points pt 7 ps 1.3"};
  sim::ReportSeries without{"the model as it is", {}, "lines dt 2 lw 2"};
  for (std::size_t k = 0; k < r.ranked.size() && k < kDrawn; ++k) {
    p.x.push_back(static_cast<double>(k + 1));
    with.y.push_back(r.ranked[k].rms_check);
    without.y.push_back(r.rms_check);
  }
  p.series = {with, without};
  p.from_zero = true;
  return p;
}

// "where, by balance equation": per equation its mean on the fit log and RMS/noise on
// both logs, the located one marked; then the equations a log lacks signals for.
std::string equations_text(const CircuitGapResult& r) {
  if (r.equations_fit.empty()) return "";
  std::string t =
      "\n  where, by balance equation (the model's net inflow or torque at the measured signals − accumulation;\n"
      "  a loss the model lacks is > 0; RMS over the propagated noise):\n";
  t += fmt::format("  {:<22} {:>6} {:>12} {:>15} {:>17}\n", "equation", "unit", "mean fit", "RMS/noise fit",
                   "RMS/noise check");
  std::string unavailable;
  for (std::size_t e = 0; e < r.equations_fit.size(); ++e) {
    const EquationStats& f = r.equations_fit[e];
    const bool has_check = e < r.equations_check.size() && r.equations_check[e].available;
    if (!f.available && !has_check) {
      unavailable +=
          fmt::format("    {}: lacks {}\n", f.equation, e < r.equations_missing.size() ? r.equations_missing[e] : "");
      continue;
    }
    t += fmt::format("  {:<22} {:>6} {:>12} {:>15} {:>17}{}\n", f.equation, f.unit,
                     f.available ? fmt::format("{:.3g}", f.mean) : "—",
                     f.available ? fmt::format("{:.3g}", f.rms_w) : "—",
                     has_check ? fmt::format("{:.3g}", r.equations_check[e].rms_w) : "—",
                     f.equation == r.located_equation ? "  <- located" : "");
  }
  if (r.located_equation.empty()) t += "  located: none (no equation beyond 3x its noise)\n";
  if (!unavailable.empty()) t += "  not available (a signal it reads is not measured):\n" + unavailable;
  return t;
}

// "discovered terms": the located equation's missing term.
std::string discovery_text(const CircuitGapResult& r) {
  if (!r.discovery) return "";
  const CircuitDiscovery& d = *r.discovery;
  std::string t =
      fmt::format("\n  discovered terms ({}, STLSQ fitted on the fit log, judged on the check log):\n", d.equation);
  for (const auto& x : d.terms)
    t += fmt::format("    {:+.4g} * {}  (+- {:.2g} {})\n", x.coefficient, x.form, x.std_error, x.unit);
  t += fmt::format(
      "    {}\n    shrinks the imbalance above noise by {:.0f} % on the check log (RMS/noise {:.3g} -> {:.3g}), "
      "{:.0f} % on the fit log\n",
      d.reading, 100.0 * d.shrink_check, d.rms_w_before_check, d.rms_w_after_check, 100.0 * d.shrink_fit);
  return t;
}

sim::ReportTable equation_table(const CircuitGapResult& r) {
  sim::ReportTable t{"Where, by balance equation (imbalance: a loss the model lacks > 0)",
                     {"equation", "unit", "mean fit log", "RMS/noise fit log", "RMS/noise check log", ""},
                     {}};
  for (std::size_t e = 0; e < r.equations_fit.size(); ++e) {
    const EquationStats& f = r.equations_fit[e];
    const bool has_check = e < r.equations_check.size() && r.equations_check[e].available;
    const std::string missing = e < r.equations_missing.size() ? r.equations_missing[e] : "";
    t.rows.push_back({f.equation, f.unit, f.available ? fmt::format("{:.3g}", f.mean) : "—",
                      f.available ? fmt::format("{:.3g}", f.rms_w) : "—",
                      has_check ? fmt::format("{:.3g}", r.equations_check[e].rms_w) : "—",
                      f.equation == r.located_equation ? "located" : (missing.empty() ? "" : "lacks " + missing)});
  }
  return t;
}

sim::ReportTable discovery_table(const CircuitDiscovery& d) {
  sim::ReportTable t{"Discovered terms in " + d.equation + " (check log shrinks by " +
                         fmt::format("{:.0f} %", 100.0 * d.shrink_check) + "): " + d.reading,
                     {"term", "coefficient", "std error", "unit"},
                     {}};
  for (const auto& x : d.terms) {
    t.rows.push_back({x.form, fmt::format("{:+.4g}", x.coefficient), fmt::format("{:.2g}", x.std_error), x.unit});
  }
  return t;
}

sim::VerdictTone tone_of(const CircuitGapResult& r) {
  if (r.verdict == "none") return sim::VerdictTone::kGood;
  if (r.verdict == "insufficient_data" || r.verdict == "unexplained") return sim::VerdictTone::kWarning;
  return sim::VerdictTone::kNeutral;
}

}  // namespace

std::string circuit_gap_verdict(const CircuitGapResult& r) {
  if (r.verdict == "none") {
    return "no gap: the model meets both logs' operating points within 2 sigma of noise and parameter uncertainty";
  }
  if (r.verdict == "insufficient_data") return "insufficient data: " + r.evidence_missing;
  if (r.verdict == "unexplained") return "no single candidate explains the gap (none halves the check log's residual)";
  if (r.verdict.rfind("parameter(", 0) == 0) {
    return r.verdict + ": a parameter off beyond its stated uncertainty; hstmon identify --circuit fits it";
  }
  return r.verdict;
}

std::string circuit_gap_text(const CircuitGapRun& a, const circuit_tools::LoadedCircuit& c, const CircuitGapResult& r) {
  std::string t = fmt::format("hstmon gap --circuit {}: fit {} ({} operating points), check {} ({})\n", a.circuit, a.fit,
                              r.fit_points, a.check, r.check_points);
  t += fmt::format("\n  verdict: {}\n", circuit_gap_verdict(r));
  for (const auto& n : r.notes) t += fmt::format("  note: {}\n", n);
  if (r.verdict == "insufficient_data") return t + equations_text(r) + discovery_text(r);
  t += fmt::format("\n  beyond noise and parameter uncertainty: fit {:.3g}, check {:.3g} [σ] (no gap at 2 or less)\n",
                   r.z_fit, r.z_check);
  t += "\n  where the gap lies (mean of measured − model over the fit log's points, in sensor σ):\n   ";
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) t += fmt::format(" {} {:+.3g}", r.channels[ch], r.mean_fit[ch]);
  t += fmt::format("\n\n  residual RMS without an effect: fit {:.3g}, check {:.3g} [σ]\n", r.rms_fit, r.rms_check);
  t += fmt::format("\n  {:<26} {:>22} {:>16} {:>16} {:>8}\n", "candidate", "size", "fit RMS [σ]", "check RMS [σ]",
                   "shrink");
  for (const auto& e : r.ranked) {
    t += fmt::format("  {:<26} {:>22} {:>16} {:>16} {:>8}\n", e.effect.name, magnitude_text(c, e), rms_text(e.rms_fit),
                     rms_text(e.rms_check), shrink_text(e.rms_check, r.rms_check));
  }
  return t + equations_text(r) + discovery_text(r);
}

sim::CircuitReport circuit_gap_report(const CircuitGapRun& a, const circuit_tools::LoadedCircuit& c,
                                      const CircuitGapResult& r, const std::string& text) {
  sim::CircuitReport rep;
  rep.title = "hstmon gap --circuit report: " + c.file.name;
  rep.verdict = circuit_gap_verdict(r);
  rep.tone = tone_of(r);
  rep.notes = r.notes;
  rep.text = text;
  rep.tables.push_back({"Logs",
                        {"log", "file", "steady operating points", "residual RMS without an effect [σ]",
                         "beyond noise and uncertainty [σ]"},
                        {{"fit", a.fit, std::to_string(r.fit_points), fmt::format("{:.3g}", r.rms_fit),
                          fmt::format("{:.3g}", r.z_fit)},
                         {"check", a.check, std::to_string(r.check_points), fmt::format("{:.3g}", r.rms_check),
                          fmt::format("{:.3g}", r.z_check)}}});
  if (r.verdict != "insufficient_data") {  // else nothing was fitted
    rep.tables.push_back(where_table(c, r));
    rep.tables.push_back(candidate_table(c, r));
  }
  if (!r.equations_fit.empty()) rep.tables.push_back(equation_table(r));
  if (r.discovery) rep.tables.push_back(discovery_table(*r.discovery));
  if (r.verdict == "insufficient_data") return rep;
  if (!r.ranked.empty()) {
    rep.panels.push_back(candidate_panel(r));
    rep.figure_caption = "How far each candidate shrinks the withheld log's residual";
  }
  return rep;
}

}  // namespace hstmon::gap
