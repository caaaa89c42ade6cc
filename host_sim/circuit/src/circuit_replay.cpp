#include "hstmon_circuit/circuit_replay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "hstmon/circuit/circuit_monitor.hpp"
#include "hstmon/circuit/engine.hpp"
#include "hstmon/envelope_check.hpp"
#include "hstmon/fault_estimator.hpp"
#include "hstmon/circuit/monitor_setup.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/compiled_circuits.hpp"
#include "hstmon_circuit/fault_fit_diagnosis.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/envelope_result.hpp"
#include "hstmon_host/number_text.hpp"

namespace hstmon::circuit_tools {

namespace {

// The interpreter: the fit, the bound leads, and the monitor of a circuit not compiled in.
using Model = host::HostCircuitModel;
// The monitor on model M (the interpreter, or a compiled circuit's model: compiled_circuits.hpp).
// 127 rows: every named parameter twice and every channel, for the host's capacity.
template <class M>
using MonitorOn = ModelMonitor<M, 127>;

// Host values (Params, Inputs: the file's capacity) as model M holds them: the first
// entries, as many as M has room for (same_circuit checked that the circuit's fit).
template <class To, class From>
To first_entries(const From& from) {
  To to{};
  constexpr std::size_t n = std::min(std::extent_v<decltype(To::v)>, std::extent_v<decltype(From::v)>);
  for (std::size_t i = 0; i < n; ++i) to.v[i] = from.v[i];
  return to;
}

// The fault table's rows as monitor Mon's matcher takes them (its channel count).
template <class Mon>
std::vector<typename Mon::Signature> matcher_rows(const CircuitFaultTable* table, std::size_t count) {
  using Row = typename Mon::Signature;
  static_assert(Row::kChannels <= CircuitFaultTable::Row::kChannels, "a compiled circuit fits the host's capacity");
  std::vector<Row> rows(table != nullptr ? count : 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const CircuitFaultTable::Row& from = table->rows[k];
    rows[k].name = from.name;
    rows[k].sensor = from.sensor;
    for (std::size_t ch = 0; ch < static_cast<std::size_t>(Row::kChannels); ++ch) {
      rows[k].channel[ch] = from.channel[ch];
      rows[k].direction[ch] = from.direction[ch];
    }
  }
  return rows;
}

double median_interval(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> d(t.size() - 1);
  for (std::size_t k = 1; k < t.size(); ++k) d[k - 1] = t[k] - t[k - 1];
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// The circuit's sensors as the envelope sentence names them: in their logged units.
std::vector<host::EnvelopeChannel> envelope_channels(const LoadedCircuit& c) {
  std::vector<host::EnvelopeChannel> out;
  for (const host::CircuitSensor& s : c.file.sensors) {
    const host::UnitResult unit = host::parse_circuit_unit(s.quantity, s.unit);
    out.push_back({s.name, s.unit.empty() ? host::circuit_si_unit(s.quantity) : s.unit,
                   unit.ok() ? 1.0 / unit.conversion.factor : 1.0});
  }
  return out;
}

const char* const kEnvelopeRemedy =
    "Run `hstmon identify --circuit` on healthy steady data, or `hstmon gap --circuit`";

// The observer tick [s]: the option's, else the log's median sampling interval (to the ns), at most 10 ms.
double replay_tick(double option, const std::vector<double>& t) {
  if (option > 0.0) return option;
  const double dt = median_interval(t);
  return dt > 0.0 ? std::min(std::round(dt * 1e9) * 1e-9, 10e-3) : 1e-3;
}

// Where the circuit's inputs and sensors are in the log (nullptr: not there) and which channels are measured.
struct LogColumns {
  std::vector<const double*> inputs;   ///< per input of the circuit file
  std::vector<const double*> sensors;  ///< per channel
  std::uint8_t mask = 0;               ///< channels in the log

  /// Row `row`'s inputs: the log's where it has them, else `held` (the circuit file's values).
  Model::Inputs inputs_at(const Model::Inputs& held, std::size_t row) const {
    Model::Inputs u = held;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (inputs[i] != nullptr) u.v[i] = inputs[i][row];
    }
    return u;
  }
};

// The log's columns for c; notes the inputs held and marks the channels measured in res.
LogColumns log_columns(const LoadedCircuit& c, const CircuitLog& log, CircuitReplayResult& res) {
  LogColumns cols;
  const std::size_t n_inputs = c.file.inputs.size();
  cols.inputs.assign(n_inputs, nullptr);
  for (std::size_t i = 0; i < n_inputs; ++i) {
    if (i < log.inputs.size() && log.inputs[i].size() == res.rows) {
      cols.inputs[i] = log.inputs[i].data();
    } else {
      res.notes.push_back(
          "input " + c.file.inputs[i].name + " (column " + c.file.inputs[i].column + ") not in log: held at " +
          host::display_unit(c.file.inputs[i].quantity, c.file.inputs[i].unit).text(c.values.inputs.v[i], 4));
    }
  }
  const std::size_t channels = c.file.sensors.size();
  cols.sensors.assign(channels, nullptr);
  for (std::size_t ch = 0; ch < channels; ++ch) {
    if (ch < log.sensors.size() && log.sensors[ch].size() == res.rows) {
      cols.sensors[ch] = log.sensors[ch].data();
      res.measured[ch] = true;
      cols.mask = static_cast<std::uint8_t>(cols.mask | (1u << ch));
    }
  }
  if (cols.mask == 0) res.notes.push_back("no sensor column of circuit " + c.file.name + " in the log: nothing compared");
  return cols;
}

// The matcher's fault table: the caller's, or built into `built`; nullptr when it cannot be built
// (residuals only). Sets res.table_rows (at most the monitor's 127) and res.undetectable.
const CircuitFaultTable* matcher_table(const LoadedCircuit& c, const CircuitReplayOptions& o, CircuitFaultTable& built,
                                       CircuitReplayResult& res) {
  const CircuitFaultTable* table = nullptr;
  try {
    if (o.table != nullptr) {
      table = o.table;
    } else {
      built = o.fault_table != nullptr ? o.fault_table(c) : circuit_fault_table(c);
      table = &built;
    }
    res.table_rows = table->rows.size();
    res.undetectable = table->undetectable;
    for (const auto& n : table->notes) res.notes.push_back("fault table: " + n);
    if (table->rows.size() > 127) {
      res.notes.push_back("fault table: " + std::to_string(table->rows.size()) + " rows, the first 127 used");
      res.table_rows = 127;
    }
  } catch (const std::exception& e) {
    res.notes.push_back(std::string(e.what()) + ": residuals only");
  }
  return table;
}

// The monitor's configuration for c at this tick: sensor noise and ranges from the circuit file,
// the circuit allowances, and matcher windows that follow the slowest time constant at u0.
template <class Mon>
typename Mon::Config monitor_config(const LoadedCircuit& c, const typename Mon::Model& model, double tick,
                                    const typename Mon::Inputs& u0, std::vector<std::string>& notes) {
  const std::size_t channels = c.file.sensors.size();
  typename Mon::Config cfg;
  cfg.observer.tick = tick;
  for (int i = 0; i < Mon::kChannels; ++i) {
    const auto ch = static_cast<std::size_t>(i);
    double sigma = 1.0, lo = -HUGE_VAL, hi = HUGE_VAL;
    if (ch < channels) {
      const host::CircuitSensor& s = c.file.sensors[ch];
      sigma = sensor_sigma(s);
      if (!(s.noise > 0.0)) {
        notes.push_back(s.name + ": no noise in the circuit file: sigma taken as 1 % of its span, " +
                        host::display_unit(s.quantity, s.unit).text(sigma));
      }
      lo = s.lo;
      hi = s.hi;
    }
    cfg.evaluator.noise_sigma[i] = sigma;
    cfg.sensors.noise[i] = sigma;
    cfg.sensors.range_lo[i] = lo;
    cfg.sensors.range_hi[i] = hi;
  }
  const auto uncertainty = circuit_uncertainty(c);
  constexpr std::size_t n_params = std::extent_v<decltype(cfg.uncertainty.rel)>;
  static_assert(n_params <= std::extent_v<decltype(uncertainty.rel)>, "a compiled circuit fits the host's capacity");
  for (std::size_t k = 0; k < n_params; ++k) cfg.uncertainty.rel[k] = uncertainty.rel[k];
  // What a circuit file does not say (its damping, how far a fault moves the model error)
  // the monitor allows for (circuit::set_circuit_allowances, shared with the firmware).
  circuit::set_circuit_allowances(cfg);
  // The matcher's windows follow the slowest time constant where the machine runs
  // (ModelMonitor::Config::settle_taus, set above); the first row's, for the reader.
  typename Mon::Model scratch = model;
  const double inf = std::numeric_limits<double>::infinity();
  const double tau = settle_time(scratch, u0, 1.0, 0.0, inf);
  if (std::isfinite(tau)) {
    notes.push_back("the matcher settles for " + host::number_text(cfg.settle_taus, 3) +
                    " and averages over 1 of the slowest time constants at each operating point, at least " +
                    host::number_text(cfg.matcher.settle_time, 3) + " s and " +
                    host::number_text(cfg.matcher.average_time, 3) + " s (" + host::number_text(tau, 3) +
                    " s at the first row's inputs)");
  }
  return cfg;
}

// One row's readings as the monitor takes them. A reading at or beyond an end of its
// transmitter's range says only that the signal is there or beyond: the monitor's sensor
// checks judge it, the statistics leave it out (counted in clipped; `compared` has the others).
template <class Mon>
struct Readings {
  typename Mon::Measurement m;
  std::uint8_t compared = 0;

