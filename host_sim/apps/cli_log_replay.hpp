#pragma once
// One log file through the thesis observer, streamed (LogStream + ChunkedReplay): memory
// flat in the file's size. `hstmon replay` uses it for one log and for each log of a fleet.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/replay.hpp"

namespace hstmon::cli {

/// What replay_log_file found: the replay, and the reader's notes and error.
struct LogReplay {
  host::ReplayResult result;               ///< over the rows read (all of them unless error)
  std::vector<std::string> notes;          ///< the reader's notes (file:line:column: note: …)
  std::optional<host::LogError> error;     ///< the reader's error, if any
  std::uint64_t file_bytes = 0;            ///< size of the file [bytes], 0 if unknown
};

/// Reads `path` chunk by chunk and replays every chunk as it comes. `progress(f)`, if
/// set, gets the share of the file done after each chunk. With an error, `result` holds
/// the rows before it (a strict read: do not report them; a lenient read: its valid prefix).
LogReplay replay_log_file(const std::string& path, const host::ReadOptions& read_options,
                          const ThesisParams<double>& params, const ThesisInputs<double>& inputs,
                          const host::ReplayOptions& options, const std::function<void(double)>& progress = {});

}  // namespace hstmon::cli
