#include "text_util.hpp"

#include <cstdio>

#include "utf8_check.hpp"

namespace hstmon::host::detail {

std::size_t char_column(const char* line_start, const char* pos) noexcept {
  std::size_t col = 1;
  for (const char* p = line_start; p < pos; ++p) {
    if ((static_cast<unsigned char>(*p) & 0xC0u) != 0x80u) ++col;
  }
  return col;
}

LineCol locate(std::string_view text, std::size_t offset) noexcept {
  if (offset > text.size()) offset = text.size();
  std::size_t start = (text.substr(0, 3) == "\xEF\xBB\xBF") ? 3 : 0;
  if (offset < start) offset = start;
  LineCol lc;
  std::size_t line_start = start;
  for (std::size_t i = start; i < offset; ++i) {
    if (text[i] == '\n') {
      ++lc.line;
      line_start = i + 1;
    }
  }
  lc.column = char_column(text.data() + line_start, text.data() + offset);
  return lc;
}

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i];
    char y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

std::string printable(std::string_view s, std::size_t max_chars) {
  const bool cut = s.size() > max_chars;
  if (cut) {
    std::size_t end = max_chars;
    while (end > 0 && (static_cast<unsigned char>(s[end]) & 0xC0u) == 0x80u) --end;  // not inside a character
    s = s.substr(0, end);
  }
  std::string out;
  out.reserve(s.size() + 8);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    // A whole UTF-8 character stays as it is (a header in UTF-8, or converted to it).
    const std::size_t n = u >= 0xC2u && u <= 0xDFu ? 2 : u >= 0xE0u && u <= 0xEFu ? 3 : u >= 0xF0u && u <= 0xF4u ? 4 : 0;
    if (n != 0 && i + n <= s.size() && find_invalid_utf8(s.substr(i, n)) == std::string_view::npos) {
      out.append(s.substr(i, n));
      i += n - 1;
    } else if (u < 0x20u || u == 0x7Fu || u >= 0x80u) {
      char buf[8];  // control bytes and binary junk, visibly
      std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(u));
      out += buf;
    } else {
      out += static_cast<char>(u);
    }
  }
  if (cut) out += "...";
  return out;
}

}  // namespace hstmon::host::detail
