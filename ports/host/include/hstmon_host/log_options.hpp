#pragma once
/// @file log_options.hpp
/// The log options of every command that reads a log (`--map`, `--separator`, `--rate`)
/// as text → ReadOptions. One parser, so `replay`, `identify` and `gap` mean the same.

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

}  // namespace hstmon::host
