#pragma once
// Plots a replay trace with gnuplot: measured against model, and the residual, for each
// channel. SVG or PNG by the output file's extension. The channels are a circuit's
// sensors (PlotTrace filled by the circuit replay).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// One channel of the figure: a row of two panels.
struct PlotChannel {
  std::string name;       ///< panel title, e.g. "Pmi", "p_mi"
  std::string unit;       ///< display unit, e.g. "bar"
  double scale = 1.0;     ///< display unit per SI unit (1e-5 for Pa → bar)
  double min_span = 0.0;  ///< narrowest y range shown [display unit]: about a sensor's resolution
  bool measured = true;   ///< in the log; otherwise the model alone and no residual panel
};

/// A replay trace to plot. Row k's values come from row(k, t, y, y_hat, r), each array
/// one value per channel in SI (NaN where absent), so no copy of the trace is made.
struct PlotTrace {
  std::vector<PlotChannel> channels;
  std::size_t rows = 0;
  std::function<void(std::size_t k, double& t, double* y, double* y_hat, double* r)> row;
  double t_first = 0.0;       ///< [s]
  double startup_hold = 0.0;  ///< the residual's range ignores t < t_first + this [s]
};

/// Sets trace's rows from a replay result with a per-row trace (t, y, y_hat, r indexable
/// by channel) and its t_first and startup_hold; the trace refers to `result`, which must
/// outlive it. The thesis replay's and a circuit's results both have that shape.
/// @param channels  channels per row (trace.channels.size())
template <class Result>
void set_trace_rows(PlotTrace& trace, const Result& result, std::size_t channels) {
  trace.rows = result.trace.size();
  trace.row = [&result, channels](std::size_t k, double& t, double* y, double* y_hat, double* r) {
    const auto& row = result.trace[k];
    t = row.t;
    for (std::size_t c = 0; c < channels; ++c) {
      y[c] = row.y[c];
      y_hat[c] = row.y_hat[c];
      r[c] = row.r[c];
    }
  };
  trace.t_first = result.t_first;
  trace.startup_hold = result.startup_hold;
}

/// Writes the figure to `path` (.svg or .png). Returns an empty string on success, else
/// a message saying what failed (gnuplot missing, unknown extension, …).
std::string plot_replay(const PlotTrace& trace, const std::string& title, const std::string& path);

}  // namespace hstmon::cli
