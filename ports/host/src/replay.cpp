#include "hstmon_host/replay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/envelope_check.hpp"
#include "hstmon/monitor.hpp"
#include "hstmon/residual_bounds.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace hstmon::host {

const std::array<Signal, 4> kMeasuredSignals = {Signal::kPMi, Signal::kPMo, Signal::kPPp, Signal::kWm};

std::vector<std::string> health_names(std::uint32_t flags) {
  static const std::pair<std::uint32_t, const char*> names[] = {
      {kHealthInputNonFinite, "input_non_finite"},     {kHealthMeasNonFinite, "measurement_non_finite"},
      {kHealthSubstepsClipped, "substeps_clipped"},    {kHealthStateNonFinite, "state_non_finite"},
      {kHealthStateOutOfBounds, "state_out_of_bounds"}, {kHealthAlgebraicDiverged, "algebraic_diverged"}};
  std::vector<std::string> out;
  for (const auto& [bit, name] : names) {
    if (flags & bit) out.emplace_back(name);
  }
  return out;
}

namespace {

// The thesis monitor on either implementation of the rig's equations (ThesisImpl): the
// engine's ThesisCircuitModel (Monitor<double>) or the hand-written specialisation.
using MonEngine = Monitor<double>;
using MonSpecialised = ModelMonitor<ThesisReducedModel<double>>;

// The thesis rig's channels as the envelope sentence names them (the human table's units).
const std::vector<EnvelopeChannel>& thesis_envelope_channels() {
  static const std::vector<EnvelopeChannel> names = {
      {"p_mi", "bar", 1e-5}, {"p_mo", "bar", 1e-5}, {"p_pp", "bar", 1e-5}, {"w_m", "rpm", 30.0 / M_PI}};
  return names;
}

// Median of the positive sample intervals; 0 for fewer than two rows.
double median_interval(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> dt;
  const std::size_t stride = std::max<std::size_t>(1, t.size() / 4096);  // a sample is plenty
  for (std::size_t i = stride; i < t.size(); i += stride) dt.push_back((t[i] - t[i - stride]) / static_cast<double>(stride));
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

// Per-row input columns, with the defaults where a column is absent.
struct InputColumns {
  const double* col[4] = {nullptr, nullptr, nullptr, nullptr};  // Psupl, Ps, Pbp, kp
  ThesisInputs<double> fallback;

  InputColumns(const LogData& log, const std::array<bool, 4>& present, const ThesisInputs<double>& defaults)
      : fallback(defaults) {
    const Signal input_signals[4] = {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp};
    for (std::size_t i = 0; i < 4; ++i) {
      if (present[i]) col[i] = log.values[index(input_signals[i])].data();
    }
  }

  ThesisInputs<double> at(std::size_t row) const {
    ThesisInputs<double> u = fallback;
    if (col[0]) u.Psupl = col[0][row];
    if (col[1]) u.Ps = col[1][row];
    if (col[2]) u.Pbp = col[2][row];
    if (col[3]) u.kp = col[3][row];
    return u;
  }
};

}  // namespace

struct ChunkedReplay::State {
  ThesisParams<double> params;
  ThesisInputs<double> defaults;
  ReplayOptions options;
  ReplayResult res;
  MonEngine mon_engine;
  MonSpecialised mon_specialised;
  // Does the model describe this machine? Judged at the first steady stretch (envelope_check.hpp).
  EnvelopeCheck<MonEngine::Model> envelope_engine;
  EnvelopeCheck<MonSpecialised::Model> envelope_specialised;
  bool out_of_envelope = false;  // then nothing more is diagnosed
  bool started = false;   // first row seen: tick, columns and initial state fixed
  bool failed = false;    // configuration refused: nothing replayed
  std::size_t row = 0;    // 0-based index of the next row in the log
  std::uint8_t mask = 0;  // measured channels present
  std::array<bool, 4> input_present{};
  ThesisInputs<double> u_prev;
  std::vector<std::string> input_notes;

  // Calls f with the monitor of the chosen implementation.
  template <class F>
  void with_monitor(F&& f) {
    if (options.thesis == ThesisImpl::kEngine) {
      f(mon_engine);
    } else {
      f(mon_specialised);
    }
  }
  void start(const LogData& log) {
    with_monitor([&](auto& mon) { start(mon, log); });
  }
  void run(const LogData& log, std::size_t rows_total) {
    with_monitor([&](auto& mon) { run(mon, log, rows_total); });
  }

  EnvelopeCheck<MonEngine::Model>& envelope(MonEngine&) { return envelope_engine; }
  EnvelopeCheck<MonSpecialised::Model>& envelope(MonSpecialised&) { return envelope_specialised; }
  template <class Mon>
  EnvelopeResult envelope_now(Mon& mon) {
    return envelope_result(envelope_figures(envelope(mon)), thesis_envelope_channels(),
                           "Run `hstmon identify` on healthy steady data, or `hstmon gap`");
  }

