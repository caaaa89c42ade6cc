#pragma once
/// @file log_layout.hpp
/// Where a delimited log's column names and units are: the rules both log readers follow
/// (the thesis rig's, log_reader.hpp, and a circuit's, host_sim/circuit circuit_log.hpp).
/// Besides the usual layout (names on the first line, perhaps a units row right below),
/// instrument exports put a units row above the names (HBM catman/Spider8) or a block of
/// metadata lines above the header (HYDAC HMG, "key;value" lines). The decision looks at
/// the content lines before the first data row.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace hstmon::host {

/// One field of a header, units or data row.
struct LogField {
  std::string_view text;  ///< trimmed, unquoted
  const char* pos;        ///< first byte of the raw field (for its column)
};

/// Splits `line` at `sep`; each field trimmed and unquoted.
std::vector<LogField> split_log_fields(std::string_view line, char sep);

/// True when the whole field is a number (blanks, '+', a decimal comma if allowed).
bool log_field_is_number(std::string_view s, bool decimal_comma) noexcept;

/// The separator of a header line: tab if it has one, else ';', else ','.
char detect_log_separator(std::string_view header) noexcept;

/// Only characters of numbers and separators, and a digit: a data row candidate.
bool looks_like_data_row(std::string_view line) noexcept;

/// No field a number and at least one non-empty: a names or units row.
bool is_text_row(std::string_view line, char sep, bool decimal_comma);

/// Fields that name a unit: one the port converts, or a common instrument unit it does
/// not (a Spider8 channel left in volts). Tells a units row from a names row.
std::size_t unit_score(std::string_view line, char sep);

/// True for the header cell that a trailing separator leaves (`t,p_mi,`): the last of
/// two or more, with no name and no unit. Such a column is dropped; its fields must be
/// empty (kUnnamedValueMessage otherwise).
bool is_trailing_empty_column(std::size_t index, std::size_t count, std::string_view cell) noexcept;

/// The error for a value in that column.
inline constexpr const char* kUnnamedValueMessage =
    "value in the last column, which has no name (the header ends with a separator)";

/// Content lines looked at before the first data row.
inline constexpr std::size_t kMaxPreambleLines = 64;

/// A layout other than the usual one, found above the first data row.
struct PreambleLayout {
  char sep = ',';                     ///< field separator
  bool decimal_comma = false;         ///< sep is not ','
  std::size_t names = 0;              ///< index in the block of the column names
  std::optional<std::size_t> units;   ///< index in the block of the units row, if any
  /// Lines of the block above the names and units: metadata, not columns.
  std::size_t metadata() const noexcept { return units ? (names < *units ? names : *units) : names; }
};

/// Decides the layout from the content lines before the first data row (`block`, at least
/// one, in file order) and that row (`data`, looks_like_data_row).
/// @param sep_option  the separator given (ReadOptions::separator), 0 = detect
/// @return the layout, or nothing for the usual one (names on block[0]; a units row right
///         below is the caller's to take)
std::optional<PreambleLayout> detect_preamble_layout(const std::vector<std::string_view>& block, std::string_view data,
                                                     char sep_option);

}  // namespace hstmon::host
