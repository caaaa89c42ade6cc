/// @file residual_plot.cpp
/// The replay's figure, for any channel set: per channel, measured and model (left) and the residual (right).
/// One key for the whole figure, in the band above the panels (never over the data, never
/// repeated); a channel the log does not have gets its model only and a note where its
/// residual would be; every y range is readable even when the signal is flat, and a
/// residual's range is not set by the model's start-up transient.
#include "hstmon_plot/residual_plot.hpp"

#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>


namespace hstmon::cli {

namespace {

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

std::string plot_replay(const PlotTrace& trace, const std::string& title, const std::string& path) {
  std::string terminal;
  const std::size_t n = trace.channels.size();
  if (n == 0 || trace.rows == 0 || !trace.row) return "nothing to plot";
  // 1100 px for the thesis rig's four rows of panels; the same height per row for others.
  const int height = 100 + 250 * static_cast<int>(n);
  if (std::string err = sim::gnuplot_terminal(path, 1400, height, terminal); !err.empty()) return err;

  namespace fs = std::filesystem;
  const fs::path data = sim::gnuplot_temp_file("plot", "dat");
  // Per channel, display-unit columns for the ranges: measured, model, residual.
  std::vector<std::array<std::vector<double>, 3>> cols(n);
  std::vector<double> t;
  {
    auto out = fmt::output_file(data.string());
    std::vector<double> y(n), y_hat(n), r(n);
    // Thin very long traces to ~20 000 points: the plot cannot show more.
    const std::size_t stride = std::max<std::size_t>(1, trace.rows / 20000);
    for (std::size_t i = 0; i < trace.rows; i += stride) {
      double ti = 0.0;
      trace.row(i, ti, y.data(), y_hat.data(), r.data());
      out.print("{:.9g}", ti);
      t.push_back(ti);
      for (std::size_t c = 0; c < n; ++c) {
        const double s = trace.channels[c].scale;
        const double v[3] = {y[c] * s, y_hat[c] * s, r[c] * s};
        out.print(" {:.9g} {:.9g} {:.9g}", v[0], v[1], v[2]);
        for (std::size_t k = 0; k < 3; ++k) cols[c][k].push_back(v[k]);
      }
      out.print("\n");
    }
  }
  bool any_measured = false;
  for (const PlotChannel& c : trace.channels) any_measured = any_measured || c.measured;

  const std::string file = sim::gnuplot_quote(data.string());
  std::string script = fmt::format("set terminal {}\nset output {}\nset datafile missing 'nan'\n", terminal,
                                   sim::gnuplot_quote(path));
  // Fixed margins leave the top band for the figure's title and its one key.
  // The band above the panels is 110 px whatever the height (0.1 of the thesis figure's).
  const double top = 1.0 - 110.0 / height;
  script += fmt::format("set multiplot layout {},2 title {} margins 0.06,0.98,{:.4f},{:.4f} spacing 0.07,{:.4f}\n", n,
                        sim::gnuplot_quote(title), 55.0 / height, top, 93.5 / height);
  const sim::AxisRange span_t = t.back() > t.front() ? sim::AxisRange{t.front(), t.back()} : sim::readable_range(t, 1.0);
  script += fmt::format("set grid\nset xlabel 't [s]'\nset xrange {}\n", range(span_t));
  for (std::size_t c = 0; c < n; ++c) {
    const int col = 2 + 3 * static_cast<int>(c);
    const PlotChannel& p = trace.channels[c];
    const bool measured = p.measured;
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
      script += fmt::format("set key at screen 0.98,{:.4f} right top horizontal samplen 3 spacing 1.2\n",
                            1.0 - 27.5 / height);
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
      if (t[i] >= trace.t_first + trace.startup_hold) after_hold.push_back(cols[c][2][i]);
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