  void read(std::size_t row, const LogColumns& cols, const std::vector<host::CircuitSensor>& sensors,
            std::vector<std::size_t>& clipped) {
    m.valid = cols.mask;
    compared = cols.mask;
    for (std::size_t ch = 0; ch < sensors.size(); ++ch) {
      const double* col = cols.sensors[ch];
      const double y = col ? col[row] : 0.0;
      m.y[static_cast<int>(ch)] = y;
      if (col != nullptr && (y <= sensors[ch].lo || y >= sensors[ch].hi)) {
        compared = static_cast<std::uint8_t>(compared & ~(1u << ch));
        ++clipped[ch];
      }
    }
  }
};

// Starts the monitor at u0 as o.init asks (auto: at the first row's readings, or at the steady
// state when they are within noise of it), at rest when that fails; sets res.start and the hold-off.
template <class Mon>
void start_monitor(Mon& mon, const typename Mon::Model& model, const LoadedCircuit& c, host::InitMode init,
                   const typename Mon::Inputs& u0, const typename Mon::Measurement& m, CircuitReplayResult& res) {
  const std::size_t channels = c.file.sensors.size();
  Status started = Status::kInvalidInputs;
  if (init == host::InitMode::kAuto) {
    started = mon.reset_measured(u0, m, &res.start);
    double noise[Mon::kChannels] = {};
    for (std::size_t ch = 0; ch < channels && ch < static_cast<std::size_t>(Mon::kChannels); ++ch) {
      noise[ch] = c.file.sensors[ch].noise;
    }
    typename Mon::Model scratch = model;
    if (started == Status::kOk &&
        circuit::at_steady_within_noise(scratch, u0, m.y, m.valid, noise, static_cast<int>(channels))) {
      // The readings' noise would otherwise be the initial error of a parallel model,
      // which a lightly damped circuit (a closed-loop HST) rings with for seconds.
      started = mon.reset_steady(u0);
      res.start = InitialState::kSteady;
      res.notes.push_back("first row within 3 sigma of the steady state on every channel: started there");
    }
  } else if (init == host::InitMode::kSteady) {
    started = mon.reset_steady(u0);
    res.start = InitialState::kSteady;
    if (started != Status::kOk) res.notes.push_back("no steady state for the first row's inputs: started at rest");
  }
  if (started != Status::kOk) {
    (void)mon.reset_rest(u0);
    res.start = InitialState::kRest;
  }
  res.startup_hold = mon.startup_hold();
}

// Row k's measured, model, residual (rv: the channels compared) and bound per channel; leads filled by the caller.
template <class Mon>
CircuitTraceRow trace_row(const Mon& mon, const LogColumns& cols, std::size_t k, double t, std::uint32_t health,
                          unsigned rv) {
  const auto& obs = mon.observer();
  CircuitTraceRow tr;
  tr.t = t;
  tr.health = health;
  for (std::size_t ch = 0; ch < cols.sensors.size(); ++ch) {
    const int i = static_cast<int>(ch);
    tr.y.push_back(cols.sensors[ch] != nullptr ? cols.sensors[ch][k] : std::nan(""));
    tr.y_hat.push_back(obs.estimate()[i]);
    tr.r.push_back((rv & (1u << ch)) != 0 ? obs.residual()[i] : std::nan(""));
    tr.bound.push_back(mon.evaluator().bound(i));
  }
  return tr;
}

// The fit's view of the row just stepped.
template <class Mon>
FaultFitDiagnosis::Row fit_row(const Mon& mon, double t, const Readings<Mon>& r, const Model::Inputs* bound_u) {
  const auto& obs = mon.observer();
  FaultFitDiagnosis::Row row;
  row.t = t;
  row.y = r.m.y.data();
  row.valid = r.compared;
  row.r = obs.residual().data();
  row.y_hat = obs.estimate().data();
  row.r_valid = obs.residual_valid();
  row.bound = mon.model_bound();
  row.matcher_quiet = mon.matcher().status() == MatchStatus::kNominal;
  row.steady_y = bound_u != nullptr ? mon.steady_outputs_at_bound_inputs() : nullptr;
  row.bound_u = bound_u;
  return row;
}

// Notes the rows left out of each channel's statistics because its reading was at a range end.
void note_clipped(const LoadedCircuit& c, CircuitReplayResult& res) {
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    if (res.clipped[ch] > 0) {
      const host::CircuitSensor& s = c.file.sensors[ch];
      const host::DisplayUnit d = host::display_unit(s.quantity, s.unit);
      res.notes.push_back(s.name + ": " + std::to_string(res.clipped[ch]) +
                          " row(s) at an end of the sensor's range (" + host::number_text(d.of(s.lo), 4) + " … " +
                          d.text(s.hi, 4) + ") not compared");
    }
  }
}

// One replay through monitor Mon on `model` (the interpreter, or a compiled circuit's
// model); `host_model` is the interpreter on the same description and values, for the fit
// and the bound leads. res holds what replay_circuit set up (rows, tick, table size).
template <class Mon>
void run_monitor(const LoadedCircuit& c, const CircuitLog& log, const CircuitReplayOptions& o,
                 const typename Mon::Model& model, const Model& host_model, const LogColumns& cols,
                 const CircuitFaultTable* table, CircuitReplayResult& res) {
  using Inputs = typename Mon::Inputs;
  const std::size_t channels = c.file.sensors.size();
  const std::vector<double>& t = log.t;
  const double tick = res.tick;
  const std::uint8_t mask = cols.mask;
  auto host_inputs_at = [&](std::size_t row) { return cols.inputs_at(c.values.inputs, row); };
  auto inputs_of = [](const Model::Inputs& u) { return first_entries<Inputs>(u); };

  // The matcher borrows its rows: they live as long as the monitor.
  const std::vector<typename Mon::Signature> rows = matcher_rows<Mon>(table, res.table_rows);
  auto mon = std::make_unique<Mon>();
  const typename Mon::Config cfg = monitor_config<Mon>(c, model, tick, inputs_of(host_inputs_at(0)), res.notes);
  if (mon->configure(model, cfg, rows.empty() ? nullptr : rows.data(), static_cast<int>(rows.size())) != Status::kOk) {
    res.notes.push_back("invalid monitor configuration: nothing replayed");
    return;
  }
  const auto& obs = mon->observer();

  const Model::Inputs host_u0 = host_inputs_at(0);
  Readings<Mon> readings;
  const typename Mon::Measurement& m = readings.m;
  readings.read(0, cols, c.file.sensors, res.clipped);
  start_monitor(*mon, model, c, o.init, inputs_of(host_u0), m, res);

  res.clipped.assign(channels, 0);  // the first row is counted again below
  Model::Inputs host_u_prev = host_u0;
  Inputs u_prev = inputs_of(host_u0);
  const typename Mon::Measurement none;
  typename Mon::Event ev;
  // The matcher detects; the fit over the steady windows after a detection decides.
  std::unique_ptr<FaultFitDiagnosis> diag;
  if (res.table_rows > 0 && o.fit) diag = std::make_unique<FaultFitDiagnosis>(c, host_model, mask, o.healthy_record);
  // Outside the model's envelope at the first steady stretch, nothing more is diagnosed.
  EnvelopeCheck<typename Mon::Model> envelope;
  {
    double sigma[Mon::kChannels] = {};
    for (std::size_t ch = 0; ch < channels; ++ch) sigma[ch] = sensor_sigma(c.file.sensors[ch]);
    envelope.configure(model, sigma);
  }
  envelope.start(res.t_first + res.startup_hold);
  const std::vector<host::EnvelopeChannel> envelope_names = envelope_channels(c);
  auto envelope_now = [&] {
    return host::envelope_result(host::envelope_figures(envelope), envelope_names, kEnvelopeRemedy);
  };
  bool out_of_envelope = false;
  // The monitor's bound inputs as the fit takes them (host inputs: the file's other entries 0).
  Inputs bound_u{};
  Model::Inputs host_bound_u{};
  auto to_host_inputs = [](const Inputs& u) { return first_entries<Model::Inputs>(u); };
  // The trace's bound leads, recomputed where the monitor's bound changed (an input change).
  std::vector<ChannelBoundLead> leads;
  std::vector<double> lead_bound;
  auto drain_events = [&](double t_now, const Model::Inputs& u) {
    while (mon->pop_event(ev)) {
      if (out_of_envelope) continue;
      const host::ReplayEvent e = host::to_replay_event(ev);
      if (diag) {
        diag->on_matcher_event(e, t_now, u, mon->matcher().sensor_faults() != 0, res.events);
      } else {
        res.events.push_back(e);
      }
    }
  };
  for (std::size_t k = 0; k < res.rows; ++k) {
    const double t_row = t[k] - res.t_first;
    while (t_row - static_cast<double>(obs.ticks()) * tick > 0.5 * tick) {
      mon->step(res.t_first + static_cast<double>(obs.ticks()) * tick, u_prev, none);
      res.health |= mon->health();
      res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs.substeps());
    }
    const Model::Inputs host_u = host_inputs_at(k);
    const Inputs u = inputs_of(host_u);
    readings.read(k, cols, c.file.sensors, res.clipped);
    const std::uint8_t compared = readings.compared;
    mon->step(t[k], u, m);
    drain_events(t[k], host_u);
    if (!res.events.empty()) envelope.detected(res.events.front().t);
    envelope.add(t[k], u, obs.residual().data(), obs.residual_valid() & compared, mon->model_bound());
    if (!out_of_envelope && envelope.verdict() == EnvelopeVerdict::kOutside && o.diagnose && res.table_rows > 0) {
      // It supersedes what was said before (a detection while the run settled names
      // faults on a model that does not apply).
      out_of_envelope = true;
      res.events.assign(1, host::envelope_event(t[k], envelope_now(), res.events));
    }
    if (diag && !out_of_envelope) {
      if (o.share_bound && !(mon->bound_inputs() == bound_u)) {
        bound_u = mon->bound_inputs();
        host_bound_u = to_host_inputs(bound_u);
      }
      diag->on_row(fit_row(*mon, t[k], readings, o.share_bound ? &host_bound_u : nullptr), host_u, res.events);
    }
    const std::uint32_t flags = mon->health();
    res.health |= flags;
    if (flags != 0) ++res.unhealthy_rows;
    res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs.substeps());
    u_prev = u;
    host_u_prev = host_u;
    const unsigned rv = obs.residual_valid() & compared;
    for (std::size_t ch = 0; ch < channels; ++ch) {
      if ((rv & (1u << ch)) != 0) res.channels[ch].add(obs.residual()[static_cast<int>(ch)], t[k], k);
    }
    if (o.keep_trace) {
      CircuitTraceRow tr = trace_row(*mon, cols, k, t[k], flags, rv);
      const double* mb = mon->model_bound();
      if (lead_bound.empty() || !std::equal(lead_bound.begin(), lead_bound.end(), mb)) {
        lead_bound.assign(mb, mb + channels);
        leads = bound_leads(c, host_model, host_u);
      }
      tr.lead = leads;
      res.trace.push_back(std::move(tr));
    }
  }
  drain_events(res.t_last, host_u_prev);
  res.ticks = obs.ticks();
  res.final_status = to_string(mon->matcher().status());
  envelope.finish();
  res.envelope = envelope_now();
  res.bound_lead = bound_leads(c, host_model, host_u_prev);
  if (out_of_envelope) {
    res.final_status = "out_of_envelope";
  } else if (res.envelope.unverified && o.diagnose && res.table_rows > 0 && !res.events.empty()) {
    // Detected before the machine was seen to match the model, and never judged: no fault
    // can be named on it.
    res.events.assign(1, host::envelope_event(res.t_last, res.envelope, res.events));
    res.final_status = "unverified";
  } else if (diag) {
    diag->finish(res.t_last, res.events);
    res.final_status = diag->status();
  }
  res.implicit_ticks = obs.implicit_ticks();
}

}  // namespace

