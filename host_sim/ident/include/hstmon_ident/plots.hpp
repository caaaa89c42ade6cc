#pragma once
/// @file plots.hpp
/// x–y plots through gnuplot (gnuplot-nox; started with popen, as host_sim's residual
/// plots). SVG or PNG by the file's extension.

#include <string>
#include <vector>

namespace hstmon::ident {

/// One data series of a plot.
struct PlotSeries {
  std::string label;         ///< legend text
  std::vector<double> x;     ///< abscissae [display unit]
  std::vector<double> y;     ///< ordinates [display unit]
  bool points = false;       ///< draw markers (data) instead of lines (model)
};

/// Writes an x–y plot of `series` to `path` (.svg or .png).
/// @return empty on success, else what failed (gnuplot missing, bad extension, …)
std::string plot_xy(const std::string& path, const std::string& title, const std::string& xlabel,
                    const std::string& ylabel, const std::vector<PlotSeries>& series);

}  // namespace hstmon::ident
