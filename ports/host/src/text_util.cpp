#include "text_util.hpp"

#include <cstdio>

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
  if (cut) s = s.substr(0, max_chars);
  std::string out;
  out.reserve(s.size() + 8);
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20u || u == 0x7Fu || u >= 0x80u) {
      // Non-ASCII is escaped too: the text may be cut mid-sequence or be binary junk.
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(u));
      out += buf;
    } else {
      out += c;
    }
  }
  if (cut) out += "...";
  return out;
}

}  // namespace hstmon::host::detail