CircuitReplayResult replay_circuit(const LoadedCircuit& c, const CircuitLog& log, const CircuitReplayOptions& o) {
  CircuitReplayResult res;
  const std::size_t channels = c.file.sensors.size();
  res.measured = std::vector<bool>(channels, false);
  res.clipped.assign(channels, 0);
  res.channels.assign(channels, host::ChannelStats{});
  res.rows = log.rows();
  if (res.rows == 0) return res;
  res.t_first = log.t.front();
  res.t_last = log.t.back();
  res.tick = replay_tick(o.tick, log.t);
  const LogColumns cols = log_columns(c, log, res);

  // The description outlives the model and the observer (both refer to it by pointer).
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = circuit::auto_stiff_mask<double>(desc, c.values.params, c.values.inputs, res.tick);
  const Model model(desc, c.values.params, c.values.inputs);
  if (model.error() != circuit::CircuitError::kOk || !model.valid()) {
    res.notes.push_back("the circuit's values do not make a physical circuit: nothing replayed");
    return res;
  }
  res.states = model.n_states();
  res.stiff_nodes = model.n_stiff();

  CircuitFaultTable built;
  const CircuitFaultTable* table = o.diagnose ? matcher_table(c, o, built, res) : nullptr;
  // A circuit compiled into the program runs its generated code: the interpreter's numbers, faster.
  const bool compiled = !o.interpret && with_compiled_kernel(desc, [&](auto kernel) {
    using CompiledModel = circuit::CompiledModel<double, typename decltype(kernel)::type>;
    const CompiledModel compiled_model(first_entries<typename CompiledModel::Params>(c.values.params),
                                       first_entries<typename CompiledModel::Inputs>(c.values.inputs));
    run_monitor<MonitorOn<CompiledModel>>(c, log, o, compiled_model, model, cols, table, res);
  });
  if (!compiled) run_monitor<MonitorOn<Model>>(c, log, o, model, model, cols, table, res);
  res.compiled = compiled;
  note_clipped(c, res);
  return res;
}

}  // namespace hstmon::circuit_tools
