#include "json_errors.hpp"

#include <utility>

#include "text_util.hpp"

namespace hstmon::host::detail {

std::string json_error_text(const std::string& what) {
  std::size_t start = 0;
  const std::size_t col = what.find("column ");
  if (col != std::string::npos) {
    const std::size_t colon = what.find(": ", col);
    if (colon != std::string::npos) start = colon + 2;
  } else if (!what.empty() && what[0] == '[') {
    const std::size_t close = what.find("] ");
    if (close != std::string::npos) start = close + 2;
  }
  return "JSON: " + printable(what.substr(start), 200);
}

std::size_t first_non_blank(std::string_view text) noexcept {
  std::size_t i = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) ++i;
  return i;
}

SourceError error_at(std::string_view text, const std::string& path, std::size_t offset, std::string message) {
  const LineCol lc = locate(text, offset);
  return SourceError{path, lc.line, lc.column, std::move(message)};
}

}  // namespace hstmon::host::detail
