#pragma once
/// @file text_source.hpp
/// The bytes of a log file as text, whatever the file: plain, or gzip-compressed (known
/// by its magic bytes 1f 8b, not its name), decompressed as it is read. What both log
/// readers read through (the thesis logs', the circuit logs'), streamed or whole.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

/// A log file read front to back. Not copyable; one file per object.
class TextSource {
 public:
  TextSource() = default;
  ~TextSource();
  TextSource(const TextSource&) = delete;
  TextSource& operator=(const TextSource&) = delete;

  /// Opens `path`. An error (no position) when it cannot be opened or is a directory.
  std::optional<SourceError> open(const std::string& path);

  /// Reads up to `n` bytes of text into `dst`: the count, 0 at the end or on an error
  /// (then error() is set, at the line and column of the text where reading broke off).
  std::size_t read(char* dst, std::size_t n);

  /// Set when a read failed (a damaged or truncated gzip stream, an I/O error).
  const std::optional<SourceError>& error() const noexcept { return error_; }
  bool eof() const noexcept { return eof_; }
  /// True when the file is gzip-compressed.
  bool compressed() const noexcept { return compressed_; }
  /// Size of the file on disk [bytes]; 0 when unknown (a pipe).
  std::uint64_t file_size() const noexcept { return file_size_; }
  /// Bytes of the file on disk read so far (compressed bytes for a gzip file).
  std::uint64_t file_offset() const noexcept;

 private:
  void track_position(const char* text, std::size_t n) noexcept;

  std::string path_;
  void* gz_ = nullptr;  ///< zlib's gzFile: reads plain files as they are
  bool compressed_ = false;
  bool eof_ = false;
  std::uint64_t file_size_ = 0;
  std::optional<SourceError> error_;
  std::size_t line_ = 1;    ///< line of the text read so far, for an error's position
  std::size_t column_ = 1;  ///< character column after the last byte read
};

/// The whole text of the log file at `path` (decompressed when it is gzip).
std::optional<SourceError> read_log_text(const std::string& path, std::string& text);

}  // namespace hstmon::host
