// report.md and report.html of `hstmon replay --report DIR` (cli_replay_report.hpp).
#include "cli_replay_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "cli_events.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_plot/html_report.hpp"
#include "hstmon_plot/residual_plot.hpp"

namespace hstmon::cli {

namespace {

// The one sentence a reader needs first, and how alarming it is.
std::string verdict(const ReplayReport& r, sim::VerdictTone& tone) {
  std::string text;
  if (!r.diagnosed) {
    text = "diagnosis not run (--no-diagnosis): residuals only";
    tone = sim::VerdictTone::kNeutral;
  } else if (r.events.empty()) {
    text = "no fault detected";
    tone = sim::VerdictTone::kGood;
  } else if (r.final_status == "out_of_envelope") {
    text = "out of envelope: " + r.events.back().why;
    tone = sim::VerdictTone::kWarning;
  } else if (r.final_status == "unverified") {
    text = r.events.back().why;
    tone = sim::VerdictTone::kWarning;
  } else {
    // The last event that names candidates says what the matcher ended with.
    const host::ReplayEvent* last = nullptr;
    for (const auto& e : r.events) {
      if (!e.candidates.empty()) last = &e;
    }
    text = fmt::format("{} at the end of the log", r.final_status);
    if (r.final_status != "nominal" && last != nullptr) {
      text += fmt::format(" (since t = {:.3f} s): {}", last->t, candidate_list(*last, 3));
      if (!r.verdict_class.empty()) text += "; " + r.verdict_class;
    } else if (r.final_status == "nominal") {
      text = fmt::format("no fault at the end of the log ({} diagnosis events before, see below)", r.events.size());
    }
    tone = r.final_status == "nominal" ? sim::VerdictTone::kWarning
           : r.final_status == "isolated" ? sim::VerdictTone::kBad
                                          : sim::VerdictTone::kWarning;
  }
  if (!r.read_error.empty()) {
    text += fmt::format("; only the {} rows before a bad row were replayed ({})", r.rows, r.read_error);
    if (tone != sim::VerdictTone::kBad) tone = sim::VerdictTone::kWarning;
  }
  const auto health = host::health_names(r.health);
  if (!health.empty()) {
    std::string joined;
    for (const auto& n : health) joined += (joined.empty() ? "" : ", ") + n;
    text += fmt::format("; observer health: {} on {} rows, results there are not trustworthy", joined, r.unhealthy_rows);
    if (tone != sim::VerdictTone::kBad) tone = sim::VerdictTone::kWarning;
  }
  return text;
}

std::vector<std::vector<std::string>> residual_rows(const ReplayReport& r) {
  std::vector<std::vector<std::string>> rows;
  for (const ReportChannel& ch : r.channels) {
    const auto& s = ch.stats;
    const std::string label = fmt::format("{} [{}]", ch.label, ch.unit);
    if (!ch.measured) {
      rows.push_back({label, "not in log"});
      continue;
    }
    const double k = ch.scale;
    rows.push_back({label, fmt::format("{:.4g}", s.mean() * k), fmt::format("{:.4g}", s.rms() * k),
                    fmt::format("{:.4g}", s.noise() * k), fmt::format("{:.4g}", s.max_signed * k), fmt::format("{:.6g}", s.t_max)});
  }
  return rows;
}

std::vector<std::vector<std::string>> event_rows(const ReplayReport& r) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& e : r.events) {
    std::string what = e.event == "cleared" ? std::string("residuals back within their bounds") : candidate_list(e, 4);
    if (!e.why.empty()) what = e.why + (what.empty() ? "" : "; " + what);
    rows.push_back({fmt::format("{:.3f}", e.t), e.event, what});
  }
  return rows;
}

std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string md = "|";
  for (const auto& h : header) md += " " + h + " |";
  md += "\n|";
  for (std::size_t k = 0; k < header.size(); ++k) md += "---|";
  md += "\n";
  for (const auto& row : rows) {
    md += "|";
    for (std::size_t k = 0; k < header.size(); ++k) md += " " + (k < row.size() ? row[k] : std::string()) + " |";
    md += "\n";
  }
  return md;
}

}  // namespace

