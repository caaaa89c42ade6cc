#pragma once
/// @file mem_log.hpp
/// The log reader tests' shorthands: a log given as text, read as the file "mem.csv" (the
/// name its errors and notes carry), and one rpm in rad/s.

#include <string_view>

#include "hstmon_host/log_reader.hpp"

namespace hstmon_test {

/// One revolution per minute [rad/s].
constexpr double kRpm = 2.0 * 3.14159265358979323846 / 60.0;

/// `text` read as the log file "mem.csv".
inline hstmon::host::LogData read(std::string_view text, const hstmon::host::ReadOptions& opt = {}) {
  return hstmon::host::read_log_from_memory(text, "mem.csv", opt);
}

}  // namespace hstmon_test
