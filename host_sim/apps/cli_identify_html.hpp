#pragma once
// `identify --report DIR`'s report.html: one self-contained page built from the command's
// JSON result and text report, with its SVG plots embedded.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hstmon::cli {

/// One plot the command wrote.
struct ReportFigure {
  std::string file;     ///< the SVG file
  std::string caption;  ///< what it shows
};

/// Writes the page to `path`: the verdict first (how many parameters were identified, the
/// fit's s², the largest validation error), then the parameter and validation tables, the
/// plots, and the text report. Returns empty on success, else why not.
std::string write_identify_html(const std::string& path, const nlohmann::json& result, const std::string& text,
                                const std::vector<ReportFigure>& figures);

}  // namespace hstmon::cli
