#pragma once
// `--report DIR` of `identify --circuit` and `gap --circuit`: report.md, report.html (one
// self-contained page) and the plots, with the plots' data and script (plots.gp) in the
// folder, so `cd DIR && gnuplot plots.gp` redraws them. Values in an engineer's units
// (bar, rpm, L/min, cc/rev: host::engineering_unit); residuals in each sensor's σ.
#include <string>
#include <vector>

#include "hstmon_plot/html_report.hpp"

namespace hstmon::cli {

/// One table of a report (header and rows of cells, already formatted).
struct ReportTable {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// One series of a panel: y per x, NaN where there is none.
struct ReportSeries {
  std::string key;         ///< the legend entry
  std::vector<double> y;
  std::string style;       ///< gnuplot `with` clause, e.g. "points pt 7 ps 1.2"
};

/// One panel: x values shared by its series.
struct ReportPanel {
  std::string title;
  std::string xlabel, ylabel;
  std::vector<double> x;
  std::vector<ReportSeries> series;
  bool from_zero = false;  ///< the y axis starts at 0 (a size, an RMS)
};

/// What a circuit command's report says.
struct CircuitReport {
  std::string title;                 ///< "hstmon identify --circuit report"
  std::string verdict;               ///< one sentence, first on the page
  sim::VerdictTone tone = sim::VerdictTone::kNeutral;
  std::vector<ReportTable> tables;
  std::vector<std::string> notes;
  std::vector<ReportPanel> panels;   ///< drawn one above the other in one figure
  std::string figure_caption;
  std::string text;                  ///< the command's own text output, kept as written
};

/// Writes the report into dir (created): report.md, report.html and, when there are
/// panels, figure.svg with its data (figure.dat) and script (plots.gp).
/// @param plot_warning  out: why the figure is missing (gnuplot absent or failed), else empty
/// @return empty on success, else why the report could not be written
std::string write_circuit_report(const std::string& dir, const CircuitReport& r, std::string& plot_warning);

/// write_circuit_report for `hstmon <command> --circuit … --report dir`, saying on stderr
/// why the figure is missing ("dir: note: no figure: …") or why the report could not be
/// written ("hstmon <command>: error: …").
/// @return false when the report could not be written
bool report_written(const char* command, const std::string& dir, const CircuitReport& r);

}  // namespace hstmon::cli
