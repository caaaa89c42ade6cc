// The embedded log through a circuit's whole monitor, printed as `hstmon replay --circuit
// --json` prints it (fw_circuit_monitor.hpp). Mirrors host_sim/circuit/src/circuit_replay.cpp
// step for step; keep the two in line.
#include "fw_circuit_monitor.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

#include "fw_json.hpp"
#include "hstmon/circuit/generated_setup.hpp"

namespace hstmon::fw {

namespace {

using Model = CircuitFwModel;
using Inputs = Model::Inputs;
using Meas = CircuitFwMonitor::Measurement;
constexpr int kCh = CircuitFwMonitor::kChannels;
constexpr int kMaxCols = 32;  // log columns looked at (more are ignored)

// Scratch model for the setup's steady-state solves (static: not on the stack).
Model g_model;

void fnv1a(std::uint64_t& h, const void* p, std::size_t n) noexcept {
  const auto* b = static_cast<const unsigned char*>(p);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
}

// Case-insensitive equality of two NUL-terminated names (ASCII).
bool same_name(const char* a, const char* b) noexcept {
  for (; *a != '\0' && *b != '\0'; ++a, ++b) {
    const char x = (*a >= 'A' && *a <= 'Z') ? static_cast<char>(*a - 'A' + 'a') : *a;
    const char y = (*b >= 'A' && *b <= 'Z') ? static_cast<char>(*b - 'A' + 'a') : *b;
    if (x != y) return false;
  }
  return *a == *b;
}

// The log column named `name`, -1 if none.
int find_column(const LogView& log, const LogColumns& cols, const char* name) noexcept {
  for (int c = 0; c < log.cols && c < kMaxCols; ++c) {
    if (same_name(cols.name[c], name)) return c;
  }
  return -1;
}

// The generated header's values, as the shared setup takes them.
circuit::GeneratedValues<gen::Cap> generated_values() noexcept {
  return {&gen::kCircuit, gen::kParams, gen::kNoiseSigma, gen::kRangeLo, gen::kRangeHi, gen::kUncertainty, kTick};
}

void error_line(Line& line, const char* what, const char* column, const char* unit) noexcept {
  line.begin().str("type", "error").key("message").raw("\"").raw(what);
  if (column != nullptr) line.raw(": column '").raw(column).raw("' unit '").raw(unit).raw("'");
  line.raw("\"").end();
}

// Row k's value of log column c in SI (scale: the column's SI factor).
double log_value(const LogView& log, std::size_t k, int c, double scale) noexcept {
  return log.data[k * static_cast<std::size_t>(log.cols) + static_cast<std::size_t>(c)] * scale;
}

// Where the time, the circuit's inputs and its channels are in the log (-1: not there), and
// the SI factor of each mapped input and channel.
struct ColumnMap {
  int t = -1;
  int in[gen::Cap::kInputs] = {};
  int ch[kCh] = {};
  double in_scale[gen::Cap::kInputs] = {};
  double ch_scale[kCh] = {};
  std::uint8_t mask = 0;  ///< channels in the log
};

// Maps the log's columns by name; a mapped column must have an SI factor (its unit known).
// False, after an error line, when it cannot be replayed.
bool map_columns(const LogView& log, const LogColumns& columns, Line& line, ColumnMap& map) noexcept {
  const int n_in = gen::kCircuit.n_inputs;
  const int n_ch = gen::kCircuit.n_channels;
  map.t = find_column(log, columns, "t");
  if (map.t < 0) map.t = find_column(log, columns, "time");
  if (map.t < 0 || log.rows == 0) {
    error_line(line, "no time column (t[s]) or no data row in the embedded log", nullptr, nullptr);
    return false;
  }
  if (!(log.scale[map.t] > 0.0)) {  // "t" is s when bare; a bare "time" is not known here
    error_line(line, "time column without a known unit (write t[s])", columns.name[map.t], columns.unit[map.t]);
    return false;
  }
  for (int& c : map.in) c = -1;
  for (int& c : map.ch) c = -1;
  for (int i = 0; i < n_in; ++i) map.in[i] = find_column(log, columns, gen::kInputColumns[i]);
  for (int i = 0; i < n_ch; ++i) map.ch[i] = find_column(log, columns, gen::kChannelColumns[i]);
  // SI factor of a mapped column: its stated unit's, else the circuit file's unit's (as
  // the host reader takes it); 0 when the stated unit is not one csv_to_header knows.
  auto scale_of = [&](int c, double file_unit) noexcept {
    return columns.unit[c][0] == '\0' ? file_unit : log.scale[c];
  };
  for (int i = 0; i < n_in; ++i) {
    if (map.in[i] >= 0) map.in_scale[i] = scale_of(map.in[i], gen::kInputUnitScale[i]);
  }
  for (int i = 0; i < n_ch; ++i) {
    if (map.ch[i] >= 0) map.ch_scale[i] = scale_of(map.ch[i], gen::kChannelUnitScale[i]);
  }
  for (int i = 0; i < n_in + n_ch; ++i) {
    const int c = i < n_in ? map.in[i] : map.ch[i - n_in];
    const double f = i < n_in ? map.in_scale[i] : map.ch_scale[i - n_in];
    if (c >= 0 && !(f > 0.0)) {
      error_line(line, "unit not known to the firmware's log converter (csv_to_header.cmake)", columns.name[c],
                 columns.unit[c]);
      return false;
    }
  }
  for (int i = 0; i < n_ch; ++i) {
    if (map.ch[i] >= 0) map.mask = static_cast<std::uint8_t>(map.mask | (1u << i));
  }
  return true;
}

// What the replay adds up over the rows.
struct ReplayTotals {
  std::uint32_t health = 0, max_substeps = 0;
  std::uint64_t unhealthy = 0, n_events = 0, digest = 0xcbf29ce484222325ull;
  Stats st[kCh];
  std::uint64_t clipped[kCh] = {};  ///< rows not compared per channel (reading at a range end)
};

// The measurement of row k; `compared` leaves out readings at an end of the range (the
// sensor checks judge them; the statistics do not count them), as the host does.
void read_measurement(const LogView& log, const ColumnMap& map, std::size_t k, Meas& m, std::uint8_t& compared,
                      std::uint64_t (&clipped)[kCh]) noexcept {
  m.valid = map.mask;
  compared = map.mask;
  for (int i = 0; i < gen::kCircuit.n_channels; ++i) {
    const double y = map.ch[i] >= 0 ? log_value(log, k, map.ch[i], map.ch_scale[i]) : 0.0;
    m.y[i] = static_cast<float>(y);
    if (map.ch[i] >= 0 && (y <= gen::kRangeLo[i] || y >= gen::kRangeHi[i])) {
      compared = static_cast<std::uint8_t>(compared & ~(1u << i));
      ++clipped[i];
    }
  }
}

// One event line per event waiting, keys in the host's (nlohmann's sorted) order; t is the row's log time.
void write_events(CircuitFwMonitor& mon, Line& line, double t_row, std::uint64_t& n_events) noexcept {
  CircuitFwMonitor::Event ev;
  while (mon.pop_event(ev)) {
    line.begin().key("candidates").raw("[");
    for (int j = 0; j < ev.count; ++j) {
      const double score = static_cast<double>(ev.candidate[j].score);
      line.raw(j ? ",{" : "{");
      line.first_key().str("fault", ev.candidate[j].name).num("score", score > 0.0 ? score : 0.0).raw("}");
    }
    line.raw("]").uint("consistent", ev.consistent).str("event", to_string(ev.kind)).num("t", t_row)
        .str("type", "event").end();
    ++n_events;
  }
}

// Row k's trace line: health flags and each channel's residual as hex floats.
void write_trace(Line& line, std::size_t k, std::uint32_t flags, const float (&r)[kCh]) noexcept {
  char b[32];
  line.raw("trace ");
  format_uint(b, k);
  line.raw(b).raw(" ");
  format_uint(b, flags);
  line.raw(b);
  for (int i = 0; i < gen::kCircuit.n_channels; ++i) {
    format_hex_float(b, r[i]);
    line.raw(" ").raw(b);
  }
  line.raw("\n").flush();
}

// Header line: the fields of `hstmon replay --circuit --json` (those the firmware knows).
void write_replay_line(Line& line, const LogView& log, const CircuitFwMonitor& mon, double t_first, double t_last,
                       InitialState start, const ReplayTotals& tot) noexcept {
  line.begin()
      .str("type", "replay")
      .str("log", log.name)
      .str("circuit", HSTMON_FW_STR(HSTMON_FW_CIRCUIT))
      .uint("rows", log.rows)
      .num("t_first", t_first)
      .num("t_last", t_last)
      .num("tick_s", kTick)
      .uint("ticks", mon.observer().ticks())
      .str("start", to_string(start))
      .num("startup_hold_s", static_cast<double>(mon.startup_hold()))
      .uint("fault_table_rows", static_cast<std::uint64_t>(sig::kSignatureCount))
      .uint("states", static_cast<std::uint64_t>(g_model.n_states()))
      .uint("stiff_nodes", static_cast<std::uint64_t>(g_model.n_stiff()));
  write_health(line, tot.health);
  line.uint("unhealthy_rows", tot.unhealthy).uint("max_substeps", tot.max_substeps).end();
}

// One residual line per channel: its statistics over the rows compared.
void write_residual_lines(Line& line, std::uint8_t mask, const ReplayTotals& tot) noexcept {
  for (int i = 0; i < gen::kCircuit.n_channels; ++i) {
    const Stats& s = tot.st[i];
    const bool pressure = gen::kCircuit.channels[i].kind == circuit::ChannelKind::kPressure;
    const bool speed = gen::kCircuit.channels[i].kind == circuit::ChannelKind::kSpeed;
    line.begin().str("type", "residual").str("channel", gen::kChannelNames[i])
        .str("unit", pressure ? "Pa" : (speed ? "rad/s" : "m3/s")).boolean("measured", (mask >> i) & 1u)
        .num("sensor_noise", gen::kNoiseSigma[i]).uint("clipped_rows", tot.clipped[i]).uint("n", s.n);
    if (s.n > 0) {
      line.num("mean", s.mean()).num("rms", s.rms()).num("max_abs", s.max_abs).num("max", s.max_signed)
          .num("t_max", s.t_max).num("noise", s.noise());
    }
    line.end();
  }
}

// The diagnosis line and the firmware's own line (scalar type, residual digest, dropped events).
void write_diagnosis_lines(Line& line, const CircuitFwMonitor& mon, const ReplayTotals& tot) noexcept {
  const char* status = sig::kSignatureCount > 0 ? to_string(mon.matcher().status()) : "not_run";
  line.begin().uint("events", tot.n_events).str("status", status).str("type", "diagnosis").end();
  char hex[17];
  for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(tot.digest >> (60 - 4 * i)) & 0xfu];
  hex[16] = '\0';
  line.begin().str("type", "firmware").str("scalar", "float").str("residual_digest", hex)
      .uint("events_dropped", mon.matcher().events_dropped()).uint("event_mismatches", 0).end();
}

}  // namespace

