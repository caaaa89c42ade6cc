#pragma once
/// @file log_reader.hpp
/// Reader for measurement logs: delimited text (CSV, semicolon or tab separated), one
/// header row of column names with optional units, optionally a units row, then one
/// row per sample. Values are converted to SI on read and stored column-major.
///
/// Format accepted:
///  - a plain or gzip-compressed file (text_source.hpp; known by its magic bytes);
///  - optional UTF-8 BOM; LF or CRLF line ends; blank lines and lines whose first
///    non-blank character is '#' are skipped anywhere;
///  - the lines above the first data row in UTF-8, or in Windows-1250/-1252 or Latin-1
///    (detected, or ReadOptions::encoding), converted to UTF-8 (text_encoding.hpp);
///  - a separator at the end of every line: the empty, unnamed last column it leaves is
///    dropped (a value in it is an error);
///  - header: `t[s],p_sup[bar],kp,p_mi[bar],...`; a unit in brackets `name[unit]` or
///    parentheses `name (unit)`; no unit = SI; names may be double-quoted (without a
///    separator inside the quotes);
///  - separator auto-detected from the header line: tab if it has one, else ';' if it
///    has one, else ','. Where the separator is not ',', a decimal comma is accepted;
///  - units row (HBM catman / Spider8 exports): a line right after the header whose
///    fields are all non-numeric or empty (at least one non-empty) gives the units;
///  - or the units row right ABOVE the names (as a Spider8 writes it): of two such lines
///    before the first data row, the one with more fields that are units (bar, s, V, …)
///    is the units row;
///  - metadata lines above the header (HYDAC HMG exports: "Device;HMG 4000", …): the
///    header is the last line before the first data row with one non-numeric field per
///    data field (with its units row next to it, if any); the lines above are noted once
///    and ignored. Looked for up to 64 lines;
///  - data fields: decimal numbers (leading '+' and blanks around the number allowed).
/// Errors (bad number, ragged row, unknown unit, time not strictly increasing, nan/inf,
/// empty file, no data rows, NUL bytes or invalid UTF-8, duplicated or missing columns, a
/// column map entry that matches no column — these two list the columns there are)
/// carry file:line:column; nothing throws.
///
/// Lenient reads (ReadOptions::lenient): a row whose time is not above the time of the
/// last kept row — a repeated timestamp, or time going backwards — is skipped with a note
/// (`file:line:column: note: time not strictly increasing: …; row skipped`) and reading
/// goes on; the read stays ok. The row must be well-formed otherwise, and the time
/// compared with is the last *kept* one, so after a clock reset every row up to the old
/// time is skipped (the first 20 with a note each, then one closing note with the count;
/// LogData::skipped_rows has it too). Any other bad row stops a lenient read there: the
/// rows before it are kept and the error is set. Strict reads fail on all of these.
/// A lenient read never drops most of a file quietly: when it would skip more than 5 %
/// of the rows (and more than 10), it fails at the first skipped row, keeps no rows and
/// names the sample rate option (ReadOptions::rate, `--rate HZ`) as the fix; so does the
/// strict error for a time that does not increase.
///
/// Messages stay short: a field is quoted to at most 40 bytes, and unknown columns get
/// a note each only for the first 8 (then one note with the count).
///
/// Numbers are bit-identical to std::from_chars. The common row (plain numbers, no
/// blanks) takes a fast path — field boundaries 16 bytes at a time, then the numbers —
/// with the same result as the general one.

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_host/signals.hpp"
#include "hstmon_host/source_error.hpp"
#include "hstmon_host/text_encoding.hpp"

namespace hstmon::host {

/// Options of read_log / read_log_from_memory.
struct ReadOptions {
  /// Field separator: ',', ';' or '\t'; 0 = detect from the header line.
  char separator = 0;
  /// false: any error leaves the result with no rows. true: a row with time not above
  /// the last kept row's is skipped with a note; reading stops at any other bad data row
  /// and the rows before it are kept (error is still set).
  bool lenient = false;
  /// Log column name → canonical signal name, e.g. {"Druck_A", "p_mi"}. Keys and
  /// targets match ignoring ASCII case (keys also the width of blank runs: "Time CH=1"
  /// finds "Time  CH=1"). A target of "" drops the column without a note. A key that
  /// names no column is an error.
  std::map<std::string, std::string> column_map;
  /// Column number (1-based, as in the header) → canonical signal name, e.g. {8, "p_pp"};
  /// for names that repeat or are awkward to type. Wins over a column_map entry for the
  /// same column; a number beyond the header's columns is an error.
  std::map<std::size_t, std::string> column_number_map;
  /// Sample rate [Hz]; 0 = time from the log's time column. > 0: time is rebuilt from
  /// the row index, t = t0 + i/rate, t0 the first row's logged time (0 when no column
  /// gives t); the logged time then need not increase (a Spider8 rounds it to 1 ms at
  /// 4800 Hz), and a logged span that disagrees with the rate gets a note.
  double rate = 0.0;
  /// Encoding of the lines above the first data row (text_encoding.hpp); they are
  /// converted to UTF-8 before they are read. kDetect: UTF-8, Windows-1250 or -1252.
  TextEncoding encoding = TextEncoding::kDetect;
};

/// A log read into memory, column-major, in SI units.
struct LogData {
  std::string path;                                        ///< source name used in messages
  std::vector<double> t;                                   ///< time [s], strictly increasing
  /// Per signal (index(Signal)), values in SI; empty unless present. The time column
  /// lives in `t`; values[index(Signal::kT)] stays empty.
  std::array<std::vector<double>, kSignalCount> values;
  std::array<bool, kSignalCount> present{};                ///< signal had a column
  std::array<std::string, kSignalCount> source_units;      ///< unit as written ("" = SI)
  std::array<std::size_t, kSignalCount> source_columns{};  ///< 1-based field index, 0 if absent
  std::vector<std::string> notes;                          ///< "file:line:col: note: ..." lines
  std::optional<LogError> error;                           ///< set when reading failed
  std::size_t header_line = 0;                             ///< 1-based line of the header row
  std::size_t skipped_rows = 0;  ///< rows a lenient read skipped (time not strictly increasing)

  /// Number of data rows kept.
  std::size_t rows() const noexcept { return t.size(); }
  /// True when the whole file was read without error.
  bool ok() const noexcept { return !error.has_value(); }
  /// True when signal s had a column (always true for kT in a successful read).
  bool has(Signal s) const noexcept { return present[index(s)]; }
  /// Values of signal s in SI (`t` for Signal::kT); empty if absent.
  const std::vector<double>& column(Signal s) const noexcept {
    return s == Signal::kT ? t : values[index(s)];
  }
};

/// Reads and parses the log file at `path` (whole file into memory, then
/// read_log_from_memory). An unreadable file gives an error with line 0. For a log too
/// long to hold, LogStream (log_stream.hpp) reads it chunk by chunk, with the same result.
LogData read_log(const std::string& path, const ReadOptions& options = {});

/// Parses log text held in memory. `path_for_messages` names the source in errors and
/// notes. Single pass, no per-field allocation; the text need not be NUL-terminated.
LogData read_log_from_memory(std::string_view text, std::string path_for_messages,
                             const ReadOptions& options = {});

}  // namespace hstmon::host
