#pragma once
/// @file gnuplot.hpp
/// The one place the host tools talk to gnuplot: terminal choice by file extension, text
/// quoting, readable axis ranges, and running a script through a pipe with gnuplot's own
/// messages kept away from the user. Callers write their own data files and scripts.

#include <string>
#include <vector>

namespace hstmon::sim {

/// gnuplot terminal for an output file: "svg …" for .svg (fixed size, so an <img> of it in
/// an HTML report has one), "pngcairo …" for .png; both `noenhanced`, so that text prints
/// as written (`m_bias_p_mi.csv` is no subscript).
/// @param path      output file
/// @param width     image width [px]
/// @param height    image height [px]
/// @param terminal  out: the `set terminal` argument
/// @return          empty on success, else why (unknown extension)
std::string gnuplot_terminal(const std::string& path, int width, int height, std::string& terminal);

/// `text` as a gnuplot single-quoted string, quotes included (a `'` inside is doubled).
std::string gnuplot_quote(const std::string& text);

/// An axis range [lo, hi] in the data's display unit.
struct AxisRange {
  double lo = -1.0;  ///< lower end [display unit]
  double hi = 1.0;   ///< upper end [display unit]
};

/// A y range that shows every finite value of `values` with a 5 % margin and is at least
/// `min_span` wide (centred on the data), so a flat signal (one load, a noise-free log)
/// gets a readable axis instead of gnuplot's empty-range warning or ticks at 1e-9.
/// @param values    data [display unit]; NaN and ±inf are ignored
/// @param min_span  narrowest range shown [display unit], > 0
/// @return          the range; [-min_span/2, min_span/2] when no value is finite
AxisRange readable_range(const std::vector<double>& values, double min_span);

/// A temporary file name for gnuplot's data or messages, unique in this process (pid and
/// a counter), so plots written at the same time never share one.
/// @param stem  what it holds, e.g. "plot"; the name ends in `.<ext>`
/// @param ext   extension without the dot
std::string gnuplot_temp_file(const std::string& stem, const std::string& ext);

/// Runs `script` with gnuplot (the script's own `set output` decides the file). gnuplot's
/// warnings never reach the terminal: its stderr is captured and only a failure is reported.
/// @return empty on success, else one line: why (gnuplot missing, could not start, or
///         "gnuplot failed: " and gnuplot's first error line)
std::string run_gnuplot(const std::string& script);

}  // namespace hstmon::sim