Status configure_circuit_monitor(CircuitFwMonitor& mon, const Inputs& u0) noexcept {
  return circuit::configure_from_generated(mon, g_model, generated_values(), u0, sig::kSignatures,
                                           sig::kSignatureCount);
}

std::uint32_t circuit_monitor_replay(CircuitFwMonitor& mon, const LogView& log, const LogColumns& columns,
                                     Sink out) noexcept {
  Line line(out);
  const int n_in = gen::kCircuit.n_inputs;
  const int n_ch = gen::kCircuit.n_channels;
  ColumnMap map;
  if (!map_columns(log, columns, line, map)) return ~0u;
  auto at = [&](std::size_t k, int c) noexcept { return log_value(log, k, c, log.scale[c]); };
  const std::size_t rows = log.rows;
  const double t_first = at(0, map.t);
  const double t_last = at(rows - 1, map.t);
  // The host replay ticks at the log's interval: so must the image, to print the same.
  const double tick = kTick;
  if (std::fabs(log_tick(log, map.t) - tick) > 1e-9) {
    error_line(line,
               "the log's sampling interval is not the image's tick: build it with HSTMON_FW_TICK=<the log's "
               "interval> (within the header's kTickMin … kTickMax, else regenerate the header with "
               "hstmon-circuit-header --tick <the log's interval>)",
               nullptr, nullptr);
    return ~0u;
  }

  const Inputs nominal = circuit_inputs();
  auto inputs_at = [&](std::size_t k) noexcept {
    Inputs u = nominal;
    for (int i = 0; i < n_in; ++i) {
      if (map.in[i] >= 0) u.v[i] = static_cast<float>(log_value(log, k, map.in[i], map.in_scale[i]));
    }
    return u;
  };
  Meas m;
  std::uint8_t compared = 0;
  ReplayTotals tot;

  // Configuration and start: as replay_circuit (`--init auto`), from the generated values.
  const circuit::GeneratedValues<gen::Cap> values = generated_values();
  const Inputs u0 = inputs_at(0);
  const Status configured = configure_circuit_monitor(mon, u0);
  if (configured == Status::kInvalidParams) {
    error_line(line, "the generated circuit's values do not make a physical circuit", nullptr, nullptr);
    return ~0u;
  }
  if (configured != Status::kOk) {
    error_line(line, "invalid monitor configuration", nullptr, nullptr);
    return ~0u;
  }
  read_measurement(log, map, 0, m, compared, tot.clipped);
  InitialState start = InitialState::kRest;
  (void)circuit::start_from_first_sample(mon, g_model, values, u0, m, start);
  for (std::uint64_t& c : tot.clipped) c = 0;  // the first row is counted again below

  const auto& obs = mon.observer();
  Inputs u_prev = u0;
  const Meas none;
  for (std::size_t k = 0; k < rows; ++k) {
    const double t_k = at(k, map.t);
    const double t_row = t_k - t_first;
    while (t_row - static_cast<double>(obs.ticks()) * tick > 0.5 * tick) {
      mon.step(static_cast<float>(t_first + static_cast<double>(obs.ticks()) * tick), u_prev, none);
      tot.health |= mon.health();
      if (obs.substeps() > tot.max_substeps) tot.max_substeps = obs.substeps();
    }
    const Inputs u = inputs_at(k);
    read_measurement(log, map, k, m, compared, tot.clipped);
    mon.step(static_cast<float>(t_k), u, m);
    write_events(mon, line, t_k, tot.n_events);
    const std::uint32_t flags = mon.health();
    tot.health |= flags;
    if (flags != 0) ++tot.unhealthy;
    if (obs.substeps() > tot.max_substeps) tot.max_substeps = obs.substeps();
    u_prev = u;
    const unsigned rv = obs.residual_valid() & compared;
    float r[kCh];
    for (int i = 0; i < kCh; ++i) r[i] = obs.residual()[i];
    fnv1a(tot.digest, r, sizeof r);
    fnv1a(tot.digest, &flags, sizeof flags);
    for (int i = 0; i < n_ch; ++i) {
      if ((rv & (1u << i)) != 0) tot.st[i].add(static_cast<double>(r[i]), t_k);
    }
    write_trace(line, k, flags, r);
  }
  write_events(mon, line, t_last, tot.n_events);

  write_replay_line(line, log, mon, t_first, t_last, start, tot);
  write_residual_lines(line, map.mask, tot);
  write_diagnosis_lines(line, mon, tot);
  return tot.health;
}

}  // namespace hstmon::fw
