#include "hstmon_host/replay.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/monitor.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace hstmon::host {

const std::array<Signal, 4> kMeasuredSignals = {Signal::kPMi, Signal::kPMo, Signal::kPPp, Signal::kWm};

void ChannelStats::add(double r, double t, std::size_t row) noexcept {
  if (n > 0) {
    sumsq_diff += (r - last) * (r - last);
    ++n_diff;
  }
  last = r;
  ++n;
  sum += r;
  sumsq += r * r;
  if (std::fabs(r) > max_abs) {
    max_abs = std::fabs(r);
    max_signed = r;
    t_max = t;
    row_max = row;
  }
}

double ChannelStats::mean() const noexcept { return n ? sum / static_cast<double>(n) : 0.0; }
double ChannelStats::rms() const noexcept { return n ? std::sqrt(sumsq / static_cast<double>(n)) : 0.0; }
double ChannelStats::noise() const noexcept {
  return n_diff ? std::sqrt(sumsq_diff / (2.0 * static_cast<double>(n_diff))) : 0.0;
}

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

using Model = ThesisReducedModel<double>;
using Mon = Monitor<double>;
using Obs = Mon::Obs;

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

ReplayResult replay(const LogData& log, const ThesisParams<double>& params,
                    const ThesisInputs<double>& defaults, const ReplayOptions& options) {
  ReplayResult res;
  const std::size_t rows = log.rows();
  res.rows = rows;
  if (rows == 0) return res;
  const std::vector<double>& t = log.t;
  res.t_first = t.front();
  res.t_last = t.back();

  InputColumns in;
  in.fallback = defaults;
  const Signal input_signals[4] = {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp};
  const char* input_names[4] = {"p_sup (Psupl)", "p_s (Ps)", "p_bp (Pbp)", "kp"};
  const double input_defaults[4] = {defaults.Psupl, defaults.Ps, defaults.Pbp, defaults.kp};
  for (int i = 0; i < 4; ++i) {
    if (log.present[index(input_signals[i])]) {
      in.col[i] = log.values[index(input_signals[i])].data();
    } else {
      res.notes.push_back(std::string(input_names[i]) + " not in log: held at the parameter value " +
                          std::to_string(input_defaults[i]));
    }
  }
  const double* meas[4];
  std::uint8_t mask = 0;
  for (int c = 0; c < 4; ++c) {
    const std::size_t s = index(kMeasuredSignals[static_cast<std::size_t>(c)]);
    res.measured[static_cast<std::size_t>(c)] = log.present[s];
    meas[c] = log.present[s] ? log.values[s].data() : nullptr;
    if (log.present[s]) mask = static_cast<std::uint8_t>(mask | (1u << c));
  }

  double tick = options.tick;
  if (!(tick > 0.0)) {
    const double dt = median_interval(t);
    // Rounded to 1 ns: the median of differences carries the time column's rounding.
    tick = (dt > 0.0) ? std::min(std::round(dt * 1e9) * 1e-9, 10e-3) : 1e-3;
  }
  res.tick = tick;

  Mon mon;
  Mon::Config cfg;
  cfg.observer.tick = tick;
  for (std::size_t c = 0; c < 4; ++c) {
    cfg.sensors.range_lo[c] = options.sensors.lo[c];
    cfg.sensors.range_hi[c] = options.sensors.hi[c];
  }
  // Without diagnosis the matcher gets an empty table: it then never raises an event.
  const int table_rows = options.diagnose ? kThesisSignatureCount : 0;
  if (mon.configure(params, cfg, kThesisSignatures, table_rows) != Status::kOk) {
    res.notes.push_back("invalid parameters or configuration: nothing replayed");
    return res;
  }
  const Obs& obs = mon.observer();

  const ThesisInputs<double> u0 = in.at(0);
  Obs::Measurement first;
  for (int c = 0; c < 4; ++c) first.y[c] = meas[c] ? meas[c][0] : 0.0;
  first.valid = mask;
  Status started = Status::kInvalidInputs;
  if (options.init == InitMode::kAuto) {
    started = mon.reset_measured(u0, first, &res.start);
  } else if (options.init == InitMode::kSteady) {
    started = mon.reset_steady(u0);
    res.start = InitialState::kSteady;
    if (started != Status::kOk) res.notes.push_back("no steady state for the first row's inputs: started at rest");
  }
  if (started != Status::kOk) {
    mon.reset_rest(u0);
    res.start = InitialState::kRest;
  }
  res.startup_hold = mon.startup_hold();

  if (options.keep_trace) res.trace.reserve(rows);
  const std::size_t progress_every = std::max<std::size_t>(1, rows / 100);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ThesisInputs<double> u_prev = u0;
  Obs::Measurement m;
  const Obs::Measurement none;
  Mon::Event ev;
  auto drain_events = [&] {
    while (mon.pop_event(ev)) res.events.push_back(to_replay_event(ev));
  };

  for (std::size_t k = 0; k < rows; ++k) {
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
    if (k == 0) {
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
      res.channels[static_cast<std::size_t>(c)].add(r[c], t[k], k);
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
    if (options.progress && (k + 1) % progress_every == 0) options.progress(static_cast<double>(k + 1) / static_cast<double>(rows));
  }
  drain_events();
  res.ticks = obs.ticks();
  res.final_status = to_string(mon.matcher().status());
  return res;
}

ReplayEvent to_replay_event(const MatchEvent<double>& e) {
  ReplayEvent out;
  out.t = e.time;
  out.event = to_string(e.kind);
  out.consistent = e.consistent;
  for (int j = 0; j < e.count; ++j) out.candidates.push_back({e.candidate[j].name, e.candidate[j].score});
  return out;
}

}  // namespace hstmon::host