  template <class Mon>
  void start(Mon& mon, const LogData& log);
  template <class Mon>
  void run(Mon& mon, const LogData& log, std::size_t rows_total);
};

// Fixes what the first chunk decides: the inputs held at their defaults, the tick, the
// monitor's configuration and its initial state.
template <class Mon>
void ChunkedReplay::State::start(Mon& mon, const LogData& log) {
  using Obs = typename Mon::Obs;
  started = true;
  res.t_first = log.t.front();
  const Signal input_signals[4] = {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp};
  const char* input_names[4] = {"p_sup (Psupl)", "p_s (Ps)", "p_bp (Pbp)", "kp"};
  const double input_defaults[4] = {defaults.Psupl, defaults.Ps, defaults.Pbp, defaults.kp};
  for (int i = 0; i < 4; ++i) {
    input_present[static_cast<std::size_t>(i)] = log.present[index(input_signals[i])];
    if (!log.present[index(input_signals[i])]) {
      // In the units of the tables beside it: pressures in bar, kp in SI.
      char value[64];
      if (input_signals[i] == Signal::kKp) {
        std::snprintf(value, sizeof value, "%.4g m3/(s*Pa^0.5)", input_defaults[i]);
      } else {
        std::snprintf(value, sizeof value, "%.4g bar", input_defaults[i] * 1e-5);
      }
      res.notes.push_back(std::string(input_names[i]) + " not in log: held at the parameter value " + value);
    }
  }
  for (int c = 0; c < 4; ++c) {
    const std::size_t s = index(kMeasuredSignals[static_cast<std::size_t>(c)]);
    res.measured[static_cast<std::size_t>(c)] = log.present[s];
    if (log.present[s]) mask = static_cast<std::uint8_t>(mask | (1u << c));
  }

  double tick = options.tick;
  if (!(tick > 0.0)) {
    const double dt = median_interval(log.t);
    // Rounded to 1 ns: the median of differences carries the time column's rounding.
    tick = (dt > 0.0) ? std::min(std::round(dt * 1e9) * 1e-9, 10e-3) : 1e-3;
  }
  res.tick = tick;

  typename Mon::Config cfg;
  cfg.observer.tick = tick;
  for (std::size_t c = 0; c < 4; ++c) {
    cfg.sensors.range_lo[c] = options.sensors.lo[c];
    cfg.sensors.range_hi[c] = options.sensors.hi[c];
  }
  // Without diagnosis the matcher gets an empty table: it then never raises an event.
  const int table_rows = options.diagnose ? kThesisSignatureCount : 0;
  if (mon.configure(params, cfg, kThesisSignatures, table_rows) != Status::kOk) {
    res.notes.push_back("invalid parameters or configuration: nothing replayed");
    failed = true;
    return;
  }

  const ThesisInputs<double> u0 = InputColumns(log, input_present, defaults).at(0);
  typename Obs::Measurement first;
  for (int c = 0; c < 4; ++c) {
    first.y[c] = (mask & (1u << c)) ? log.values[index(kMeasuredSignals[static_cast<std::size_t>(c)])][0] : 0.0;
  }
  first.valid = mask;
  Status status = Status::kInvalidInputs;
  if (options.init == InitMode::kAuto) {
    status = mon.reset_measured(u0, first, &res.start);
  } else if (options.init == InitMode::kSteady) {
    status = mon.reset_steady(u0);
    res.start = InitialState::kSteady;
    if (status != Status::kOk) res.notes.push_back("no steady state for the first row's inputs: started at rest");
  }
  if (status != Status::kOk) {
    mon.reset_rest(u0);
    res.start = InitialState::kRest;
  }
  res.startup_hold = mon.startup_hold();
  u_prev = u0;
  double sigma[4];
  for (int c = 0; c < 4; ++c) sigma[c] = mon.evaluator().sigma(c);
  envelope(mon).configure(mon.observer().model(), sigma);
  envelope(mon).start(res.t_first + res.startup_hold);
}

// The monitor over one chunk's rows (row numbers and statistics continue across chunks).
template <class Mon>
void ChunkedReplay::State::run(Mon& mon, const LogData& log, std::size_t rows_total) {
  using Obs = typename Mon::Obs;
  const std::size_t rows = log.rows();
  const std::vector<double>& t = log.t;
  const InputColumns in(log, input_present, defaults);
  const double* meas[4];
  for (int c = 0; c < 4; ++c) {
    meas[c] = (mask & (1u << c)) ? log.values[index(kMeasuredSignals[static_cast<std::size_t>(c)])].data() : nullptr;
  }
  const Obs& obs = mon.observer();
  const double tick = res.tick;
  if (options.keep_trace) res.trace.reserve(res.trace.size() + rows);
  const std::size_t progress_every = std::max<std::size_t>(1, rows_total / 100);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  typename Obs::Measurement m;
  const typename Obs::Measurement none;
  typename Mon::Event ev;
  auto& env = envelope(mon);
  auto drain_events = [&] {
    while (mon.pop_event(ev)) {
      if (!out_of_envelope) res.events.push_back(to_replay_event(ev));
    }
  };

  for (std::size_t k = 0; k < rows; ++k, ++row) {
    // Ticks without a measurement until the model clock reaches this row (inputs held).
    const double t_row = t[k] - res.t_first;
    while (t_row - static_cast<double>(obs.ticks()) * tick > 0.5 * tick) {
      mon.step(res.t_first + static_cast<double>(obs.ticks()) * tick, u_prev, none);
      res.health |= mon.health();
      res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs.substeps());
    }
    const ThesisInputs<double> u = in.at(k);
    for (int c = 0; c < 4; ++c) m.y[c] = meas[c] ? meas[c][k] : 0.0;
    m.valid = mask;
    mon.step(t[k], u, m);
    drain_events();
    if (!res.events.empty()) env.detected(res.events.front().t);
    env.add(t[k], u, obs.residual().data(), obs.residual_valid(), mon.model_bound());
    if (!out_of_envelope && env.verdict() == EnvelopeVerdict::kOutside && options.diagnose) {
      // It supersedes what was said before: a detection while the run settled names
      // faults on a model that does not apply.
      out_of_envelope = true;
      res.events.assign(1, envelope_event(t[k], envelope_now(mon), res.events));
    }
    if (row == 0) {
      for (int c = 0; c < 4; ++c) res.thresholds[static_cast<std::size_t>(c)] = mon.evaluator().bound(c);
    }
    const std::uint32_t flags = mon.health();
    res.health |= flags;
    if (flags) ++res.unhealthy_rows;
    res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs.substeps());
    u_prev = u;

