#pragma once
/// @file plots.hpp
/// A data series of the identification tools' x–y plots (panels of a command's report).

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

}  // namespace hstmon::ident
