// Portable firmware replay loop (see fw_replay.hpp). Compiled for Cortex-M4F and for the
// host; keep it free of anything either side lacks (no <cstdio>, no heap, no exceptions).
#include "fw_replay.hpp"

#include "fw_json.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "hstmon/thesis_reduced.hpp"
#include "hstmon_c.h"

namespace hstmon::fw {

namespace {

// The monitor is the C API's (hstmon_c.h: observer, sensor checks, evaluator, matcher,
// the 26-row table), in static storage: its size is the monitor's RAM, and it keeps the
// replay's stack use small and independent of the model.
hstmon_monitor_storage g_storage;

/// Candidates printed per event: as many as the host's events carry (MatchEvent<double>).
constexpr int kPrintCandidates = 8;

constexpr const char* kChannelName[4] = {"p_mi", "p_mo", "p_pp", "w_m"};
constexpr const char* kInputNote[4] = {"p_sup (Psupl)", "p_s (Ps)", "p_bp (Pbp)", "kp"};

// FNV-1a 64 over bytes: a cheap, exact fingerprint of every residual of the replay.
void fnv1a(std::uint64_t& h, const void* p, std::size_t n) noexcept {
  const auto* b = static_cast<const unsigned char*>(p);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
}

}  // namespace

// Median of up to 63 strided sample intervals, rounded to 1 ns, capped at 10 ms: the host
// rule (replay.cpp samples up to 4096 intervals) on a bounded sample, identical on the
// uniformly sampled logs hstmon-sim writes.
double log_tick(const LogView& log, int t_col) noexcept {
  if (log.rows < 2) return 1e-3;
  constexpr std::size_t kMax = 63;
  double dt[kMax];
  std::size_t stride = log.rows / kMax;
  if (stride == 0) stride = 1;
  std::size_t m = 0;
  for (std::size_t i = stride; i < log.rows && m < kMax; i += stride) {
    const double a = log.data[(i - stride) * static_cast<std::size_t>(log.cols) + static_cast<std::size_t>(t_col)];
    const double b = log.data[i * static_cast<std::size_t>(log.cols) + static_cast<std::size_t>(t_col)];
    const double v = (b - a) * log.scale[t_col] / static_cast<double>(stride);
    std::size_t j = m++;  // insertion sort: m ≤ 63
    for (; j > 0 && dt[j - 1] > v; --j) dt[j] = dt[j - 1];
    dt[j] = v;
  }
  const double med = dt[m / 2];
  if (!(med > 0.0)) return 1e-3;
  const double r = std::round(med * 1e9) * 1e-9;
  return r < 10e-3 ? r : 10e-3;
}

int format_uint(char* buf, std::uint64_t v) noexcept {
  char tmp[24];
  int n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + static_cast<int>(v % 10u));
    v /= 10u;
  } while (v != 0);
  for (int i = 0; i < n; ++i) buf[i] = tmp[n - 1 - i];
  buf[n] = '\0';
  return n;
}

int format_double(char* buf, double v) noexcept {
  if (!std::isfinite(v)) {
    std::memcpy(buf, "null", 5);
    return 4;
  }
  int n = 0;
  if (std::signbit(v)) buf[n++] = '-';
  double a = std::fabs(v);
  if (a == 0.0) {
    buf[n++] = '0';
    buf[n] = '\0';
    return n;
  }
  // Scale into [1, 10) by powers of ten; each step rounds once (≤ 1e-14 relative over the
  // double range), far below the 12 digits printed.
  int e = 0;
  while (a >= 1e16) { a *= 1e-16; e += 16; }
  while (a >= 10.0) { a *= 0.1; ++e; }
  while (a < 1e-16) { a *= 1e16; e -= 16; }
  while (a < 1.0) { a *= 10.0; --e; }
  // NOLINTNEXTLINE(bugprone-incorrect-roundings): a is in [1, 10) here, so adding 0.5 rounds correctly
  auto d = static_cast<std::uint64_t>(a * 1e11 + 0.5);
  if (d >= 1000000000000ull) { d /= 10u; ++e; }
  char digits[24];
  format_uint(digits, d);
  int last = 11;  // trim trailing zeros of the fraction
  while (last > 0 && digits[last] == '0') --last;
  buf[n++] = digits[0];
  if (last > 0) {
    buf[n++] = '.';
    for (int i = 1; i <= last; ++i) buf[n++] = digits[i];
  }
  if (e != 0) {
    buf[n++] = 'e';
    buf[n++] = e < 0 ? '-' : '+';
    n += format_uint(buf + n, static_cast<std::uint64_t>(e < 0 ? -e : e));
  }
  buf[n] = '\0';
  return n;
}

