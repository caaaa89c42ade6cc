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
  return {&gen::kCircuit, gen::kParams, gen::kNoiseSigma, gen::kRangeLo, gen::kRangeHi, gen::kUncertainty, gen::kTick};
}

void error_line(Line& line, const char* what, const char* column, const char* unit) noexcept {
  line.begin().str("type", "error").key("message").raw("\"").raw(what);
  if (column != nullptr) line.raw(": column '").raw(column).raw("' unit '").raw(unit).raw("'");
  line.raw("\"").end();
}

}  // namespace

std::uint32_t circuit_monitor_replay(CircuitFwMonitor& mon, const LogView& log, const LogColumns& columns,
                                     Sink out) noexcept {
  Line line(out);
  const int n_in = gen::kCircuit.n_inputs;
  const int n_ch = gen::kCircuit.n_channels;
  const auto stride = static_cast<std::size_t>(log.cols);

  // Columns by name; a mapped column must have an SI factor (its unit known).
  int t_col = find_column(log, columns, "t");
  if (t_col < 0) t_col = find_column(log, columns, "time");
  if (t_col < 0 || log.rows == 0) {
    error_line(line, "no time column (t[s]) or no data row in the embedded log", nullptr, nullptr);
    return ~0u;
  }
  if (!(log.scale[t_col] > 0.0)) {  // "t" is s when bare; a bare "time" is not known here
    error_line(line, "time column without a known unit (write t[s])", columns.name[t_col], columns.unit[t_col]);
    return ~0u;
  }
  int in_col[gen::Cap::kInputs];
  int ch_col[kCh];
  for (int& c : in_col) c = -1;
  for (int& c : ch_col) c = -1;
  for (int i = 0; i < n_in; ++i) in_col[i] = find_column(log, columns, gen::kInputColumns[i]);
  for (int i = 0; i < n_ch; ++i) ch_col[i] = find_column(log, columns, gen::kChannelColumns[i]);
  // SI factor of a mapped column: its stated unit's, else the circuit file's unit's (as
  // the host reader takes it); 0 when the stated unit is not one csv_to_header knows.
  double in_scale[gen::Cap::kInputs] = {};
  double ch_scale[kCh] = {};
  auto scale_of = [&](int c, double file_unit) noexcept {
    return columns.unit[c][0] == '\0' ? file_unit : log.scale[c];
  };
  for (int i = 0; i < n_in; ++i) {
    if (in_col[i] >= 0) in_scale[i] = scale_of(in_col[i], gen::kInputUnitScale[i]);
  }
  for (int i = 0; i < n_ch; ++i) {
    if (ch_col[i] >= 0) ch_scale[i] = scale_of(ch_col[i], gen::kChannelUnitScale[i]);
  }
  for (int i = 0; i < n_in + n_ch; ++i) {
    const int c = i < n_in ? in_col[i] : ch_col[i - n_in];
    const double f = i < n_in ? in_scale[i] : ch_scale[i - n_in];
    if (c >= 0 && !(f > 0.0)) {
      error_line(line, "unit not known to the firmware's log converter (csv_to_header.cmake)", columns.name[c],
                 columns.unit[c]);
      return ~0u;
    }
  }
  auto value = [&](std::size_t k, int c, double scale) noexcept {
    return log.data[k * stride + static_cast<std::size_t>(c)] * scale;
  };
  auto at = [&](std::size_t k, int c) noexcept { return value(k, c, log.scale[c]); };
  const std::size_t rows = log.rows;
  const double t_first = at(0, t_col);
  const double t_last = at(rows - 1, t_col);
  // The stiff mask of the generated header was chosen for gen::kTick; the host replay
  // chooses it for the log's interval. The two must be the same tick.
  const double tick = gen::kTick;
  if (std::fabs(log_tick(log, t_col) - tick) > 1e-9) {
    error_line(line, "the log's sampling interval is not the generated header's tick: regenerate the header with "
                     "hstmon-circuit-header --tick <the log's interval>", nullptr, nullptr);
    return ~0u;
  }

  const Inputs nominal = circuit_inputs();
  auto inputs_at = [&](std::size_t k) noexcept {
    Inputs u = nominal;
    for (int i = 0; i < n_in; ++i) {
      if (in_col[i] >= 0) u.v[i] = static_cast<float>(value(k, in_col[i], in_scale[i]));
    }
    return u;
  };
  std::uint8_t mask = 0;
  for (int i = 0; i < n_ch; ++i) {
    if (ch_col[i] >= 0) mask = static_cast<std::uint8_t>(mask | (1u << i));
  }
  // The measurement of row k; `compared` leaves out readings at an end of the range (the
  // sensor checks judge them; the statistics do not count them), as the host does.
  Meas m;
  std::uint8_t compared = 0;
  std::uint64_t clipped[kCh] = {};
  auto measurement_at = [&](std::size_t k) noexcept {
    m.valid = mask;
    compared = mask;
    for (int i = 0; i < n_ch; ++i) {
      const double y = ch_col[i] >= 0 ? value(k, ch_col[i], ch_scale[i]) : 0.0;
      m.y[i] = static_cast<float>(y);
      if (ch_col[i] >= 0 && (y <= gen::kRangeLo[i] || y >= gen::kRangeHi[i])) {
        compared = static_cast<std::uint8_t>(compared & ~(1u << i));
        ++clipped[i];
      }
    }
  };

  // Configuration and start: as replay_circuit (`--init auto`), from the generated values.
  const circuit::GeneratedValues<gen::Cap> values = generated_values();
  const Inputs u0 = inputs_at(0);
  const Status configured = circuit::configure_from_generated(mon, g_model, values, u0, sig::kSignatures,
                                                              sig::kSignatureCount);
  if (configured == Status::kInvalidParams) {
    error_line(line, "the generated circuit's values do not make a physical circuit", nullptr, nullptr);
    return ~0u;
  }
  if (configured != Status::kOk) {
    error_line(line, "invalid monitor configuration", nullptr, nullptr);
    return ~0u;
  }
  measurement_at(0);
  InitialState start = InitialState::kRest;
  (void)circuit::start_from_first_sample(mon, g_model, values, u0, m, start);
  for (std::uint64_t& c : clipped) c = 0;  // the first row is counted again below

  const auto& obs = mon.observer();
  std::uint32_t health = 0, max_substeps = 0;
  std::uint64_t unhealthy = 0, n_events = 0, digest = 0xcbf29ce484222325ull;
  Stats st[kCh];
  Inputs u_prev = u0;
  const Meas none;
  CircuitFwMonitor::Event ev;
  // One event line, keys in the host's (nlohmann's sorted) order; t is the row's log time.
  auto drain_events = [&](double t_row) noexcept {
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
  };
  for (std::size_t k = 0; k < rows; ++k) {
    const double t_k = at(k, t_col);
    const double t_row = t_k - t_first;
    while (t_row - static_cast<double>(obs.ticks()) * tick > 0.5 * tick) {
      mon.step(static_cast<float>(t_first + static_cast<double>(obs.ticks()) * tick), u_prev, none);
      health |= mon.health();
      if (obs.substeps() > max_substeps) max_substeps = obs.substeps();
    }
    const Inputs u = inputs_at(k);
    measurement_at(k);
    mon.step(static_cast<float>(t_k), u, m);
    drain_events(t_k);
    const std::uint32_t flags = mon.health();
    health |= flags;
    if (flags != 0) ++unhealthy;
    if (obs.substeps() > max_substeps) max_substeps = obs.substeps();
    u_prev = u;
    const unsigned rv = obs.residual_valid() & compared;
    float r[kCh];
    for (int i = 0; i < kCh; ++i) r[i] = obs.residual()[i];
    fnv1a(digest, r, sizeof r);
    fnv1a(digest, &flags, sizeof flags);
    for (int i = 0; i < n_ch; ++i) {
      if ((rv & (1u << i)) != 0) st[i].add(static_cast<double>(r[i]), t_k);
    }
    char b[32];
    line.raw("trace ");
    format_uint(b, k);
    line.raw(b).raw(" ");
    format_uint(b, flags);
    line.raw(b);
    for (int i = 0; i < n_ch; ++i) {
      format_hex_float(b, r[i]);
      line.raw(" ").raw(b);
    }
    line.raw("\n").flush();
  }
  drain_events(t_last);

  // Header line: the fields of `hstmon replay --circuit --json` (those the firmware knows).
  line.begin().str("type", "replay").str("log", log.name).str("circuit", HSTMON_FW_STR(HSTMON_FW_CIRCUIT))
      .uint("rows", rows).num("t_first", t_first).num("t_last", t_last).num("tick_s", tick).uint("ticks", obs.ticks())
      .str("start", to_string(start)).num("startup_hold_s", static_cast<double>(mon.startup_hold()))
      .uint("fault_table_rows", static_cast<std::uint64_t>(sig::kSignatureCount))
      .uint("states", static_cast<std::uint64_t>(g_model.n_states()))
      .uint("stiff_nodes", static_cast<std::uint64_t>(g_model.n_stiff()));
  line.key("health").raw("[");
  bool first = true;
  for (int bit = 0; bit < kHealthNameCount; ++bit) {
    if (health & (1u << bit)) {
      line.raw(first ? "\"" : ",\"").raw(kHealthNames[bit]).raw("\"");
      first = false;
    }
  }
  line.raw("]").uint("unhealthy_rows", unhealthy).uint("max_substeps", max_substeps).end();

  for (int i = 0; i < n_ch; ++i) {
    const Stats& s = st[i];
    const bool pressure = gen::kCircuit.channels[i].kind == circuit::ChannelKind::kPressure;
    const bool speed = gen::kCircuit.channels[i].kind == circuit::ChannelKind::kSpeed;
    line.begin().str("type", "residual").str("channel", gen::kChannelNames[i])
        .str("unit", pressure ? "Pa" : (speed ? "rad/s" : "m3/s")).boolean("measured", (mask >> i) & 1u)
        .num("sensor_noise", gen::kNoiseSigma[i]).uint("clipped_rows", clipped[i]).uint("n", s.n);
    if (s.n > 0) {
      line.num("mean", s.mean()).num("rms", s.rms()).num("max_abs", s.max_abs).num("max", s.max_signed)
          .num("t_max", s.t_max).num("noise", s.noise());
    }
    line.end();
  }
  const char* status = sig::kSignatureCount > 0 ? to_string(mon.matcher().status()) : "not_run";
  line.begin().uint("events", n_events).str("status", status).str("type", "diagnosis").end();

  char hex[17];
  for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(digest >> (60 - 4 * i)) & 0xfu];
  hex[16] = '\0';
  line.begin().str("type", "firmware").str("scalar", "float").str("residual_digest", hex)
      .uint("events_dropped", mon.matcher().events_dropped()).uint("event_mismatches", 0).end();
  return health;
}

}  // namespace hstmon::fw
