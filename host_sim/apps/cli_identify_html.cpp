// report.html of `hstmon identify --report DIR` (cli_identify_html.hpp).
#include "cli_identify_html.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "hstmon_plot/html_report.hpp"

namespace hstmon::cli {

namespace {

std::string number(const nlohmann::json& v, const char* format = "{:.4g}") {
  return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : std::string("—");
}

// The thesis fit's verdict: identified or not, noise model, and the largest validation error.
void thesis_verdict(sim::HtmlReport& page, const nlohmann::json& t) {
  std::size_t estimated = 0, total = 0;
  std::string held;
  for (const auto& p : t["parameters"]) {
    ++total;
    if (p.value("identifiable", false)) {
      ++estimated;
    } else {
      held += (held.empty() ? "" : ", ") + p.value("name", std::string("?"));
    }
  }
  double worst = 0.0;
  std::string worst_signal;
  for (const auto& v : t["validation"]) {
    const double e = v["rms_error_pct"].is_number() ? std::fabs(v["rms_error_pct"].get<double>())
                                                    : std::numeric_limits<double>::quiet_NaN();
    if (!(e <= worst)) {
      worst = e;
      worst_signal = v.value("signal", std::string("?"));
    }
  }
  const bool converged = t.value("lm_status", std::string()).rfind("converged", 0) == 0;
  std::string text = fmt::format("{} of {} parameters identified{}; s² = {} (≈ 1 when the noise model fits)", estimated,
                                 total, held.empty() ? "" : " (held at the prior: " + held + ")", number(t["s2"], "{:.3g}"));
  if (!worst_signal.empty()) text += fmt::format("; largest validation RMS error {:.3g} % ({})", worst, worst_signal);
  if (!converged) text += "; the fit did not converge: " + t.value("lm_status", std::string("?"));
  const sim::VerdictTone tone = !converged || std::isnan(worst) ? sim::VerdictTone::kBad
                                : estimated < total             ? sim::VerdictTone::kWarning
                                                                : sim::VerdictTone::kGood;
  page.verdict(text, tone);
}

void thesis_tables(sim::HtmlReport& page, const nlohmann::json& t) {
  page.heading("Parameters (95 % intervals)");
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : t["parameters"]) {
    const bool id = p.value("identifiable", false);
    const auto& ci = p["ci"];
    rows.push_back({p.value("name", std::string("?")), number(p["value"], "{:.6g}"), id ? number(p["se"], "{:.3g}") : "—",
                    id && ci.is_array() && ci.size() == 2 ? fmt::format("[{}, {}]", number(ci[0], "{:.6g}"), number(ci[1], "{:.6g}")) : "—",
                    p.value("unit", std::string()), id ? "" : "not identifiable: held at the prior"});
  }
  page.table({"parameter", "estimate", "SE", "95 % interval", "unit", "note"}, rows);
  page.heading("Validation (Table 2.3 form; error = (model − data)/data)");
  rows.clear();
  for (const auto& v : t["validation"]) {
    rows.push_back({v.value("signal", std::string("?")), number(v["points"], "{:.0f}"), number(v["avg_error_pct"], "{:.3f} %"),
                    number(v["rms_error_pct"], "{:.3f} %")});
  }
  page.table({"variable", "points", "average error", "RMS error"}, rows);
}

}  // namespace

std::string write_identify_html(const std::string& path, const nlohmann::json& result, const std::string& text,
                                const std::vector<ReportFigure>& figures) {
  sim::HtmlReport page("hstmon identify report");
  if (result.contains("thesis")) {
    thesis_verdict(page, result["thesis"]);
    thesis_tables(page, result["thesis"]);
  } else {
    std::string parts;
    if (result.contains("paper")) parts = "paper rig: pump curve and port areas fitted";
    if (result.contains("studies")) parts += std::string(parts.empty() ? "" : "; ") + "parameter studies run";
    page.verdict(parts.empty() ? "nothing identified" : parts, sim::VerdictTone::kNeutral);
  }
  if (!figures.empty()) page.heading("Plots");
  for (const auto& f : figures) page.image(f.file, f.caption);
  page.heading("Full text report");
  page.preformatted(text);
  return page.write(path);
}

}  // namespace hstmon::cli
