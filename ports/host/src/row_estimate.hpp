#pragma once
/// @file row_estimate.hpp
/// Internal: how many rows to reserve for a log's data, so that its columns are filled
/// without regrowing (each regrowth copies every value read so far). Shared by the
/// thesis log reader and the circuit log reader.

#include <algorithm>
#include <cstddef>

namespace hstmon::host::detail {

/// Rows to reserve for the data in [p, end): the line density of the first 256 KiB
/// scaled to the whole text, with 10 % margin (exact for small texts). A longer tail
/// only costs one regrowth; counting every line would cost a full pass.
inline std::size_t estimate_rows(const char* p, const char* end) noexcept {
  constexpr std::size_t kSample = std::size_t{256} << 10;
  const auto total = static_cast<std::size_t>(end - p);
  const std::size_t sample = std::min(total, kSample);
  const auto lines = static_cast<std::size_t>(std::count(p, p + sample, '\n')) + 1;
  if (sample == total) return lines;
  const double per_byte = static_cast<double>(lines) / static_cast<double>(sample);
  return static_cast<std::size_t>(per_byte * static_cast<double>(total) * 1.1) + 16;
}

}  // namespace hstmon::host::detail
