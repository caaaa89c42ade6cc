/// @file plots.cpp
/// gnuplot x–y plots (through hstmon_plot/gnuplot.hpp).
#include "hstmon_ident/plots.hpp"

#include "hstmon_plot/gnuplot.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hstmon::ident {

namespace {
// A range over every series' values on one axis, at least 2 % of their level wide (a flat
// curve gets a readable axis, and gnuplot no empty-range warning).
std::string axis_range(const std::vector<PlotSeries>& series, bool y) {
  std::vector<double> v;
  double level = 0.0;
  for (const auto& s : series) {
    for (double x : y ? s.y : s.x) {
      v.push_back(x);
      if (std::isfinite(x)) level = std::max(level, std::fabs(x));
    }
  }
  const sim::AxisRange r = sim::readable_range(v, level > 0.0 ? 0.02 * level : 1.0);
  return fmt::format("[{:.9g}:{:.9g}]", r.lo, r.hi);
}
}  // namespace

std::string plot_xy(const std::string& path, const std::string& title, const std::string& xlabel,
                    const std::string& ylabel, const std::vector<PlotSeries>& series) {
  std::string terminal;
  if (std::string err = sim::gnuplot_terminal(path, 1000, 650, terminal); !err.empty()) return err;
  if (series.empty()) return "nothing to plot";
  namespace fs = std::filesystem;
  const fs::path data = sim::gnuplot_temp_file("ident-" + fs::path(path).stem().string(), "dat");
  {
    auto out = fmt::output_file(data.string());
    for (const auto& s : series) {
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) out.print("{:.9g} {:.9g}\n", s.x[i], s.y[i]);
      out.print("\n\n");
    }
  }
  // The key right of the plot: never over the data, nor over the axis labels.
  std::string script = fmt::format("set terminal {}\nset output {}\nset grid\nset key outside right top vertical\n", terminal, sim::gnuplot_quote(path));
  script += fmt::format("set title {}\nset xlabel {}\nset ylabel {}\nset xrange {}\nset yrange {}\nplot ", sim::gnuplot_quote(title),
                        sim::gnuplot_quote(xlabel), sim::gnuplot_quote(ylabel), axis_range(series, false), axis_range(series, true));
  // Point series that coincide (a model through its data) must all show: the first as large
  // open circles, the later ones as smaller filled dots inside them.
  int nth_points = 0;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* style = !series[k].points   ? "lines lw 1.8"
                        : nth_points++ == 0 ? "points pt 6 ps 1.6"
                                            : "points pt 7 ps 0.7";
    script += fmt::format("{}{} index {} using 1:2 with {} title {}", k ? ", " : "", sim::gnuplot_quote(data.string()),
                          k, style, sim::gnuplot_quote(series[k].label));
  }
  script += "\n";
  const std::string err = sim::run_gnuplot(script);
  std::error_code ec;
  fs::remove(data, ec);
  return err.empty() ? err : err + " on " + path;
}

}  // namespace hstmon::ident
