#pragma once
/// @file source_error.hpp
/// A located error in a text source (log file, parameter file): what every reader of
/// the host port returns instead of throwing.

#include <cstddef>
#include <string>

namespace hstmon::host {

/// An error at a position in a named source. Positions are 1-based: line is the
/// physical line (counted by '\n'), column the character (UTF-8 code point) within it.
/// line = 0 means the error has no position (e.g. the file cannot be opened).
struct SourceError {
  std::string file;         ///< path (or the name given for in-memory text)
  std::size_t line = 0;     ///< 1-based physical line; 0 = no position
  std::size_t column = 0;   ///< 1-based character column; 0 = no position
  std::string message;      ///< what is wrong, without position or "error:" prefix

  /// "file:line:column: error: message", or "file: error: message" when line is 0.
  std::string to_string() const;
};

/// Errors of the log reader and writer are SourceErrors.
using LogError = SourceError;

}  // namespace hstmon::host
