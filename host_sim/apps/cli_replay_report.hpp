#pragma once
// `hstmon replay --report DIR`: the replay as a report a person reads and files: report.md
// and report.html (one self-contained page: the diagnosis verdict first, the residual table,
// the diagnosis events, the residual plot embedded) and the plot itself, residuals.svg.
#include <string>

#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// Writes the report into `dir` (created).
/// @param dir           report directory
/// @param log           the log's name as given on the command line
/// @param r             the replay, with its trace (ReplayOptions::keep_trace)
/// @param diagnosed     false with --no-diagnosis: the verdict says the matcher did not run
/// @param plot_warning  out: why the plot is missing (gnuplot absent or failed), else empty
/// @return              empty on success, else why the report could not be written
std::string write_replay_report(const std::string& dir, const std::string& log, const host::ReplayResult& r,
                                bool diagnosed, std::string& plot_warning);

}  // namespace hstmon::cli
