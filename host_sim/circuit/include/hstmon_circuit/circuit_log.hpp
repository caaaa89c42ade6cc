#pragma once
/// @file circuit_log.hpp
/// Logs of a circuit: a time column `t[s]`, then any of the circuit's input columns and
/// sensor columns (CircuitInput::column, CircuitSensor::column), each `name[unit]` or
/// `name (unit)` in the header, or a bare name for the unit the circuit file gives the
/// column ("" = SI). The format `hstmon replay` reads and hstmon-sim writes:
///  - plain or gzip-compressed; the lines above the data in UTF-8 (BOM or not) or a
///    Windows code page, converted (ReadOptions::encoding; hstmon_host/text_encoding.hpp);
///  - LF or CRLF; blank lines and lines starting with '#' skipped; a separator at the end
///    of every line allowed (the unnamed last column it leaves is dropped);
///  - separator from the header line: tab if it has one, else ';', else ',' (or given:
///    ReadOptions::separator); a decimal comma where the separator is not ',';
///  - data rows of decimal numbers (blanks around them allowed), time strictly rising
///    (or rebuilt from the row index: ReadOptions::rate);
///  - columns renamed by ReadOptions' maps (by name, or by number), as the thesis logs';
///    a name that matches no column is an error listing the columns.
///  - instrument layouts as the thesis reader finds them (hstmon_host/log_layout.hpp): a
///    units row above or below the names, a block of metadata lines above them (noted);
///    a unit in the units row fills a header cell without one and must agree with one.
/// Columns the circuit does not know are ignored with a note. Every error (bad number,
/// ragged row, unknown unit, duplicated column, no time column, no rows, time not rising,
/// non-finite value, unreadable file) is a SourceError at file:line:column; nothing
/// throws, and the rows before an error are not kept.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::circuit_tools {

/// A circuit log in memory, column-major, SI units.
struct CircuitLog {
  std::string path;                           ///< source name used in messages
  std::vector<double> t;                      ///< time [s], strictly increasing
  std::vector<std::vector<double>> inputs;    ///< by input index; empty when not in the log
  std::vector<std::vector<double>> sensors;   ///< by channel index; empty when not in the log
  std::vector<std::string> notes;             ///< "file:line:col: note: ..." lines
  std::size_t header_line = 0;                ///< 1-based line of the column names (0: none read)
  std::optional<host::SourceError> error;     ///< set when reading failed (then no rows)

  std::size_t rows() const noexcept { return t.size(); }
  bool ok() const noexcept { return !error.has_value(); }
};

/// Reads the log at path for circuit c.
/// @param o  the log options every reader takes (`--separator`, `--map`, `--lenient`,
///           `--rate`; host::ReadOptions), with the same meaning as for the thesis logs:
///           a map's target is a circuit column name (or `t`, or "" to drop); with a rate
///           the time is t0 + i/rate and need not increase (no time column: t0 = 0); a
///           lenient read skips a row whose time does not increase (a note each), keeps
///           the rows before any other bad row (error still set), and refuses the log when
///           it would drop more than 5 % of the rows.
CircuitLog read_circuit_log(const std::string& path, const host::CircuitFile& c, const host::ReadOptions& o = {});

/// Parses log text for circuit c; path_for_messages names it in errors.
CircuitLog parse_circuit_log(std::string_view text, std::string path_for_messages, const host::CircuitFile& c,
                             const host::ReadOptions& o = {});

/// Which of a header's column names (`p_mi[bar]`, `t`, …) a log of circuit c reads: the
/// time, the circuit's inputs and sensors, under o's maps; the others are ignored (with
/// a note). For a log held as columns (a pandas DataFrame): the columns to convert.
/// @param error  set, and the result empty, for a header the reader refuses (its message;
///               line 1, column = the 1-based column number)
std::vector<bool> circuit_log_columns_used(const std::vector<std::string>& names, const host::CircuitFile& c,
                                           const host::ReadOptions& o, std::optional<host::SourceError>& error);

/// A log held as columns, read as parse_circuit_log reads text whose header row is
/// `names`: the same names, units, maps, notes and errors, the same time and value checks
/// (finite, time rising, o.rate, o.lenient), without a text round trip. columns[k] holds
/// `rows` values of column k in its header unit; nullptr where circuit_log_columns_used is
/// false. Errors name `source`, line = the row as a CSV file of these columns would have
/// it (the header line 1, the first row line 2), column = the 1-based column number.
CircuitLog circuit_log_from_columns(const std::vector<std::string>& names, const std::vector<const double*>& columns,
                                    std::size_t rows, std::string source, const host::CircuitFile& c,
                                    const host::ReadOptions& o = {});

/// The log as text: `t[s]`, the present input columns, then the present sensor columns,
/// each in the unit the circuit file gives it (bracketed; none for SI), values "%.9g" (a
/// time that needs more digits to a nanosecond: as many as read back the same number).
/// @param comments  lines written first as "# ..."
std::string circuit_log_text(const host::CircuitFile& c, const CircuitLog& log,
                             const std::vector<std::string>& comments = {});

}  // namespace hstmon::circuit_tools
