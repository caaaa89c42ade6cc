#pragma once
/// @file fw_json.hpp
/// Pieces of the firmware replays' output, shared by fw_replay.cpp (the thesis monitor)
/// and fw_circuit_monitor.cpp (a circuit's): a bounded JSON line builder and the
/// per-channel residual statistics of the host replay. Portable, no heap, no I/O.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fw_replay.hpp"
#include "hstmon/residual_stats.hpp"

namespace hstmon::fw {

/// Names of the observer's HealthFlag bits 0 … 5, as host::health_names prints them.
inline constexpr const char* const kHealthNames[] = {"input_non_finite",  "measurement_non_finite",
                                                     "substeps_clipped",  "state_non_finite",
                                                     "state_out_of_bounds", "algebraic_diverged"};
inline constexpr int kHealthNameCount = static_cast<int>(sizeof kHealthNames / sizeof kHealthNames[0]);

/// One JSON line at a time, assembled in a fixed buffer and handed to the sink.
class Line {
 public:
  explicit Line(Sink out) noexcept : out_(out) {}
  Line& raw(const char* s) noexcept {
    while (*s != '\0' && n_ + 1 < sizeof(buf_)) buf_[n_++] = *s++;
    buf_[n_] = '\0';
    return *this;
  }
  Line& key(const char* k) noexcept {
    raw(first_ ? "\"" : ",\"").raw(k).raw("\":");
    first_ = false;
    return *this;
  }
  Line& str(const char* k, const char* v) noexcept { return key(k).raw("\"").raw(v).raw("\""); }
  Line& num(const char* k, double v) noexcept {
    char b[32];
    format_double(b, v);
    return key(k).raw(b);
  }
  Line& uint(const char* k, std::uint64_t v) noexcept {
    char b[24];
    format_uint(b, v);
    return key(k).raw(b);
  }
  Line& boolean(const char* k, bool v) noexcept { return key(k).raw(v ? "true" : "false"); }
  /// Closes the object and hands the line to the sink.
  void end() noexcept { raw("}\n").flush(); }
  /// Hands the buffer to the sink as it is (for non-JSON lines).
  void flush() noexcept {
    out_(buf_);
    n_ = 0;
    first_ = true;
    buf_[0] = '\0';
  }
  Line& begin() noexcept { return raw("{"); }
  /// The next key is the first of a nested object (no comma before it).
  Line& first_key() noexcept {
    first_ = true;
    return *this;
  }

 private:
  Sink out_;
  char buf_[640] = {};  // an event line with 8 candidates is ≈ 450 characters
  std::size_t n_ = 0;
  bool first_ = true;
};

/// Writes the key "health" and the names of the bits set in `health` as a JSON array, as
/// host::health_names lists them (both replays' header lines carry it).
inline void write_health(Line& line, std::uint32_t health) noexcept {
  line.key("health").raw("[");
  bool first = true;
  for (int bit = 0; bit < kHealthNameCount; ++bit) {
    if (health & (1u << bit)) {
      line.raw(first ? "\"" : ",\"").raw(kHealthNames[bit]).raw("\"");
      first = false;
    }
  }
  line.raw("]");
}

/// Residual statistics of one channel, as the host replay counts them (host::ChannelStats).
using Stats = ResidualStats<double>;

}  // namespace hstmon::fw
