// The report of `gap --circuit` (cli_circuit_gap_report.hpp).
#include "cli_circuit_gap_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hstmon_host/circuit_units.hpp"

namespace hstmon::cli {

namespace {

// At most this many candidates in the figure (the table lists every one).
constexpr std::size_t kDrawn = 10;

// A candidate's magnitude as an engineer reads it: an offset in its sensor's engineering
// unit, a parameter's change in %, the others in SI with their unit.
std::string magnitude_text(const circuit_tools::LoadedCircuit& c, const gap::CircuitEffectResult& e) {
  if (!std::isfinite(e.magnitude)) return "not fitted";
  using Kind = gap::CircuitEffect::Kind;
  if (e.effect.kind == Kind::kOffset && e.effect.index >= 0 &&
      static_cast<std::size_t>(e.effect.index) < c.file.sensors.size()) {
    return host::engineering_text(c.file.sensors[static_cast<std::size_t>(e.effect.index)].quantity, e.magnitude);
  }
  if (e.effect.kind == Kind::kParam) return fmt::format("{:+.3g} %", 100.0 * e.magnitude);
  return fmt::format("{:.4g} {}", e.magnitude, gap::effect_unit(c, e.effect));
}

ReportTable where_table(const circuit_tools::LoadedCircuit& c, const gap::CircuitGapResult& r) {
  ReportTable t{"Where the gap lies (fit log)", {"channel", "mean measured − model [σ]", "σ fit log", "σ check log"}, {}};
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const auto q = c.file.sensors[ch].quantity;
    t.rows.push_back({r.channels[ch], std::isfinite(r.mean_fit[ch]) ? fmt::format("{:+.3g}", r.mean_fit[ch]) : "not logged",
                      ch < r.noise_fit.size() ? host::engineering_text(q, r.noise_fit[ch]) : "",
                      ch < r.noise_check.size() ? host::engineering_text(q, r.noise_check[ch]) : ""});
  }
  return t;
}

ReportTable candidate_table(const circuit_tools::LoadedCircuit& c, const gap::CircuitGapResult& r) {
  ReportTable t{"Candidate effects, best on the check log first",
                {"#", "candidate", "size (fit log)", "fit RMS [σ]", "check RMS [σ]", "check shrinks by",
                 "check beyond noise and uncertainty [σ]"},
                {}};
  for (std::size_t k = 0; k < r.ranked.size(); ++k) {
    const auto& e = r.ranked[k];
    t.rows.push_back({std::to_string(k + 1), e.effect.name, magnitude_text(c, e), fmt::format("{:.3g}", e.rms_fit),
                      fmt::format("{:.3g}", e.rms_check),
                      r.rms_check > 0.0 ? fmt::format("{:.0f} %", 100.0 * (1.0 - e.rms_check / r.rms_check)) : "",
                      fmt::format("{:.3g}", e.z_check)});
  }
  return t;
}

ReportPanel candidate_panel(const gap::CircuitGapResult& r) {
  ReportPanel p{"The check log's residual with each candidate (numbers as in the table)", "candidate",
                "check log RMS [σ]", {}, {}};
  ReportSeries with{"with the candidate's fitted size", {}, "points pt 7 ps 1.3"};
  ReportSeries without{"the model as it is", {}, "lines dt 2 lw 2"};
  for (std::size_t k = 0; k < r.ranked.size() && k < kDrawn; ++k) {
    p.x.push_back(static_cast<double>(k + 1));
    with.y.push_back(r.ranked[k].rms_check);
    without.y.push_back(r.rms_check);
  }
  p.series = {with, without};
  p.from_zero = true;
  return p;
}

sim::VerdictTone tone_of(const gap::CircuitGapResult& r) {
  if (r.verdict == "none") return sim::VerdictTone::kGood;
  if (r.verdict == "insufficient_data" || r.verdict == "unexplained") return sim::VerdictTone::kWarning;
  return sim::VerdictTone::kNeutral;
}

}  // namespace

CircuitReport circuit_gap_report(const CircuitGapArgs& a, const circuit_tools::LoadedCircuit& c,
                                 const gap::CircuitGapResult& r, const std::string& verdict, const std::string& text) {
  CircuitReport rep;
  rep.title = "hstmon gap --circuit report: " + c.file.name;
  rep.verdict = verdict;
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

}  // namespace hstmon::cli
