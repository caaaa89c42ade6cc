/// @file csv_log_writer.cpp
#include "hstmon_sim/csv_log_writer.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace hstmon::sim {

std::string header_cell(const LogColumn& c) { return c.unit.empty() ? c.name : c.name + "[" + c.unit + "]"; }

std::string format_value(double v) {
  char buf[32];
  const int n = std::snprintf(buf, sizeof buf, "%.10g", v);
  return std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
}

CsvLogWriter::CsvLogWriter(std::ostream& os, std::vector<LogColumn> columns) : os_(os), cols_(std::move(columns)) {
  if (cols_.empty()) throw std::invalid_argument("CsvLogWriter: no columns");
  for (std::size_t i = 0; i < cols_.size(); ++i) {
    if (i > 0) os_ << ',';
    os_ << header_cell(cols_[i]);
  }
  os_ << '\n';
  if (!os_) throw std::runtime_error("CsvLogWriter: write failed");
}

void CsvLogWriter::write_row(const std::vector<double>& values) {
  if (values.size() != cols_.size()) throw std::invalid_argument("CsvLogWriter: row size does not match the columns");
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ',';
    line += format_value(values[i]);
  }
  line += '\n';
  os_ << line;
  if (!os_) throw std::runtime_error("CsvLogWriter: write failed");
}

}  // namespace hstmon::sim
