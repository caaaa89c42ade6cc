#include "cli_log_options.hpp"

#include <fmt/format.h>

#include <string>

#include "cli_validators.hpp"
#include "hstmon_host/log_options.hpp"

namespace hstmon::cli {

void add_log_options(CLI::App& cmd, LogOptionArgs& args, const std::string& params_help,
                     const std::string& params_names) {
  cmd.add_option("--map", args.maps,
                 "Map a log column to a signal: COLUMN=SIGNAL, split at the last '=' (\"p CH=8=p_pp\"), or "
                 "'#N=SIGNAL' for column N from 1 (repeatable)");
  cmd.add_option("--separator", args.separator, "Field separator: , ; or tab (default: detected)");
  cmd.add_flag("--lenient", args.lenient,
               "Skip rows whose time does not increase (noted; more than 5 % of the rows is an error); on any "
               "other bad row, report it and use the rows before it");
  cmd.add_option("--rate", args.rate,
                 "Sample rate [Hz]: rebuild time from the row index (for a time column rounded coarser than the "
                 "sample period, or none)")
      ->check(positive_number());
  cmd.add_option("--encoding", args.encoding,
                 "Encoding of the lines above the data (names, units): utf-8, windows-1250, windows-1252 or "
                 "latin-1 (default: detected; UTF-8, else Windows-1250 for Polish/Czech letters, else 1252)");
  cmd.add_option(params_names, args.params, params_help);
}

std::optional<host::ReadOptions> to_read_options(const LogOptionArgs& args, const char* command) {
  host::ReadOptions ro;
  ro.lenient = args.lenient;
  std::string err;
  if (!args.separator.empty()) err = host::set_separator(ro, args.separator);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon {}: error: --separator {}\n", command, err);
    return std::nullopt;
  }
  if (args.rate != 0.0) err = host::set_rate(ro, args.rate);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon {}: error: --rate {}\n", command, err);
    return std::nullopt;
  }
  if (!args.encoding.empty()) err = host::set_encoding(ro, args.encoding);
  if (!err.empty()) {
    fmt::print(stderr, "hstmon {}: error: --encoding {}\n", command, err);
    return std::nullopt;
  }
  for (const auto& m : args.maps) {
    err = host::add_column_map(ro, m);
    if (!err.empty()) {
      fmt::print(stderr, "hstmon {}: error: --map {}\n", command, err);
      return std::nullopt;
    }
  }
  return ro;
}

std::string capped(const std::string& message, std::size_t max_chars) {
  if (message.size() <= max_chars) return message;
  std::size_t cut = max_chars;
  while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0u) == 0x80u) --cut;  // not inside a code point
  return message.substr(0, cut) + fmt::format("… ({} bytes in all)", message.size());
}

void print_log_messages(const std::string& path, const std::vector<std::string>& notes,
                        const std::optional<host::LogError>& error) {
  for (std::size_t i = 0; i < notes.size() && i < kMaxNotes; ++i) fmt::print(stderr, "{}\n", capped(notes[i]));
  if (notes.size() > kMaxNotes) {
    fmt::print(stderr, "{}: note: … and {} more notes\n", path, notes.size() - kMaxNotes);
  }
  if (error) fmt::print(stderr, "{}\n", capped(error->to_string()));
}

host::LogData read_log_reporting(const std::string& path, const host::ReadOptions& options) {
  host::LogData log = host::read_log(path, options);
  print_log_messages(path, log.notes, log.error);
  return log;
}

}  // namespace hstmon::cli
