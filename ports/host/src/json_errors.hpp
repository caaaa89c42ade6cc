#pragma once
/// @file json_errors.hpp
/// Internal: errors of the JSON files (circuit and parameter files) at their place in the text.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "hstmon_host/source_error.hpp"

namespace hstmon::host::detail {

/// "JSON: " and nlohmann::json's exception text without its "[json.exception.x.n] ...
/// line L, column C: " prefix (the SourceError gives the place), printable, at most 200 characters.
std::string json_error_text(const std::string& what);

/// Offset of the first byte of `text` that is no blank, line end or UTF-8 BOM: where an
/// error about the whole document points.
std::size_t first_non_blank(std::string_view text) noexcept;

/// Why a JSON text did not parse, and the byte it points at.
struct JsonParseError {
  std::size_t offset;
  std::string message;  ///< json_error_text's
};

/// Parses `text` into `j` (a nlohmann::json type); nullopt when it parsed. A syntax error
/// points at its byte; any other parse error (a number overflow) has none, and
/// `unplaced(what)` chooses the offset from the exception's text.
template <class Json, class Place>
std::optional<JsonParseError> parse_json(std::string_view text, Json& j, Place unplaced) {
  try {
    j = Json::parse(text.begin(), text.end());
    return std::nullopt;
  } catch (const typename Json::parse_error& e) {
    return JsonParseError{e.byte > 0 ? e.byte - 1 : 0, json_error_text(e.what())};
  } catch (const typename Json::exception& e) {
    const std::string what = e.what();
    return JsonParseError{unplaced(what), json_error_text(what)};
  }
}

/// The error `message` at byte `offset` of `text`, read from `path`.
SourceError error_at(std::string_view text, const std::string& path, std::size_t offset, std::string message);

}  // namespace hstmon::host::detail
