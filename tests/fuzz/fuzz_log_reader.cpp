// libFuzzer target: the log reader (read_log_from_memory) on arbitrary text.
// The first byte picks the ReadOptions (separator, lenient, a column map), the rest is
// the log text. Invariants: never crash (ASan/UBSan watch memory and UB); an error has
// a position with line ≥ 1 and column ≥ 1, or none at all (line = column = 0); a
// strict read that fails keeps no rows; every kept value is finite, the time column is
// strictly increasing, and every present column has one value per row.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hstmon_host/log_reader.hpp"

namespace {
[[noreturn]] void fail(const char* what, const hstmon::host::LogData& d) {
  std::fprintf(stderr, "fuzz_log_reader invariant violated: %s\n", what);
  if (d.error) std::fprintf(stderr, "  error: %s\n", d.error->to_string().c_str());
  std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hstmon::host;
  if (size == 0) return 0;
  const std::uint8_t sel = data[0];
  ReadOptions o;
  static const char seps[4] = {0, ',', ';', '\t'};
  o.separator = seps[sel & 3u];
  o.lenient = (sel & 4u) != 0;
  if (sel & 8u) o.column_map = {{"Druck_A", "p_mi"}, {"speed", "w_m"}, {"junk", ""}};
  if (sel & 16u) o.column_map["P_MI"] = "p_mo";  // may collide with a real p_mo column
  if (sel & 32u) {  // issue 16: time from the sample rate, a column by number
    o.rate = 4800.0;
    o.column_number_map = {{2, "p_pp"}};
  }
  // The text is passed as is, not NUL-terminated (the API allows that), so a read one
  // past the end is caught. HSTMON_FUZZ_PAD=1 passes a std::string copy instead (its
  // terminator hides an over-read by one byte) to fuzz past a known over-read.
  static const bool pad = std::getenv("HSTMON_FUZZ_PAD") != nullptr;
  std::string copy;
  std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  if (pad) {
    copy.assign(text);
    text = copy;
  }
  const LogData d = read_log_from_memory(text, "fuzz.csv", o);

  if (d.error) {
    const auto& e = *d.error;
    const bool no_pos = e.line == 0 && e.column == 0;
    if (!no_pos && (e.line < 1 || e.column < 1)) fail("error position has line or column 0", d);
    if (e.message.empty()) fail("error without a message", d);
    if (!o.lenient && d.rows() != 0) fail("strict read with an error kept rows", d);
  }
  const std::size_t n = d.rows();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(d.t[i])) fail("non-finite time", d);
    if (i > 0 && !(d.t[i] > d.t[i - 1])) fail("time not strictly increasing", d);
  }
  for (std::size_t s = 1; s < kSignalCount; ++s) {
    if (!d.present[s]) continue;
    if (d.values[s].size() != n) fail("column length differs from row count", d);
    for (double v : d.values[s]) {
      if (!std::isfinite(v)) fail("non-finite value kept", d);
    }
  }
  return 0;
}