int format_hex_float(char* buf, float v) noexcept {
  std::uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  int n = 0;
  const bool neg = (bits >> 31) != 0;
  const auto exp_field = static_cast<int>((bits >> 23) & 0xffu);
  std::uint32_t frac = bits & 0x7fffffu;
  if (neg) buf[n++] = '-';
  if (exp_field == 0xff) {
    std::memcpy(buf + n, frac ? "nan" : "inf", 4);
    return n + 3;
  }
  int e;
  if (exp_field == 0) {
    if (frac == 0) {
      std::memcpy(buf + n, "0x0p+0", 7);
      return n + 6;
    }
    e = -126;  // subnormal: normalise, as printf does after the conversion to double
    while ((frac & 0x800000u) == 0) { frac <<= 1; --e; }
    frac &= 0x7fffffu;
  } else {
    e = exp_field - 127;
  }
  std::memcpy(buf + n, "0x1", 3);  // NOLINT(bugprone-not-null-terminated-result): length-counted text (n)
  n += 3;
  std::uint32_t f = frac << 1;  // 24 bits = 6 hex digits
  if (f != 0) {
    buf[n++] = '.';
    for (int shift = 20; shift >= 0 && f != 0; shift -= 4) {
      buf[n++] = "0123456789abcdef"[(f >> shift) & 0xfu];
      f &= (1u << shift) - 1u;
    }
  }
  buf[n++] = 'p';
  buf[n++] = e < 0 ? '-' : '+';
  n += format_uint(buf + n, static_cast<std::uint64_t>(e < 0 ? -e : e));
  return n;
}

namespace {

// Where each signal is in the log (the first column carrying it; -1: not there).
struct SignalColumns {
  int col[kSigCount];
  std::uint8_t mask = 0;  ///< measured channels (p_mi, p_mo, p_pp, w_m) in the log

  explicit SignalColumns(const LogView& log) noexcept {
    for (int& c : col) c = -1;
    for (int c = 0; c < log.cols; ++c) {
      const int s = log.signal[c];
      if (s >= 0 && s < kSigCount && col[s] < 0) col[s] = c;
    }
    for (int c = 0; c < 4; ++c) {
      if (col[kSigPMi + c] >= 0) mask = static_cast<std::uint8_t>(mask | (1u << c));
    }
  }
};

// The log read by signal, in SI (double, as the host reader stores it).
struct SignalLog {
  const LogView& log;
  SignalColumns sc;

