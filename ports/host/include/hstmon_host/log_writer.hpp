#pragma once
/// @file log_writer.hpp
/// Writer for logs in the format log_reader.hpp reads: header `name[unit]`, one row per
/// sample, values converted from SI to each column's unit and printed like printf
/// "%.9g" (std::to_chars). Used by the simulator and for residual output.

#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/signals.hpp"
#include "hstmon_host/source_error.hpp"
#include "hstmon_host/units.hpp"

namespace hstmon::host {

/// One output column.
struct CsvColumn {
  std::string name;                      ///< column name (canonical signal name or any other)
  Quantity quantity = Quantity::kNone;   ///< decides which units are valid
  std::string unit;                      ///< unit written and converted to; "" = SI, no brackets
};

/// Column for a known signal, in `unit` ("" = SI).
CsvColumn column_for(Signal s, std::string unit = {});

/// Options of CsvWriter and write_log.
struct WriteOptions {
  char separator = ',';             ///< ',', ';' or '\t'
  bool decimal_comma = false;       ///< write "1,5" (only with ';' or '\t')
  int precision = 9;                ///< significant digits ("%.9g"); 0 = shortest round-trip
  std::vector<std::string> comments;  ///< lines written first as "# ..." (reader skips them)
};

/// Row-by-row CSV writer. Output is buffered and written in large blocks. Non-finite
/// values are written as "nan"/"inf"/"-inf" (which log_reader refuses; use them only in
/// outputs that are not read back as logs). Move-only; the destructor closes.
class CsvWriter {
 public:
  CsvWriter() = default;
  ~CsvWriter();
  CsvWriter(CsvWriter&& other) noexcept;
  CsvWriter& operator=(CsvWriter&& other) noexcept;
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// Creates (truncates) the file at `path` and writes the comments and header.
  /// @return an error for a bad unit, separator or I/O failure (writer stays closed)
  std::optional<SourceError> open(const std::string& path, std::vector<CsvColumn> columns,
                                  const WriteOptions& options = {});

  /// As open(), but the output is kept in memory (see str()).
  std::optional<SourceError> open_memory(std::vector<CsvColumn> columns,
                                         const WriteOptions& options = {});

  /// Writes one row of `count` SI values, one per column.
  /// @return false if the writer is not open, count differs from the column count, or a
  ///         write failed (error() says which); the row is then not written
  bool write_row(const double* values, std::size_t count);
  /// Writes one row from a list of SI values.
  bool write_row(std::initializer_list<double> values) { return write_row(values.begin(), values.size()); }
  /// Writes one row from a vector of SI values.
  bool write_row(const std::vector<double>& values) { return write_row(values.data(), values.size()); }

  /// Flushes and closes the file (memory output stays readable).
  /// @return the first error seen since open(), if any
  std::optional<SourceError> close();

  /// Text written so far in memory mode (empty for file output).
  const std::string& str() const noexcept { return buffer_; }
  /// First error since open(), if any.
  const std::optional<SourceError>& error() const noexcept { return error_; }
  /// Data rows written since open().
  std::size_t rows_written() const noexcept { return rows_; }
  /// True between a successful open() and close().
  bool is_open() const noexcept { return open_; }

 private:
  std::optional<SourceError> start(std::vector<CsvColumn> columns, const WriteOptions& options);
  bool flush_buffer();
  void set_error(std::string message);

  std::string path_;
  std::FILE* file_ = nullptr;
  bool memory_ = false;
  bool open_ = false;
  std::string buffer_;
  std::vector<UnitConversion> conv_;
  WriteOptions options_;
  std::size_t rows_ = 0;
  std::optional<SourceError> error_;
};

/// Writes the present signals of `log` (time first, then signal order) to `path`.
/// `units` picks the unit per signal (missing = SI).
std::optional<SourceError> write_log(const std::string& path, const LogData& log,
                                     const std::map<Signal, std::string>& units = {},
                                     const WriteOptions& options = {});

/// As write_log, into `out` (replaced).
std::optional<SourceError> write_log_to_string(std::string& out, const LogData& log,
                                               const std::map<Signal, std::string>& units = {},
                                               const WriteOptions& options = {});

}  // namespace hstmon::host