std::string write_replay_report(const std::string& dir, const ReplayReport& r, std::string& plot_warning) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create " + dir + ": " + ec.message();
  const std::string plot = (fs::path(dir) / "residuals.svg").string();
  plot_warning = plot_replay(r.plot, "hstmon replay " + r.log, plot);

  sim::VerdictTone tone = sim::VerdictTone::kNeutral;
  const std::string verdict_text = verdict(r, tone);
  const std::string about = fmt::format(
      "Log: {}; {}; {} rows, t = {:.6g} … {:.6g} s; observer tick {}; start-up hold-off {}.", r.log, r.circuit, r.rows,
      r.t_first, r.t_last, host::duration_text(r.tick), host::duration_text(r.startup_hold));
  const std::vector<std::string> residual_header = {"channel", "mean", "RMS", "noise", "peak", "at t [s]"};
  const std::vector<std::string> event_header = {"t [s]", "event", "candidates (score)"};
  const auto residuals = residual_rows(r);
  const auto events = event_rows(r);

  sim::HtmlReport page("hstmon replay report");
  page.verdict(verdict_text, tone);
  page.paragraph(about);
  for (const auto& n : r.notes) page.paragraph("note: " + n);
  page.heading("Residual (measured − model; noise from successive samples)");
  page.table(residual_header, residuals);
  if (r.diagnosed) {
    page.heading("Diagnosis events (single-fault hypotheses, best first)");
    if (events.empty()) {
      page.paragraph("none: no fault detected");
    } else {
      page.table(event_header, events);
    }
  }
  page.heading("Measured, model and residual");
  if (plot_warning.empty()) {
    page.image(plot, "per channel: measured and model (left), residual (right)");
  } else {
    page.paragraph("no plot: " + plot_warning);
  }
  if (std::string err = page.write((fs::path(dir) / "report.html").string()); !err.empty()) return err;

  std::ofstream md(fs::path(dir) / "report.md");
  md << "# hstmon replay report\n\n**Verdict:** " << verdict_text << "\n\n" << about << "\n\n";
  for (const auto& n : r.notes) md << "note: " << n << "\n\n";
  md << "## Residual (measured − model)\n\n" << markdown_table(residual_header, residuals) << "\n";
  if (r.diagnosed) {
    md << "## Diagnosis events\n\n" << (events.empty() ? "none: no fault detected\n" : markdown_table(event_header, events)) << "\n";
  }
  md << (plot_warning.empty() ? "## Measured, model and residual\n\n![](residuals.svg)\n" : "(no plot: " + plot_warning + ")\n");
  md.close();
  if (!md) return "cannot write " + (fs::path(dir) / "report.md").string();
  return {};
}

bool write_plot_and_report(const std::string& plot, const std::string& report_dir, const ReplayReport& r, bool json) {
  bool ok = true;
  if (!plot.empty()) {
    if (const std::string err = plot_replay(r.plot, "hstmon replay " + r.log, plot); !err.empty()) {
      fmt::print(stderr, "hstmon replay: error: plot: {}\n", err);
      ok = false;
    } else if (!json) {
      fmt::print("  plot written to {}\n", plot);
    }
  }
  if (!report_dir.empty()) {
    std::string plot_warning;
    if (const std::string err = write_replay_report(report_dir, r, plot_warning); !err.empty()) {
      fmt::print(stderr, "hstmon replay: error: report: {}\n", err);
      ok = false;
    } else {
      if (!plot_warning.empty()) fmt::print(stderr, "hstmon replay: warning: report without plot: {}\n", plot_warning);
      if (!json) fmt::print("  report written to {0}/report.md and {0}/report.html\n", report_dir);
    }
  }
  return ok;
}

}  // namespace hstmon::cli
