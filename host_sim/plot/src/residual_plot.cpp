/// @file residual_plot.cpp
/// The replay's figure: per channel, measured and model (left) and the residual (right).
/// One key for the whole figure, in the band above the panels (never over the data, never
/// repeated); a channel the log does not have gets its model only and a note where its
/// residual would be; every y range is readable even when the signal is flat, and a
/// residual's range is not set by the model's start-up transient.
#include "hstmon_plot/residual_plot.hpp"

#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>


namespace hstmon::cli {

namespace {

struct Panel {
  const char* name;
  const char* unit;
  double scale;      // SI → display
  double min_span;   // narrowest y range shown [display unit]: below a sensor's resolution
};
const Panel kPanels[4] = {{"Pmi", "bar", 1e-5, 0.1},
                          {"Pmo", "bar", 1e-5, 0.1},
                          {"Ppp", "bar", 1e-5, 0.1},
                          {"ωm", "rpm", 60.0 / (2.0 * M_PI), 1.0}};

const char* const kMeasuredColour = "#888888";
const char* const kModelColour = "#1f77b4";
const char* const kResidualColour = "#d62728";

std::string range(const sim::AxisRange& r) { return fmt::format("[{:.9g}:{:.9g}]", r.lo, r.hi); }

// A signal panel's narrowest range: the unit's floor, or 2 % of the level (a flat 1700 rpm
// gets ±17 rpm, as gnuplot itself would, without its warning).
double signal_span(const std::vector<double>& v, double floor) {
  double level = 0.0;
  for (double x : v) {
    if (std::isfinite(x)) level = std::max(level, std::fabs(x));
  }
  return std::max(floor, 0.02 * level);
}

}  // namespace

std::string plot_trace(const host::ReplayResult& result, const std::string& title, const std::string& path) {
  std::string terminal;
  if (std::string err = sim::gnuplot_terminal(path, 1400, 1100, terminal); !err.empty()) return err;
  if (result.trace.empty()) return "nothing to plot";

  namespace fs = std::filesystem;
  const fs::path data = sim::gnuplot_temp_file("plot", "dat");
  // Per channel, display-unit columns for the ranges: measured, model, residual.
  std::vector<double> cols[4][3];
  std::vector<double> t;
  {
    auto out = fmt::output_file(data.string());
    // Thin very long traces to ~20 000 points: the plot cannot show more.
    const std::size_t stride = std::max<std::size_t>(1, result.trace.size() / 20000);
    for (std::size_t i = 0; i < result.trace.size(); i += stride) {
      const auto& r = result.trace[i];
      out.print("{:.9g}", r.t);
      t.push_back(r.t);
      for (std::size_t c = 0; c < 4; ++c) {
        const double s = kPanels[c].scale;
        const double v[3] = {r.y[c] * s, r.y_hat[c] * s, r.r[c] * s};
        out.print(" {:.9g} {:.9g} {:.9g}", v[0], v[1], v[2]);
        for (int k = 0; k < 3; ++k) cols[c][k].push_back(v[k]);
      }
      out.print("\n");
    }
  }
  bool any_measured = false;
  for (bool m : result.measured) any_measured = any_measured || m;

  const std::string file = sim::gnuplot_quote(data.string());
  std::string script = fmt::format("set terminal {}\nset output {}\nset datafile missing 'nan'\n", terminal,
                                   sim::gnuplot_quote(path));
  // Fixed margins leave the top band for the figure's title and its one key.
  script += fmt::format("set multiplot layout 4,2 title {} margins 0.06,0.98,0.05,0.9 spacing 0.07,0.085\n",
                        sim::gnuplot_quote(title));
  const sim::AxisRange span_t = t.back() > t.front() ? sim::AxisRange{t.front(), t.back()} : sim::readable_range(t, 1.0);
  script += fmt::format("set grid\nset xlabel 't [s]'\nset xrange {}\n", range(span_t));
  for (std::size_t c = 0; c < 4; ++c) {
    const int col = 2 + 3 * static_cast<int>(c);
    const Panel& p = kPanels[c];
    const bool measured = result.measured[c];
    std::vector<double> both = cols[c][1];
    if (measured) both.insert(both.end(), cols[c][0].begin(), cols[c][0].end());
    script += fmt::format("set ylabel '{}'\nset yrange {}\n", p.unit, range(sim::readable_range(both, signal_span(both, p.min_span))));
    script += measured ? fmt::format("set title '{} measured and model'\n", p.name)
                       : fmt::format("set title '{} model (not in the log)'\n", p.name);
    std::string plot = "plot ";
    if (measured) {
      plot += fmt::format("{} using 1:{} with lines lc rgb '{}' notitle, ", file, col, kMeasuredColour);
    }
    plot += fmt::format("{} using 1:{} with lines lw 1.5 lc rgb '{}' notitle", file, col + 1, kModelColour);
    if (c == 0) {
      // The figure's key: drawn once, from the first panel, as entries of no data.
      script += "set key at screen 0.98,0.975 right top horizontal samplen 3 spacing 1.2\n";
      if (any_measured) plot += fmt::format(", NaN with lines lc rgb '{}' title 'measured'", kMeasuredColour);
      plot += fmt::format(", NaN with lines lw 1.5 lc rgb '{}' title 'model'", kModelColour);
      if (any_measured) plot += fmt::format(", NaN with lines lc rgb '{}' title 'residual'", kResidualColour);
    }
    script += plot + "\n";
    if (c == 0) script += "unset key\n";
    if (!measured) {
      // No residual without a measurement: an empty slot that says so, not a zero line.
      script += "set title ''\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\n";
      script += fmt::format("set label 1 '{} is not in the log: no residual' at graph 0.5,0.5 center\n", p.name);
      script += "set yrange [0:1]\nplot NaN notitle\nunset label 1\nset border\nset tics\nset grid\nset xlabel 't [s]'\n";
      continue;
    }
    // The model's own start-up transient (the hold-off, when detection waits) would set
    // the scale and flatten the rest: the range covers what comes after it, and says so.
    std::vector<double> after_hold;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] >= result.t_first + result.startup_hold) after_hold.push_back(cols[c][2][i]);
    }
    const sim::AxisRange all = sim::readable_range(cols[c][2], p.min_span);
    const sim::AxisRange shown = after_hold.empty() ? all : sim::readable_range(after_hold, p.min_span);
    const bool clipped = shown.lo > all.lo || shown.hi < all.hi;
    script += fmt::format("set title '{} residual (measured − model){}'\nset yrange {}\n", p.name,
                          clipped ? ", start-up transient off scale" : "", range(shown));
    script += fmt::format("plot {} using 1:{} with lines lc rgb '{}' notitle\n", file, col + 2, kResidualColour);
  }
  script += "unset multiplot\n";

  const std::string err = sim::run_gnuplot(script);
  std::error_code ec;
  fs::remove(data, ec);
  return err.empty() ? err : err + " (writing " + path + ")";
}

}  // namespace hstmon::cli
