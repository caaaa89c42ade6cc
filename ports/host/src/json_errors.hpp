#pragma once
/// @file json_errors.hpp
/// Internal: errors of the JSON files (circuit and parameter files) at their place in the text.

#include <cstddef>
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

/// The error `message` at byte `offset` of `text`, read from `path`.
SourceError error_at(std::string_view text, const std::string& path, std::size_t offset, std::string message);

}  // namespace hstmon::host::detail
