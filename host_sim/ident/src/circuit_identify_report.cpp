// The text and report of `identify --circuit` (circuit_identify_report.hpp).
#include "hstmon_ident/circuit_identify_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "hstmon_circuit/circuit_faults.hpp"  // sensor_sigma
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::ident {

namespace {

sim::ReportTable parameter_table(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  sim::ReportTable t{"Fitted parameters",
                {"parameter", "start", "fitted", "change", "std. error", "monitor's bound", "the data show a change"},
                {}};
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const auto q = c.file.params[static_cast<std::size_t>(c.file.param_index(r.names[j]))].quantity;
    t.rows.push_back({r.names[j], host::engineering_text(q, r.start[j], 4), host::engineering_text(q, r.value[j], 4),
                      fmt::format("{:+.2f} %", 100.0 * (r.value[j] / r.start[j] - 1.0)),
                      std::isfinite(r.rel_se[j]) ? fmt::format("{:.2g} %", 100.0 * r.rel_se[j]) : "not determined",
                      r.pinned[j] ? fmt::format("±{:.2g} % (was ±{:.2g} %)", 100.0 * r.uncertainty[j],
                                                100.0 * r.prior_uncertainty[j])
                                  : fmt::format("±{:.2g} % (kept)", 100.0 * r.uncertainty[j]),
                      r.moved[j] ? "yes" : "no: the start lies within the 95 % interval"});
  }
  return t;
}

sim::ReportTable held_table(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  sim::ReportTable t{
      "Held at their start values (the points cannot determine them)", {"parameter", "value", "why"}, {}};
  for (const auto& h : r.held) {
    const auto q = c.file.params[static_cast<std::size_t>(c.file.param_index(h.name))].quantity;
    t.rows.push_back({h.name, host::engineering_text(q, h.value, 4), h.why});
  }
  return t;
}

sim::ReportTable agreement_table(const std::vector<ChannelAgreement>& a) {
  sim::ReportTable t{"Agreement at the operating points after the fit (Table 2.3 form, (measured − model)/measured)",
                     {"channel", "points", "average error", "RMS error"},
                     {}};
  for (const auto& g : a) {
    t.rows.push_back({g.channel, std::to_string(g.points), fmt::format("{:+.3f} %", 100.0 * g.mean),
                      fmt::format("{:.3f} %", 100.0 * g.rms)});
  }
  return t;
}

std::string correlation_text(const CircuitFitResult& r) {
  if (r.names.size() < 2 || r.correlation.size() != r.names.size()) return {};
  std::string t = "\n  correlation of the estimates (ln p):\n  " + std::string(12, ' ');
  for (const auto& n : r.names) t += fmt::format(" {:>9.9}", n);
  t += "\n";
  for (std::size_t i = 0; i < r.names.size(); ++i) {
    t += fmt::format("  {:<12}", r.names[i]);
    for (double v : r.correlation[i]) t += std::isfinite(v) ? fmt::format(" {:>9.3f}", v) : fmt::format(" {:>9}", "—");
    t += "\n";
  }
  return t;
}

std::string inputs_text(const circuit_tools::LoadedCircuit& c, const CircuitOperatingPoint& p) {
  std::string s;
  for (std::size_t i = 0; i < p.inputs.size() && i < c.file.inputs.size(); ++i) {
    s += (s.empty() ? "" : ", ") + c.file.inputs[i].name + " " +
         host::engineering_text(c.file.inputs[i].quantity, p.inputs[i], 4);
  }
  return s;
}

sim::ReportTable point_table(const CircuitIdentifyRun& a, const circuit_tools::LoadedCircuit& c,
                        const CircuitFitResult& r) {
  sim::ReportTable t{"Operating points (measured − model, in each sensor's σ: start values → fitted)",
                {"#", "log", "t [s]", "rows", "inputs"},
                {}};
  for (const auto& s : c.file.sensors) t.header.push_back(s.name);
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const auto& p = r.points[k];
    const std::string log = p.log < a.logs.size() ? std::filesystem::path(a.logs[p.log]).filename().string() : "?";
    std::vector<std::string> row = {std::to_string(k + 1), log,
                                    fmt::format("{:.3f} … {:.3f}", p.t0, p.t1), std::to_string(p.n),
                                    inputs_text(c, p)};
    for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
      const bool has = ch < p.before.size() && std::isfinite(p.before[ch]);
      row.push_back(has ? fmt::format("{:+.3g} → {:+.3g}", p.before[ch],
                                      ch < p.after.size() ? p.after[ch] : static_cast<double>(NAN))
                        : "not logged");
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::vector<sim::ReportPanel> point_panels(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  std::vector<sim::ReportPanel> panels;
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    sim::ReportPanel p{c.file.sensors[ch].name, "operating point", "measured − model [σ]", {}, {}};
    sim::ReportSeries before{"start values", {}, "points pt 6 ps 1.3"}, after{"fitted", {}, "points pt 7 ps 1.1"};
    bool any = false;
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      const auto& pt = r.points[k];
      p.x.push_back(static_cast<double>(k + 1));
      before.y.push_back(ch < pt.before.size() ? pt.before[ch] : static_cast<double>(NAN));
      after.y.push_back(ch < pt.after.size() ? pt.after[ch] : static_cast<double>(NAN));
      any = any || std::isfinite(before.y.back());
    }
    if (!any) continue;  // a channel the logs do not have: nothing to draw
    p.series = {before, after};
    panels.push_back(std::move(p));
  }
  return panels;
}

}  // namespace

