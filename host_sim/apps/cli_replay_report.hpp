#pragma once
// `hstmon replay --report DIR`: the replay as a report a person reads and files: report.md
// and report.html (one self-contained page: the diagnosis verdict first, the residual table,
// the diagnosis events, the residual plot embedded) and the plot itself, residuals.svg.
// One writer for every replay's report (`hstmon replay`, any circuit).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hstmon_host/replay.hpp"
#include "hstmon_plot/residual_plot.hpp"

namespace hstmon::cli {

/// One channel's row of the residual table.
struct ReportChannel {
  std::string label;      ///< "Pmi", "p_mi"
  std::string unit;       ///< display unit
  double scale = 1.0;     ///< display unit per SI unit
  bool measured = true;   ///< in the log
  host::ChannelStats stats;  ///< residual statistics [SI]
};

/// What a report says, whichever replay made it.
struct ReplayReport {
  std::string log;                        ///< the log's name as given on the command line
  std::string circuit;                    ///< "circuit NAME (FILE[, PARAMS])": the model replayed
  std::size_t rows = 0;
  double t_first = 0.0, t_last = 0.0;     ///< [s]
  double tick = 0.0;                      ///< observer tick [s]
  double startup_hold = 0.0;              ///< [s]
  std::vector<std::string> notes;
  std::vector<ReportChannel> channels;
  std::vector<host::ReplayEvent> events;
  std::string final_status = "nominal";
  std::uint32_t health = 0;               ///< HealthFlag bits OR-ed over the replay
  std::size_t unhealthy_rows = 0;
  bool diagnosed = true;                  ///< false: the verdict says the matcher did not run
  /// A lenient read that stopped at a bad row ("file:line:column: error: …"): the verdict
  /// says that only the rows before it were replayed. Empty when the whole log was read.
  std::string read_error;
  /// A circuit replay's final candidates said plainly, with what would split them
  /// (circuit_tools::CandidateClass::sentence); the verdict adds it. Empty: nothing added.
  std::string verdict_class;
  PlotTrace plot;                         ///< the trace (rows = 0: no plot)
};

/// A report with what every replay result has (host::ReplayResult, a circuit's
/// CircuitReplayResult): span, tick, hold-off, notes (with the envelope check's sentence),
/// events, final status, health. The
/// caller adds the channels, the plot and whether the matcher ran.
template <class Result>
ReplayReport replay_report_facts(const std::string& log, const Result& r) {
  ReplayReport rep;
  rep.log = log;
  rep.rows = r.rows;
  rep.t_first = r.t_first;
  rep.t_last = r.t_last;
  rep.tick = r.tick;
  rep.startup_hold = r.startup_hold;
  rep.notes = r.notes;
  rep.notes.push_back("envelope: " + r.envelope.text);
  rep.events = r.events;
  rep.final_status = r.final_status;
  rep.health = r.health;
  rep.unhealthy_rows = r.unhealthy_rows;
  return rep;
}

/// Writes the report into `dir` (created).
/// @param plot_warning  out: why the plot is missing (gnuplot absent or failed), else empty
/// @return              empty on success, else why the report could not be written
std::string write_replay_report(const std::string& dir, const ReplayReport& r, std::string& plot_warning);

/// `--plot FILE` and `--report DIR` of a replay (either may be empty: not asked for):
/// writes them, says so on stdout (unless json), and an error on stderr for each that fails.
/// @return true when every one asked for was written
bool write_plot_and_report(const std::string& plot, const std::string& report_dir, const ReplayReport& r, bool json);

}  // namespace hstmon::cli
