#pragma once
/// @file text_util.hpp
/// Internal helpers of the host port: positions, trimming, ASCII case, quoting.

#include <cstddef>
#include <string>
#include <string_view>

namespace hstmon::host::detail {

/// A 1-based line and character column.
struct LineCol {
  std::size_t line = 1;    ///< physical line, counted by '\n'
  std::size_t column = 1;  ///< UTF-8 code points from the line start, plus one
};

/// 1-based character column of `pos` in the line starting at `line_start`: counts the
/// bytes in [line_start, pos) that do not continue a UTF-8 sequence.
std::size_t char_column(const char* line_start, const char* pos) noexcept;

/// Line and column of byte `offset` in `text`. A UTF-8 BOM at the start is not counted.
LineCol locate(std::string_view text, std::size_t offset) noexcept;

/// True for ' ' and '\t'.
constexpr bool is_blank(char c) noexcept { return c == ' ' || c == '\t'; }

/// `s` without leading and trailing blanks (' ', '\t').
std::string_view trim(std::string_view s) noexcept;

/// `s` with A–Z mapped to a–z; other bytes unchanged.
std::string ascii_lower(std::string_view s);

/// Equality ignoring ASCII case.
bool iequals(std::string_view a, std::string_view b) noexcept;

/// `s` for a message: at most max_chars bytes (then "...", never inside a character);
/// control bytes and bytes that are not valid UTF-8 shown as \xNN.
std::string printable(std::string_view s, std::size_t max_chars = 40);

}  // namespace hstmon::host::detail
