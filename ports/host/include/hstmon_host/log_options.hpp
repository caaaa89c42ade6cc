#pragma once
/// @file log_options.hpp
/// The log options of every command that reads a log (`--map`, `--separator`, `--rate`)
/// as text → ReadOptions. One parser, so `replay`, `identify` and `gap` mean the same.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::host {

/// Adds one column map entry written `COLUMN=SIGNAL` to `options`:
///  - `#N=SIGNAL` maps column N (1-based, as in the header), whatever its name;
///  - otherwise the text is split at its LAST '=', so a name may hold '=':
///    `p CH=8=p_pp` maps the column named `p CH=8` to p_pp.
/// SIGNAL is a canonical name (t, p_mi, …; checked when the log is read). Returns "" on
/// success, else why the entry was refused.
std::string add_column_map(ReadOptions& options, std::string_view entry);

/// True when a column map key names a header column: equal ignoring ASCII case and the
/// width of blank runs, blanks around the key ignored ("Time Spider8_1 CH=1" names a
/// Spider8's "Time  Spider8_1 CH=1"). The rule of every log reader (the thesis logs',
/// the circuit logs').
bool column_name_matches(std::string_view key, std::string_view name) noexcept;

/// Sets the field separator from `,`, `;`, `tab`, `\t` (the two characters) or a tab
/// character. Returns "" on success, else why it was refused.
std::string set_separator(ReadOptions& options, std::string_view text);

/// Sets the sample rate [Hz] (ReadOptions::rate); must be finite and > 0. Returns ""
/// on success, else why it was refused.
std::string set_rate(ReadOptions& options, double rate_hz);

/// Sets the encoding of the log's head (ReadOptions::encoding) from `utf-8`,
/// `windows-1250`, `windows-1252` or `latin-1`. Returns "" on success, else why not.
std::string set_encoding(ReadOptions& options, std::string_view text);

/// The error for a column map entry that names no header column: the entry and the
/// columns there are, quoted, so a typo or a name in another spelling shows at once.
/// @param key      the entry's column name as given
/// @param columns  the header's column names, in order
std::string unmatched_map_message(std::string_view key, const std::vector<std::string_view>& columns);

/// "the columns are 'a', 'b', …" (the first two dozen, then the count): what an error
/// about a column that is not there appends.
std::string listed_columns(const std::vector<std::string_view>& columns);

/// How many notes a read writes, and how many rows a lenient read may skip: the rules of
/// every log reader, so that one file gives the same messages through every command.
struct LogNoteRules {
  /// Unknown columns that get a note of their own (then one note with the count).
  static constexpr std::size_t kMaxColumnNotes = 8;
  /// Skipped rows that get a note of their own (a clock reset can skip thousands).
  static constexpr std::size_t kMaxSkipNotes = 20;
  /// A lenient read fails when it would skip more than this share of the rows [%] ...
  static constexpr std::size_t kMaxSkipPercent = 5;
  /// ... and more than this many (a short log may have a glitch or two).
  static constexpr std::size_t kFreeSkips = 10;
};

/// True when a lenient read that skipped `skipped` of `total` rows (time not strictly
/// increasing) must fail instead (LogNoteRules): its time column cannot be used.
bool lenient_skips_too_many(std::size_t skipped, std::size_t total) noexcept;

/// The error of such a read, placed at its first skipped row.
std::string lenient_refusal_message(std::size_t skipped, std::size_t total);

/// The closing note of a read that skipped more rows than have a note of their own.
std::string skipped_rows_note(std::size_t skipped);

/// The closing note of a header with more unknown columns than have a note of their own.
/// @param what  what they are not, e.g. "known signals"
std::string ignored_columns_note(std::size_t ignored, std::string_view what);

/// What is wrong with a data field that is no number: "empty field", "number out of range
/// 'TEXT'" or "bad number 'TEXT'", then " in column 'COLUMN'" (both quoted shortened to
/// printable text, as every reader's messages).
std::string bad_number_message(std::string_view text, std::string_view column, bool out_of_range);

/// What is wrong with a number that is not finite in SI: "non-finite value 'TEXT'" (nan,
/// inf as written), or "value out of range after unit conversion 'TEXT'", then the column.
/// @param written_finite  the number as written was finite (the unit overflowed it)
std::string non_finite_message(std::string_view text, std::string_view column, bool written_finite);

}  // namespace hstmon::host
