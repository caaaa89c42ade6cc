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
  if (r.verdict == "insufficient_data") return t;
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
  return t;
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
  if (r.verdict == "insufficient_data") return rep;  // nothing was fitted
  rep.tables.push_back(where_table(c, r));
  rep.tables.push_back(candidate_table(c, r));
  if (!r.ranked.empty()) {
    rep.panels.push_back(candidate_panel(r));
    rep.figure_caption = "How far each candidate shrinks the withheld log's residual";
  }
  return rep;
}

}  // namespace hstmon::gap