std::vector<ChannelAgreement> channel_agreement(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r) {
  std::vector<ChannelAgreement> out;
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    ChannelAgreement g{c.file.sensors[ch].name, 0, 0.0, 0.0};
    const double sigma = circuit_tools::sensor_sigma(c.file.sensors[ch]);
    for (const auto& p : r.points) {
      if (ch >= p.after.size() || !std::isfinite(p.after[ch]) || !(std::fabs(p.mean[ch]) > 0.0)) continue;
      const double e = p.after[ch] * sigma / p.mean[ch];
      g.mean += e;
      g.rms += e * e;
      ++g.points;
    }
    if (g.points == 0) continue;
    g.mean /= static_cast<double>(g.points);
    g.rms = std::sqrt(g.rms / static_cast<double>(g.points));
    out.push_back(g);
  }
  return out;
}

std::string circuit_identify_text(const CircuitIdentifyRun& a, const circuit_tools::LoadedCircuit& c,
                                  const CircuitFitResult& r) {
  std::string t = fmt::format("hstmon identify, {}: {} log(s), {} operating point(s)\n", c.file.path, a.logs.size(),
                              r.points.size());
  if (r.default_fit) t += "  fitted: the circuit's losses and openings (--fit names others)\n";
  for (const auto& n : r.notes) t += fmt::format("  note: {}\n", n);
  t += fmt::format("\n  {:<12} {:>14} {:>14} {:>10} {:>12} {:>18}\n", "parameter", "start", "fitted", "change",
                   "std. error", "monitor's bound");
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    const int k = c.file.param_index(r.names[j]);
    // Start and fitted value as the report's table shows them (engineering units).
    const host::DisplayUnit d = host::display_unit(c.file.params[static_cast<std::size_t>(k)].quantity);
    const std::string bound = fmt::format("±{:.2g}% {}", 100.0 * r.uncertainty[j], r.pinned[j] ? "(was " : "(kept");
    const std::string se = std::isfinite(r.rel_se[j]) ? fmt::format("{:.2f}%", 100.0 * r.rel_se[j]) : "not determined";
    t += fmt::format("  {:<12} {:>14.6g} {:>14.6g} {:>+9.2f}% {:>12}   {}{}   [{}]\n", r.names[j], d.of(r.start[j]),
                     d.of(r.value[j]), 100.0 * (r.value[j] / r.start[j] - 1.0), se, bound,
                     r.pinned[j] ? fmt::format("±{:.2g}%)", 100.0 * r.prior_uncertainty[j]) : std::string(")"), d.unit);
  }
  for (const auto& h : r.held) {
    const int k = c.file.param_index(h.name);
    const host::DisplayUnit d = host::display_unit(c.file.params[static_cast<std::size_t>(k)].quantity);
    t += fmt::format("  {:<12} {:>14.6g} {:>14}   held at its start value: {}   [{}]\n", h.name, d.of(h.value), "—",
                     h.why, d.unit);
  }
  t += correlation_text(r);
  t += fmt::format("\n  residual RMS (mean reading − model, in sensor σ): {:.3g} before, {:.3g} after ({})\n",
                   r.rms_before, r.rms_after, r.status);
  const std::vector<ChannelAgreement> agreement = channel_agreement(c, r);
  if (!agreement.empty()) {
    t += "\n  agreement at the operating points after the fit (Table 2.3 form, (measured − model)/measured):\n";
    t += fmt::format("  {:<10} {:>7} {:>14} {:>11}\n", "channel", "points", "average error", "RMS error");
    for (const auto& g : agreement) {
      t += fmt::format("  {:<10} {:>7} {:>13.3f}% {:>10.3f}%\n", g.channel, g.points, 100.0 * g.mean, 100.0 * g.rms);
    }
  }
  if (!a.out.empty()) t += fmt::format("  parameter file written: {}\n", a.out);
  if (!a.header.empty()) t += fmt::format("  C++ header written: {} (the circuit at the fitted values)\n", a.header);
  return t;
}

sim::CircuitReport circuit_identify_report(const CircuitIdentifyRun& a, const circuit_tools::LoadedCircuit& c,
                                           const CircuitFitResult& r, const std::string& text) {
  sim::CircuitReport rep;
  rep.title = "hstmon identify report: " + c.file.name;
  std::size_t pinned = 0;
  for (bool p : r.pinned) pinned += p ? 1 : 0;
  rep.verdict = fmt::format(
      "{} parameter(s) fitted to {} operating point(s); residual RMS {:.3g} σ before, {:.3g} σ after; {} of them "
      "pinned tighter than they were known{}",
      r.names.size(), r.points.size(), r.rms_before, r.rms_after, pinned,
      r.held.empty() ? std::string() : fmt::format("; {} held at the start (not determined)", r.held.size()));
  rep.tone = pinned == r.names.size() && r.notes.empty() ? sim::VerdictTone::kGood : sim::VerdictTone::kWarning;
  rep.tables = {parameter_table(c, r)};
  if (!r.held.empty()) rep.tables.push_back(held_table(c, r));
  rep.tables.push_back(agreement_table(channel_agreement(c, r)));
  rep.tables.push_back(point_table(a, c, r));
  rep.notes = r.notes;
  rep.panels = point_panels(c, r);
  rep.figure_caption = "Steady residual per operating point, start values and fitted";
  rep.text = text;
  return rep;
}

}  // namespace hstmon::ident
