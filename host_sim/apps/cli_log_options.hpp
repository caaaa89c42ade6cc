#pragma once
// The log options of every hstmon command that reads a thesis-rig log (`replay`,
// `identify`, `gap`): one registration, one meaning, one message style. README "Log
// format" documents them.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::cli {

/// The log options as given on the command line.
struct LogOptionArgs {
  std::vector<std::string> maps;  ///< --map COLUMN=SIGNAL or '#N=SIGNAL', repeatable
  std::string separator;          ///< --separator , ; or tab ("" = detect)
  bool lenient = false;           ///< --lenient
  double rate = 0.0;              ///< --rate HZ: time from the row index [Hz]; 0 = from the log
  std::string encoding;           ///< --encoding of the header lines ("" = detect)
  std::string params;             ///< --params FILE (JSON parameter file)
};

/// Registers --map, --separator, --lenient, --rate, --encoding and --params on `cmd`, with the same
/// help everywhere. `params_names` lets a command keep an old spelling as an alias
/// (identify: "--params,--prior"); `params_help` says what the file is for there.
void add_log_options(CLI::App& cmd, LogOptionArgs& args, const std::string& params_help,
                     const std::string& params_names = "--params");

/// ReadOptions from the arguments. A bad value prints `hstmon COMMAND: error: --opt …`
/// and gives nullopt (the command then exits with kExitUsage).
std::optional<host::ReadOptions> to_read_options(const LogOptionArgs& args, const char* command);

/// Reads a log and prints its notes and error to stderr, every one as
/// `file:line:column: note|error: …`, at most a few lines each and at most kMaxNotes
/// notes (then a count). The caller decides what an error means for it.
host::LogData read_log_reporting(const std::string& path, const host::ReadOptions& options);

/// Prints a log's notes and error to stderr as read_log_reporting does.
void print_log_messages(const std::string& path, const std::vector<std::string>& notes,
                        const std::optional<host::LogError>& error);

/// `message` cut to at most max_chars bytes (on a UTF-8 boundary) with "… (N bytes)"
/// appended: no message fills a screen.
std::string capped(const std::string& message, std::size_t max_chars = 400);

/// Notes printed per log before "… and N more notes".
inline constexpr std::size_t kMaxNotes = 30;

}  // namespace hstmon::cli
