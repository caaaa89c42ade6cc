#pragma once
// Plots a replay trace with gnuplot: measured against estimate, and the residual, for
// each measured channel. SVG or PNG by the output file's extension.
#include <string>

#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// Writes the plot to `path` (.svg or .png). Returns an empty string on success, else
/// a message saying what failed (gnuplot missing, unknown extension, …).
std::string plot_trace(const host::ReplayResult& result, const std::string& title, const std::string& path);

}  // namespace hstmon::cli