    const auto& r = obs.residual();
    const std::uint8_t rv = obs.residual_valid();
    for (int c = 0; c < 4; ++c) {
      if (!(rv & (1u << c))) continue;
      res.channels[static_cast<std::size_t>(c)].add(r[c], t[k], row);
    }
    if (options.keep_trace) {
      TraceRow tr;
      tr.t = t[k];
      tr.health = flags;
      for (int c = 0; c < 4; ++c) {
        const auto i = static_cast<std::size_t>(c);
        tr.y[i] = meas[c] ? meas[c][k] : nan;
        tr.y_hat[i] = obs.estimate()[c];
        tr.r[i] = (rv & (1u << c)) ? r[c] : nan;
      }
      res.trace.push_back(tr);
    }
    if (rows_total > 0 && options.progress && (row + 1) % progress_every == 0) {
      options.progress(static_cast<double>(row + 1) / static_cast<double>(rows_total));
    }
  }
  drain_events();
  res.rows = row;
  res.t_last = t.back();
}

ChunkedReplay::ChunkedReplay(const ThesisParams<double>& params, const ThesisInputs<double>& defaults,
                             const ReplayOptions& options)
    : s_(std::make_unique<State>()) {
  s_->params = params;
  s_->defaults = defaults;
  s_->options = options;
}

ChunkedReplay::~ChunkedReplay() = default;

void ChunkedReplay::add(const LogData& chunk, std::size_t rows_total) {
  if (chunk.rows() == 0) return;
  if (!s_->started) s_->start(chunk);
  if (s_->failed) {
    // Nothing replayed: the rows and the time span are still said, as replay() did.
    s_->row += chunk.rows();
    s_->res.rows = s_->row;
    s_->res.t_last = chunk.t.back();
    return;
  }
  s_->run(chunk, rows_total);
}

ReplayResult ChunkedReplay::finish() {
  ReplayResult res = std::move(s_->res);
  if (s_->started && !s_->failed) {
    s_->with_monitor([this, &res](auto& mon) {
      res.ticks = mon.observer().ticks();
      res.final_status = s_->out_of_envelope ? "out_of_envelope" : to_string(mon.matcher().status());
      s_->envelope(mon).finish();
      res.envelope = s_->envelope_now(mon);
      // Detected before the machine was seen to match the model, and never judged: no
      // fault can be named on it.
      if (res.envelope.unverified && s_->options.diagnose && !res.events.empty()) {
        res.events.assign(1, envelope_event(res.t_last, res.envelope, res.events));
        res.final_status = "unverified";
      }
    });
  }
  return res;
}

ReplayResult replay(const LogData& log, const ThesisParams<double>& params,
                    const ThesisInputs<double>& defaults, const ReplayOptions& options) {
  ChunkedReplay r(params, defaults, options);
  r.add(log, log.rows());
  ReplayResult res = r.finish();
  res.rows = log.rows();
  if (log.rows() > 0) {
    res.t_first = log.t.front();
    res.t_last = log.t.back();
  }
  return res;
}

ReplayEvent to_replay_event(const MatchEvent<double>& e) {
  ReplayEvent out;
  out.t = e.time;
  out.event = to_string(e.kind);
  out.consistent = e.consistent;
  // The matcher's cosine is negative when the residuals point away from a fault's
  // direction: no match at all, so 0 (a printed "-0.3" read as a bug).
  for (int j = 0; j < e.count; ++j) {
    ReplayCandidate c;
    c.fault = e.candidate[j].name;
    c.score = std::max(0.0, static_cast<double>(e.candidate[j].score));
    out.candidates.push_back(std::move(c));
  }
  return out;
}

}  // namespace hstmon::host
