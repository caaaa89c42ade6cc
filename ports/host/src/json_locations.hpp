#pragma once
/// @file json_locations.hpp
/// Internal: byte offsets of object keys and values in JSON text, which nlohmann::json
/// does not keep. Used to put file:line:column on semantic errors of parameter files.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace hstmon::host::detail {

/// Offsets of the members of objects up to a fixed depth, keyed by JSON Pointer
/// ("/params/Dm"; '~' and '/' in keys escaped as ~0 and ~1).
struct JsonLocations {
  std::map<std::string, std::size_t> key;    ///< offset of the key's opening quote
  std::map<std::string, std::size_t> value;  ///< offset of the value's first byte
  /// First key repeated within one object: (pointer, offset of the repeat's quote).
  std::optional<std::pair<std::string, std::size_t>> duplicate;
};

/// Walks `text`, which must be valid JSON (parse it with nlohmann first), and records
/// member locations down to `max_depth` levels of objects. Deeper values are skipped
/// without recursion, so any nesting depth is safe.
JsonLocations locate_json_members(std::string_view text, int max_depth = 2);

/// Escapes a key for use in a JSON Pointer.
std::string json_pointer_token(std::string_view key);

}  // namespace hstmon::host::detail
