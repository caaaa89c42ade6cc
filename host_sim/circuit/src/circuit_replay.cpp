#include "hstmon_circuit/circuit_replay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "hstmon/circuit/engine.hpp"
#include "hstmon/observer.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::circuit_tools {

namespace {

using Model = host::HostCircuitModel;
using Obs = Observer<Model, false>;

double median_interval(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> d(t.size() - 1);
  for (std::size_t k = 1; k < t.size(); ++k) d[k - 1] = t[k] - t[k - 1];
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// True when every channel of m is measured with a noise σ > 0 and lies within 3σ of the
// outputs at the steady state for inputs u.
bool at_steady_within_noise(const LoadedCircuit& c, Model model, const Model::Inputs& u, const Obs::Measurement& m) {
  const std::size_t channels = c.file.sensors.size();
  if (channels == 0) return false;
  model.set_inputs(u);
  Model::State xs;
  if (!model.steady_state(xs)) return false;
  const Model::Output ys = model.outputs(xs);
  for (std::size_t ch = 0; ch < channels; ++ch) {
    const int i = static_cast<int>(ch);
    const double sigma = c.file.sensors[ch].noise;
    if ((m.valid & (1u << ch)) == 0 || !(sigma > 0.0)) return false;
    if (!(std::fabs(m.y[i] - ys[i]) <= 3.0 * sigma)) return false;
  }
  return true;
}

}  // namespace

CircuitReplayResult replay_circuit(const LoadedCircuit& c, const CircuitLog& log, const CircuitReplayOptions& o) {
  CircuitReplayResult res;
  const std::size_t channels = c.file.sensors.size();
  res.measured.assign(channels, false);
  res.clipped.assign(channels, 0);
  res.channels.assign(channels, host::ChannelStats{});
  res.rows = log.rows();
  res.notes.push_back("residuals only: the fault matcher is thesis-only for now (no diagnosis for circuit " +
                      c.file.name + ")");
  if (res.rows == 0) return res;
  const std::vector<double>& t = log.t;
  res.t_first = t.front();
  res.t_last = t.back();

  double tick = o.tick;
  if (!(tick > 0.0)) {
    const double dt = median_interval(t);
    tick = dt > 0.0 ? std::min(std::round(dt * 1e9) * 1e-9, 10e-3) : 1e-3;
  }
  res.tick = tick;

  const std::size_t n_inputs = c.file.inputs.size();
  std::vector<const double*> in_col(n_inputs, nullptr);
  for (std::size_t i = 0; i < n_inputs; ++i) {
    if (i < log.inputs.size() && log.inputs[i].size() == res.rows) {
      in_col[i] = log.inputs[i].data();
    } else {
      res.notes.push_back("input " + c.file.inputs[i].name + " (column " + c.file.inputs[i].column +
                          ") not in log: held at " + number(c.values.inputs.v[i]) + " " +
                          host::circuit_si_unit(c.file.inputs[i].quantity));
    }
  }
  std::vector<const double*> meas(channels, nullptr);
  std::uint8_t mask = 0;
  for (std::size_t ch = 0; ch < channels; ++ch) {
    if (ch < log.sensors.size() && log.sensors[ch].size() == res.rows) {
      meas[ch] = log.sensors[ch].data();
      res.measured[ch] = true;
      mask = static_cast<std::uint8_t>(mask | (1u << ch));
    }
  }
  if (mask == 0) res.notes.push_back("no sensor column of circuit " + c.file.name + " in the log: nothing compared");
  auto inputs_at = [&](std::size_t row) {
    Model::Inputs u = c.values.inputs;
    for (std::size_t i = 0; i < n_inputs; ++i) {
      if (in_col[i] != nullptr) u.v[i] = in_col[i][row];
    }
    return u;
  };

  // The description outlives the model and the observer (both refer to it by pointer).
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = circuit::auto_stiff_mask<double>(desc, c.values.params, c.values.inputs, tick);
  Model model(desc, c.values.params, c.values.inputs);
  if (model.error() != circuit::CircuitError::kOk || !model.valid()) {
    res.notes.push_back("the circuit's values do not make a physical circuit: nothing replayed");
    return res;
  }
  res.states = model.n_states();
  res.stiff_nodes = model.n_stiff();
  auto obs = std::make_unique<Obs>();
  Obs::Config cfg;
  cfg.tick = tick;
  if (obs->configure(model, cfg) != Status::kOk) {
    res.notes.push_back("invalid observer configuration: nothing replayed");
    return res;
  }

  const Model::Inputs u0 = inputs_at(0);
  Obs::Measurement m;
  // A reading at or beyond an end of its transmitter's range says only that the signal is
  // there or beyond: it is not compared (counted in res.clipped).
  auto measurement_at = [&](std::size_t row) {
    m.valid = mask;
    for (std::size_t ch = 0; ch < channels; ++ch) {
      const double y = meas[ch] ? meas[ch][row] : 0.0;
      m.y[static_cast<int>(ch)] = y;
      const host::CircuitSensor& s = c.file.sensors[ch];
      if (meas[ch] != nullptr && (y <= s.lo || y >= s.hi)) {
        m.valid = static_cast<std::uint8_t>(m.valid & ~(1u << ch));
        ++res.clipped[ch];
      }
    }
  };
  measurement_at(0);
  Status started = Status::kInvalidInputs;
  if (o.init == host::InitMode::kAuto) {
    started = obs->reset_measured(u0, m, &res.start);
    if (started == Status::kOk && at_steady_within_noise(c, model, u0, m)) {
      // The readings' noise would otherwise be the initial error of a parallel model,
      // which a lightly damped circuit (a closed-loop HST) rings with for seconds.
      started = obs->reset_steady(u0);
      res.start = InitialState::kSteady;
      res.notes.push_back("first row within 3 sigma of the steady state on every channel: started there");
    }
  } else if (o.init == host::InitMode::kSteady) {
    started = obs->reset_steady(u0);
    res.start = InitialState::kSteady;
    if (started != Status::kOk) res.notes.push_back("no steady state for the first row's inputs: started at rest");
  }
  if (started != Status::kOk) {
    (void)obs->reset_rest(u0);
    res.start = InitialState::kRest;
  }

  res.clipped.assign(channels, 0);  // the first row is counted again below
  Model::Inputs u_prev = u0;
  const Obs::Measurement none;
  for (std::size_t k = 0; k < res.rows; ++k) {
    const double t_row = t[k] - res.t_first;
    while (t_row - static_cast<double>(obs->ticks()) * tick > 0.5 * tick) {
      res.health |= obs->step(u_prev, none);
      res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs->substeps());
    }
    const Model::Inputs u = inputs_at(k);
    measurement_at(k);
    const std::uint32_t flags = obs->step(u, m);
    res.health |= flags;
    if (flags != 0) ++res.unhealthy_rows;
    res.max_substeps = std::max<std::uint32_t>(res.max_substeps, obs->substeps());
    u_prev = u;
    const std::uint8_t rv = obs->residual_valid();
    for (std::size_t ch = 0; ch < channels; ++ch) {
      if ((rv & (1u << ch)) != 0) res.channels[ch].add(obs->residual()[static_cast<int>(ch)], t[k], k);
    }
  }
  res.ticks = obs->ticks();
  for (std::size_t ch = 0; ch < channels; ++ch) {
    if (res.clipped[ch] > 0) {
      res.notes.push_back(c.file.sensors[ch].name + ": " + std::to_string(res.clipped[ch]) +
                          " row(s) at an end of the sensor's range (" + number(c.file.sensors[ch].lo) + " .. " +
                          number(c.file.sensors[ch].hi) + " " + host::circuit_si_unit(c.file.sensors[ch].quantity) +
                          ") not compared");
    }
  }
  return res;
}

}  // namespace hstmon::circuit_tools