  bool has(int s) const noexcept { return sc.col[s] >= 0; }
  /// Value of signal s at row k.
  double at(std::size_t k, int s) const noexcept {
    return log.data[k * static_cast<std::size_t>(log.cols) + static_cast<std::size_t>(sc.col[s])] * log.scale[sc.col[s]];
  }
  /// Row k's inputs: the log's where it has them, else the thesis defaults.
  hstmon_inputs inputs_at(std::size_t k) const noexcept {
    const ThesisInputs<float> defaults;
    hstmon_inputs u{defaults.Psupl, defaults.Ps, defaults.Pbp, defaults.kp};
    if (has(kSigPSup)) u.p_sup = static_cast<float>(at(k, kSigPSup));
    if (has(kSigPS)) u.p_s = static_cast<float>(at(k, kSigPS));
    if (has(kSigPBp)) u.p_bp = static_cast<float>(at(k, kSigPBp));
    if (has(kSigKp)) u.kp = static_cast<float>(at(k, kSigKp));
    return u;
  }
  /// Row k's measurement (time, inputs, readings, valid channels).
  hstmon_sample sample_at(std::size_t k) const noexcept {
    hstmon_sample s{};
    s.t_s = static_cast<float>(at(k, kSigT));
    s.u = inputs_at(k);
    for (int c = 0; c < 4; ++c) s.y[c] = has(kSigPMi + c) ? static_cast<float>(at(k, kSigPMi + c)) : 0.0f;
    s.valid = sc.mask;
    return s;
  }
};

// What the replay adds up over the rows.
struct ReplayTotals {
  hstmon_report rep{};
  std::uint8_t start = HSTMON_START_REST;
  std::uint32_t health = 0, max_substeps = 0;
  std::uint64_t unhealthy = 0, digest = 0xcbf29ce484222325ull, n_events = 0, event_mismatch = 0;
  Stats st[4];
};

// One `hstmon replay --json` event line: keys in the host's (nlohmann's sorted) order;
// t is the row's time (the event's float t_s must be that row's, checked).
void print_event(Line& line, hstmon_monitor* mon, const hstmon_event& e, double t_row, ReplayTotals& tot) noexcept {
  hstmon_candidate live[kPrintCandidates];
  int shown = e.count;
  const hstmon_candidate* cand = e.candidate;
  bool same = e.t_s == static_cast<float>(t_row);
  if (e.kind != HSTMON_EVENT_CLEARED) {
    // The event stores the best HSTMON_EVENT_CANDIDATES; the rest is the live ranking,
    // which is the event's when the queue is drained after every tick (all events of a
    // tick are raised after its ranking). Checked on the stored part.
    const int total = hstmon_candidates(mon, live, kPrintCandidates);
    bool match = total == e.consistent;
    for (int j = 0; match && j < e.count; ++j) {
      // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): bit-identical scores wanted, not equal values
      match = live[j].name == e.candidate[j].name && std::memcmp(&live[j].score, &e.candidate[j].score, sizeof(float)) == 0;
    }
    if (match) {
      shown = total < kPrintCandidates ? total : kPrintCandidates;
      cand = live;
    }
    same = same && match;
  }
  if (!same) ++tot.event_mismatch;
  line.begin().key("candidates").raw("[");
  for (int j = 0; j < shown; ++j) {
    line.raw(j ? ",{" : "{");
    line.first_key().str("fault", cand[j].name).num("score", static_cast<double>(cand[j].score)).raw("}");
  }
  line.raw("]").uint("consistent", e.consistent).str("event", hstmon_event_name(static_cast<hstmon_event_kind>(e.kind)))
      .num("t", t_row).str("type", "event").end();
  ++tot.n_events;
}

// Row k's trace line: health flags and each channel's residual as hex floats.
void print_trace(Line& line, std::size_t k, std::uint32_t flags, const float* r) noexcept {
  char b[40];
  line.raw("trace ");
  format_uint(b, k);
  line.raw(b).raw(" ");
  format_uint(b, flags);
  line.raw(b);
  for (int c = 0; c < 4; ++c) {
    format_hex_float(b, r[c]);
    line.raw(" ").raw(b);
  }
  line.raw("\n").flush();
}

// The rows through the monitor, started as `hstmon replay --init auto` (from the first row's
// measurements), with the ticks between rows stepped on held inputs; rows > 0.
void replay_rows(hstmon_monitor* mon, const SignalLog& lg, std::size_t rows, double tick, bool trace, Line& line,
                 ReplayTotals& tot) noexcept {
  const double t_first = lg.at(0, kSigT);
  const hstmon_inputs u0 = lg.inputs_at(0);
  const hstmon_sample first = lg.sample_at(0);
  if (hstmon_reset_measured(mon, &first, &tot.start) != HSTMON_OK) {
    (void)hstmon_reset_rest(mon, &u0);
    tot.start = HSTMON_START_REST;
  }

  hstmon_sample none{};  // inputs held, nothing measured (valid = 0): the matcher does not run
  none.u = u0;
  hstmon_event ev;
  hstmon_report& rep = tot.rep;
  hstmon_read(mon, &rep);
  for (std::size_t k = 0; k < rows; ++k) {
    const double t_row = lg.at(k, kSigT) - t_first;
    while (t_row - static_cast<double>(rep.ticks) * tick > 0.5 * tick) {
      none.t_s = static_cast<float>(t_first + static_cast<double>(rep.ticks) * tick);
      tot.health |= hstmon_step(mon, &none);
      hstmon_read(mon, &rep);
      if (rep.substeps > tot.max_substeps) tot.max_substeps = rep.substeps;
    }
    const hstmon_sample s = lg.sample_at(k);
    const std::uint32_t flags = hstmon_step(mon, &s);
    while (hstmon_pop_event(mon, &ev)) print_event(line, mon, ev, lg.at(k, kSigT), tot);
    tot.health |= flags;
    if (flags) ++tot.unhealthy;
    hstmon_read(mon, &rep);
    if (rep.substeps > tot.max_substeps) tot.max_substeps = rep.substeps;
    none.u = s.u;

    const float* r = rep.residual;
    const std::uint8_t rv = rep.residual_valid;
    fnv1a(tot.digest, r, sizeof(float) * 4);
    fnv1a(tot.digest, &flags, sizeof flags);
    for (int c = 0; c < 4; ++c) {
      if (!(rv & (1u << c))) continue;
      tot.st[c].add(static_cast<double>(r[c]), lg.at(k, kSigT));
    }
    if (trace) print_trace(line, k, flags, r);
  }
}

// Header line: the fields of `hstmon replay --json`.
void print_replay_line(Line& line, const LogView& log, const SignalColumns& sc, std::size_t rows, double t_first,
                       double t_last, double tick, const ReplayTotals& tot) noexcept {
  line.begin().str("type", "replay").str("log", log.name).uint("rows", rows).num("t_first", t_first)
      .num("t_last", t_last).num("tick_s", tick).uint("ticks", tot.rep.ticks).str("start", tot.start == HSTMON_START_MEASURED ? "measured" : (tot.start == HSTMON_START_STEADY ? "steady" : "rest"));
  write_health(line, tot.health);
  line.uint("unhealthy_rows", tot.unhealthy).uint("max_substeps", tot.max_substeps);
  line.key("notes").raw("[");
  bool first = true;
  for (int i = 0; i < 4; ++i) {
    if (sc.col[kSigPSup + i] < 0) {
      line.raw(first ? "\"" : ",\"").raw(kInputNote[i]).raw(" not in log: held at the parameter value\"");
      first = false;
    }
  }
  line.raw("]").end();
}

// One residual line per channel: its statistics over the rows compared.
void print_residual_lines(Line& line, std::uint8_t mask, const ReplayTotals& tot) noexcept {
  for (int c = 0; c < 4; ++c) {
    const Stats& s = tot.st[c];
    line.begin().str("type", "residual").str("channel", kChannelName[c]).str("unit", c == 3 ? "rad/s" : "Pa")
        .boolean("measured", (mask >> c) & 1u).uint("n", s.n);
    if (s.n > 0) {
      line.num("mean", s.mean()).num("rms", s.rms()).num("max_abs", s.max_abs).num("max", s.max_signed)
          .num("t_max", s.t_max).num("noise", s.noise());
    }
    line.end();
  }
}

// The diagnosis line of `hstmon replay --json` (keys sorted, as there) and the firmware's own line.
void print_diagnosis_lines(Line& line, hstmon_monitor* mon, const ReplayTotals& tot) noexcept {
  line.begin().uint("events", tot.n_events).str("status", hstmon_match_name(hstmon_match_status(mon))).str("type", "diagnosis").end();

  char hex[20];
  for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(tot.digest >> (60 - 4 * i)) & 0xfu];
  hex[16] = '\0';
  line.begin().str("type", "firmware").str("scalar", "float").str("residual_digest", hex)
      .uint("events_dropped", hstmon_events_dropped(mon))
      .uint("event_mismatches", tot.event_mismatch).end();
}

}  // namespace

