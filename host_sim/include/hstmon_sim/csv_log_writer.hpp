#pragma once
/// @file csv_log_writer.hpp
/// Minimal CSV log writer: a header row of `name[unit]` cells, then one row of numbers per
/// sample printed with "%.10g" (non-finite values as nan / inf / -inf). Kept inside host_sim
/// so the simulator does not depend on the host port's log library (to be merged later).

#include <ostream>
#include <string>
#include <vector>

namespace hstmon::sim {

/// One column of a log.
struct LogColumn {
  std::string name;  ///< column name, e.g. "p_mi"
  std::string unit;  ///< unit, e.g. "bar"; empty for a dimensionless column (no brackets)
};

/// Header cell of a column: "name[unit]", or "name" when the unit is empty.
std::string header_cell(const LogColumn& c);

/// Formats one value as "%.10g".
std::string format_value(double v);

/// Writes a CSV log to a stream. Not copyable.
class CsvLogWriter {
 public:
  /// Writes the header row at once.
  /// @throws std::invalid_argument if there are no columns
  CsvLogWriter(std::ostream& os, std::vector<LogColumn> columns);
  CsvLogWriter(const CsvLogWriter&) = delete;
  CsvLogWriter& operator=(const CsvLogWriter&) = delete;

  /// Writes one row; `values` must have one entry per column.
  /// @throws std::invalid_argument on a size mismatch; std::runtime_error if the stream fails
  void write_row(const std::vector<double>& values);

  /// The columns.
  const std::vector<LogColumn>& columns() const noexcept { return cols_; }

 private:
  std::ostream& os_;
  std::vector<LogColumn> cols_;
};

}  // namespace hstmon::sim
