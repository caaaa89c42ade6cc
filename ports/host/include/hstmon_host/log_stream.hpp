#pragma once
/// @file log_stream.hpp
/// A log read chunk by chunk, so a one-hour 1 kHz log (3.6 M rows, ~290 MB) never sits
/// in memory whole: the same format, checks, numbers, errors and notes as read_log
/// (log_reader.hpp), in a read buffer of kStreamBufferBytes plus the rows of one chunk.
/// A gzip-compressed file is decompressed into that buffer as it is read.
///
/// Lenient reads and reads with a sample rate (ReadOptions::rate) look at the whole file
/// (the share of rows skipped; the logged span against the rate), so they read it whole
/// as read_log does and hand it over as one chunk; so does a file whose header and first
/// data row are not within the first buffer.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "hstmon_host/log_reader.hpp"

namespace hstmon::host {

/// Bytes read from the file at a time (and the longest line a streamed read takes).
inline constexpr std::size_t kStreamBufferBytes = std::size_t{4} << 20;
/// Rows per chunk unless LogStream::open is told otherwise.
inline constexpr std::size_t kStreamChunkRows = std::size_t{1} << 16;

/// Reads a log file in chunks of rows. Not copyable; one file per object.
class LogStream {
 public:
  LogStream();
  ~LogStream();
  LogStream(const LogStream&) = delete;
  LogStream& operator=(const LogStream&) = delete;

  /// Opens `path` and reads its header (and units row), up to the first data row.
  /// False when no rows can come: the file cannot be opened or its header is bad
  /// (data().error says where). `chunk_rows` (≥ 1) rows at most per chunk; `buffer_bytes`
  /// (≥ 64) read at a time, the longest line it takes (smaller only in tests).
  bool open(const std::string& path, const ReadOptions& options = {}, std::size_t chunk_rows = kStreamChunkRows,
            std::size_t buffer_bytes = kStreamBufferBytes);

  /// Reads the next chunk into data(), dropping the previous chunk's rows. False when no
  /// rows are left or a row is bad: then data().error is set (file:line:column) and a
  /// strict read hands out nothing more (the rows already handed out are not to be
  /// trusted as a whole log: read_log would have kept none).
  bool next();

  /// The current chunk's rows, and the log's header facts (present, source units,
  /// notes, error) as read_log gives them.
  const LogData& data() const noexcept { return data_; }

  /// Rows handed out so far, this chunk included.
  std::size_t rows_read() const noexcept { return rows_read_; }

  /// Share of the file parsed so far, 0…1 (for a progress line; 0 when the size is unknown).
  double fraction() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LogData data_;
  std::size_t rows_read_ = 0;
  bool whole_ = false;      ///< read whole (lenient, rate, or header beyond the first buffer)
  bool done_ = false;
};

}  // namespace hstmon::host
