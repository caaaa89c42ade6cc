// The embedded log through the circuit engine, one exact trace line per row
// (fw_circuit.hpp: circuit_replay_trace).
#include <cstddef>
#include <cstring>

#include "fw_circuit.hpp"

namespace hstmon::fw {

namespace {

// FNV-1a 64 over bytes: a cheap, exact fingerprint of every residual of the replay.
void fnv1a(std::uint64_t& h, const void* p, std::size_t n) noexcept {
  const auto* b = static_cast<const unsigned char*>(p);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
}

// A bounded output line.
struct Out {
  char buf[256];
  std::size_t n = 0;
  void put(const char* s) noexcept {
    while (*s != '\0' && n + 1 < sizeof buf) buf[n++] = *s++;
    buf[n] = '\0';
  }
  void uint(std::uint64_t v) noexcept {
    char b[24];
    (void)format_uint(b, v);
    put(b);
  }
};

}  // namespace

std::uint32_t circuit_replay_trace(CircuitFwObserver& obs, const LogView& log, Sink out) noexcept {
  using Inputs = CircuitFwObserver::Inputs;
  using Meas = CircuitFwObserver::Measurement;
  constexpr int kIn = gen::Cap::kInputs;
  constexpr int kCh = CircuitFwObserver::kOutputs;
  if (configure_circuit_observer(obs) != Status::kOk) return ~0u;
  int col[kSigCount];
  for (int& c : col) c = -1;
  for (int c = 0; c < log.cols; ++c) {
    const int s = log.signal[c];
    if (s >= 0 && s < kSigCount && col[s] < 0) col[s] = c;
  }
  const auto cols = static_cast<std::size_t>(log.cols);
  // Value of signal s at row k in SI (double, as the host reader stores it).
  auto at = [&](std::size_t k, int s) noexcept {
    return log.data[k * cols + static_cast<std::size_t>(col[s])] * log.scale[col[s]];
  };
  const int n_in = gen::kCircuit.n_inputs;
  const int n_ch = gen::kCircuit.n_channels;
  const Inputs nominal = circuit_inputs();
  auto inputs_at = [&](std::size_t k) noexcept {
    Inputs u = nominal;
    for (int i = 0; i < n_in && i < kIn && kSigPSup + i < kSigPMi; ++i) {
      if (col[kSigPSup + i] >= 0) u.v[i] = static_cast<float>(at(k, kSigPSup + i));
    }
    return u;
  };
  auto meas_at = [&](std::size_t k) noexcept {
    Meas m;
    for (int c = 0; c < n_ch && c < kCh && kSigPMi + c < kSigCount; ++c) {
      if (col[kSigPMi + c] < 0) continue;
      m.y[c] = static_cast<float>(at(k, kSigPMi + c));
      m.valid = static_cast<std::uint8_t>(m.valid | (1u << c));
    }
    return m;
  };
  const std::size_t rows = col[kSigT] >= 0 ? log.rows : 0;
  const double tick = kTick;
  std::uint32_t health = 0;
  std::uint64_t digest = 0xcbf29ce484222325ull, ticks = 0;
  if (rows > 0) {
    const double t_first = at(0, kSigT);
    Inputs u_prev = inputs_at(0);
    (void)obs.reset_measured(u_prev, meas_at(0));
    const Meas none;
    Out o;
    for (std::size_t k = 0; k < rows; ++k) {
      // Ticks without a measurement, inputs held, until the model clock reaches the row.
      const double t_row = at(k, kSigT) - t_first;
      while (t_row - static_cast<double>(ticks) * tick > 0.5 * tick) {
        health |= obs.step(u_prev, none);
        ++ticks;
      }
      const Inputs u = inputs_at(k);
      const std::uint32_t flags = obs.step(u, meas_at(k));
      ++ticks;
      health |= flags;
      u_prev = u;
      float r[kCh];
      for (int c = 0; c < kCh; ++c) r[c] = obs.residual()[c];
      fnv1a(digest, r, sizeof r);
      fnv1a(digest, &flags, sizeof flags);
      o.n = 0;
      o.put("trace ");
      o.uint(k);
      o.put(" ");
      o.uint(flags);
      for (int c = 0; c < n_ch; ++c) {
        char b[32];
        (void)format_hex_float(b, r[c]);
        o.put(" ");
        o.put(b);
      }
      o.put("\n");
      out(o.buf);
    }
  }
  char hex[17];
  for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(digest >> (60 - 4 * i)) & 0xfu];
  hex[16] = '\0';
  Out o;
  o.put("{\"type\":\"circuit_firmware\",\"circuit\":\"");
  o.put(HSTMON_FW_STR(HSTMON_FW_CIRCUIT));
  o.put("\",\"scalar\":\"float\",\"rows\":");
  o.uint(rows);
  o.put(",\"ticks\":");
  o.uint(ticks);
  o.put(",\"health\":");
  o.uint(health);
  o.put(",\"residual_digest\":\"");
  o.put(hex);
  o.put("\"}\n");
  out(o.buf);
  return health;
}

}  // namespace hstmon::fw