std::uint32_t replay_json(const LogView& log, Sink out, const ReplayOptions& opt) noexcept {
  Line line(out);
  const SignalLog lg{log, SignalColumns(log)};
  const std::size_t rows = lg.has(kSigT) ? log.rows : 0;
  const double t_first = rows ? lg.at(0, kSigT) : 0.0;
  const double t_last = rows ? lg.at(rows - 1, kSigT) : 0.0;
  const double tick = rows ? log_tick(log, lg.sc.col[kSigT]) : 1e-3;

  // As ports/host/src/replay.cpp: default parameters and monitor settings, the log's tick.
  hstmon_config cfg;
  hstmon_default_config(&cfg);
  cfg.tick_s = static_cast<float>(tick);
  hstmon_monitor* mon = nullptr;
  if (hstmon_create(&g_storage, sizeof g_storage, &cfg, &mon) != HSTMON_OK) return ~0u;
  ReplayTotals tot;
  if (rows > 0) replay_rows(mon, lg, rows, tick, opt.trace, line, tot);

  print_replay_line(line, log, lg.sc, rows, t_first, t_last, tick, tot);
  print_residual_lines(line, lg.sc.mask, tot);
  print_diagnosis_lines(line, mon, tot);
  return tot.health;
}

}  // namespace hstmon::fw
