#pragma once
// `hstmon replay --summary LOG|DIR...`: many logs of one circuit, each read and replayed
// on its own (circuit_replay.hpp) on a pool of threads, one JSON summary line per log in the order of
// the sorted paths, whatever the number of threads. docs/fleet.md describes the line, the
// machine rule and how to run it under GNU parallel or a Slurm array instead.
#include <memory>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// What names a log's machine: its parent folder (default; the file stem for a log given
/// without a folder), its file stem, or the first group of a regular expression matched
/// against the path as given.
struct MachineRule {
  enum class Kind { kParent, kStem, kRegex } kind = Kind::kParent;
  std::string pattern;  ///< kRegex: ECMAScript regex with one capture group
};

/// Parses --machine-from: "parent", "stem" or "regex:PATTERN". On a bad rule sets `error`.
MachineRule parse_machine_rule(const std::string& text, std::string& error);

/// The machine of `path` under `rule`; "" when a regex does not match.
std::string machine_of(const std::string& path, const MachineRule& rule);

/// Logs named on the command line: files as given, folders searched recursively for
/// *.csv, *.tsv and *.txt; sorted by path (byte order), duplicates removed. A name that is
/// neither file nor folder is kept (its line then says it cannot be opened).
std::vector<std::string> expand_logs(const std::vector<std::string>& names);

/// Everything a summary replay needs besides the logs.
struct FleetReplayArgs {
  host::ReadOptions read;
  MachineRule machine;
  unsigned jobs = 0;           ///< threads; 0 = all cores
  /// The circuit every log is of (read whole, circuit_log.hpp), replayed through its
  /// monitor with circuit_replay. Required.
  std::shared_ptr<const circuit_tools::LoadedCircuit> circuit;
  /// Its fault table, built once for every log (null: each replay builds its own, or runs
  /// residuals only, as circuit_replay says).
  std::shared_ptr<const circuit_tools::CircuitFaultTable> circuit_table;
  circuit_tools::CircuitReplayOptions circuit_replay;  ///< keep_trace and table are ignored
};

/// One log's summary line (no newline): {"type":"log","log",...,"status":"ok"|"error",...};
/// residuals keyed by the circuit's sensor names.
/// The same input gives the same bytes. `failed` (if given) is set when the log failed.
std::string summary_line(const std::string& path, const FleetReplayArgs& args, bool* failed = nullptr);

/// Replays `logs` on args.jobs threads and prints one summary line per log to stdout, in
/// the order of `logs`. Returns kExitOk, or kExitBadInput when any log failed.
int run_fleet_replay(const std::vector<std::string>& logs, const FleetReplayArgs& args);

}  // namespace hstmon::cli
