// The report of `hstmon identify` (cli_identify_report.hpp): the paper sections' plots as
// panels of the circuit report's one figure.
#include "cli_identify_report.hpp"

#include <algorithm>

namespace hstmon::cli::identify {

namespace {

// y of a line series at x (its x ascending): linear between its points, NaN outside them.
double line_at(const id::PlotSeries& s, double x) {
  const auto it = std::lower_bound(s.x.begin(), s.x.end(), x);
  if (it == s.x.end()) return std::nan("");
  const auto i = static_cast<std::size_t>(it - s.x.begin());
  if (*it == x) return s.y[i];
  if (i == 0) return std::nan("");
  return s.y[i - 1] + (s.y[i] - s.y[i - 1]) * (x - s.x[i - 1]) / (s.x[i] - s.x[i - 1]);
}

// A plot as one panel of the circuit report's figure: the panel's x are every series' x
// (sorted, once each); a data series has NaN where it has no point, a line is interpolated
// (gnuplot leaves NaN out, so a line would otherwise break at another series' x).
sim::ReportPanel panel_of(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                          const std::vector<id::PlotSeries>& series) {
  sim::ReportPanel p{title, xlabel, ylabel, {}, {}};
  for (const auto& s : series) p.x.insert(p.x.end(), s.x.begin(), s.x.end());
  std::sort(p.x.begin(), p.x.end());
  p.x.erase(std::unique(p.x.begin(), p.x.end()), p.x.end());
  for (const auto& s : series) {
    sim::ReportSeries out{s.label, {}, s.points ? "points pt 7 ps 0.6" : "lines lw 2"};
    out.y.reserve(p.x.size());
    for (double x : p.x) {
      if (!s.points) {
        out.y.push_back(line_at(s, x));
        continue;
      }
      const auto it = std::find(s.x.begin(), s.x.end(), x);
      out.y.push_back(it == s.x.end() ? std::nan("") : s.y[static_cast<std::size_t>(it - s.x.begin())]);
    }
    p.series.push_back(std::move(out));
  }
  return p;
}

}  // namespace

void Report::plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                  const std::vector<id::PlotSeries>& series) {
  if (plots()) panels->push_back(panel_of(title, xlabel, ylabel, series));
}

}  // namespace hstmon::cli::identify
