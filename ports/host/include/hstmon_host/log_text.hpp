#pragma once
/// @file log_text.hpp
/// A log file's whole text in memory, as cheaply as the file allows: a plain file is
/// mapped read-only (no copy into the process, no zero-fill, pages shared with the page
/// cache), a gzip-compressed one is decompressed into memory (text_source.hpp). For a
/// reader that wants the text at once (the circuit log reader parses a string_view).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

/// The text of one log file; the view lives as long as the object. Not copyable.
class LogText {
 public:
  LogText() = default;
  ~LogText();
  LogText(const LogText&) = delete;
  LogText& operator=(const LogText&) = delete;

  /// The text (empty before load_log_text, or for an empty file).
  std::string_view view() const noexcept {
    return map_ != nullptr ? std::string_view(static_cast<const char*>(map_), map_size_) : std::string_view(owned_);
  }
  /// True when the file is mapped (a plain regular file), false when its text was read.
  bool mapped() const noexcept { return map_ != nullptr; }

 private:
  friend std::optional<SourceError> load_log_text(const std::string& path, LogText& text);
  void release() noexcept;

  std::string owned_;         ///< the text read (compressed files, pipes, or where mapping failed)
  void* map_ = nullptr;       ///< the mapping of a plain file
  std::size_t map_size_ = 0;  ///< its length [bytes]
};

/// Loads the log file at `path` into `text` (replacing what it held): mapped when it is a
/// plain regular file, else read and decompressed as read_log_text does, with its errors;
/// a text too large for memory is an error too ("cannot read: ..."), not an exception.
/// A file must not be truncated by another program while mapped (the mapping's pages past
/// the new end no longer exist); logs are written before they are read.
std::optional<SourceError> load_log_text(const std::string& path, LogText& text);

}  // namespace hstmon::host
