#include "hstmon_circuit/circuit_sim.hpp"

#include "hstmon/circuit/stiffness.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace hstmon::circuit_tools {

namespace {

using Model = host::HostCircuitModel;

}  // namespace

CircuitLog simulate_circuit(const LoadedCircuit& c, const CircuitSimOptions& o) {
  if (!(o.duration > 0.0 && std::isfinite(o.duration)) || !(o.rate > 0.0 && std::isfinite(o.rate))) {
    throw std::runtime_error("duration and rate must be > 0");
  }
  if (o.duration * o.rate > 1e7) throw std::runtime_error("more than 10 million samples: lower --duration or --rate");
  std::vector<InputStep> steps = o.steps;
  sort_steps(steps);
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = 0;  // the full equations: every volume a state
  Model::Inputs u = c.values.inputs;
  Model::Params p = c.values.params;
  bool params_changed = false;
  std::size_t next = 0;
  auto apply_steps_until = [&](double t) {
    bool changed = false;
    while (next < steps.size() && steps[next].t <= t + 1e-12) {
      const InputStep& st = steps[next];
      if (st.param >= 0) {
        p.v[st.param] = c.values.params.v[st.param] * st.factor;
        params_changed = true;
      } else {
        u.v[st.input] = st.value;
      }
      ++next;
      changed = true;
    }
    return changed;
  };
  apply_steps_until(0.0);
  params_changed = false;
  Model full(desc, p, u);
  if (full.error() != circuit::CircuitError::kOk || !full.valid()) {
    throw std::runtime_error("circuit " + c.file.name + ": the values do not make a physical circuit");
  }
  Model::State x0 = full.rest_state();
  if (!o.from_rest && !full.steady_state(x0)) {
    throw std::runtime_error("circuit " + c.file.name + ": no steady state for the inputs at t = 0 (try --start rest)");
  }

  const int n = full.n_states();
  // What a transducer sees at a sample that falls on a step: no transducer follows the
  // microseconds in which the volumes far faster than the sampling settle (a flow
  // reversing through a valve the instant its supply drops). At such a sample those
  // volumes (the ones an observer at this period takes quasi-steady) are read at their
  // settled pressures, the other states as they are.
  host::HostCircuit settled_desc = c.file.circuit;
  settled_desc.stiff_mask = circuit::auto_stiff_mask<double>(settled_desc, p, u, 1.0 / o.rate);
  std::optional<Model> settled;
  std::vector<int> settled_from_full;  // full-model state index of each settled-model state
  if (settled_desc.stiff_mask != 0) {
    settled.emplace(settled_desc, p, u);
    if (settled->error() != circuit::CircuitError::kOk || !settled->valid()) {
      settled.reset();
    } else {
      for (int j = 0; j < settled->n_states(); ++j) {
        for (int s = 0; s < n; ++s) {
          if (full.state_z(s) == settled->state_z(j)) settled_from_full.push_back(s);
        }
      }
    }
  }
  std::vector<double> abs_tol(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    abs_tol[static_cast<std::size_t>(s)] =
        full.state_z(s) < Model::kNodes ? 1e-7 * full.pressure_envelope() : 1e-7 * full.speed_envelope();
  }
  std::vector<double> x(x0.data(), x0.data() + n);
  std::optional<sim::StiffIntegrator> ref;
  if (n > 0) ref.emplace(abs_tol, 1e-9, 1e-7);
  auto to_state = [n](const double* xs) {
    Model::State s = Model::State::Zero();
    for (int i = 0; i < n; ++i) s[i] = xs[i];
    return s;
  };
  auto restart = [&](double t) {
    if (params_changed) full.set_params(p);
    params_changed = false;
    full.set_inputs(u);
    if (!ref) return;
    ref->restart(
        t, x.data(),
        [&full, &to_state, n](const double* xs, double* dx) {
          const Model::State d = full.derivative(to_state(xs));
          for (int i = 0; i < n; ++i) dx[i] = d[i];
        },
        [&full, &to_state, n](const double* xs, double* jac) {
          Model::StateMatrix J;
          full.jacobian(to_state(xs), J);
          for (int r = 0; r < n; ++r) {
            for (int k = 0; k < n; ++k) jac[r * n + k] = J(r, k);
          }
        });
  };
  restart(0.0);

  std::vector<sim::ChannelSpec> specs;
  for (const host::CircuitSensor& s : c.file.sensors) {
    sim::ChannelSpec ch;
    ch.name = s.name;
    ch.noise_std = o.noise ? s.noise : 0.0;
    ch.range_lo = s.lo;
    ch.range_hi = s.hi;
    specs.push_back(ch);
  }
  sim::SensorChain chain(specs, o.seed);
  const std::size_t channels = specs.size();

  CircuitLog log;
  log.path = c.file.name + " (simulated)";
  log.inputs.assign(c.file.inputs.size(), {});
  log.sensors.assign(channels, {});
  const auto samples = static_cast<std::size_t>(std::llround(o.duration * o.rate));
  log.t.reserve(samples);
  std::vector<double> truth(channels), meas(channels);
  double t_last = 0.0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double ts = static_cast<double>(k) / o.rate;
    // Steps up to this sample, each met exactly by a hard stop.
    bool stepped_here = false;
    while (next < steps.size() && steps[next].t <= ts + 1e-12) {
      stepped_here = stepped_here || std::fabs(steps[next].t - ts) <= 1e-12;
      if (ref && steps[next].t > ref->time()) ref->advance_to(steps[next].t);
      if (ref) x = ref->state();
      apply_steps_until(steps[next].t);
      restart(ref ? ref->time() : ts);
    }
    if (ref && ts > ref->time()) ref->advance_to(ts);
    if (ref) x = ref->state();
    Model::Output y = full.outputs(to_state(x.data()));
    if (stepped_here && settled && static_cast<int>(settled_from_full.size()) == settled->n_states()) {
      settled->set_params(p);
      settled->set_inputs(u);
      Model::State xs = Model::State::Zero();
      for (std::size_t j = 0; j < settled_from_full.size(); ++j) {
        xs[static_cast<int>(j)] = x[static_cast<std::size_t>(settled_from_full[j])];
      }
      y = settled->outputs(xs);
    }
    for (std::size_t ch = 0; ch < channels; ++ch) truth[ch] = y[static_cast<int>(ch)];
    if (k == 0) {
      chain.reset(truth.data());
    } else {
      chain.advance(truth.data(), ts - t_last);
    }
    chain.measure(meas.data());
    t_last = ts;
    log.t.push_back(ts);
    for (std::size_t i = 0; i < log.inputs.size(); ++i) log.inputs[i].push_back(u.v[i]);
    for (std::size_t ch = 0; ch < channels; ++ch) log.sensors[ch].push_back(meas[ch]);
  }
  return log;
}

}  // namespace hstmon::circuit_tools
