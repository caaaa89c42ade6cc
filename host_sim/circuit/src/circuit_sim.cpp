#include "hstmon_circuit/circuit_sim.hpp"

#include "hstmon/circuit/stiffness.hpp"

#include <algorithm>
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
  if (!std::isfinite(o.start_time)) throw std::runtime_error("the start time must be finite");
  std::vector<double> sample_times = o.sample_times;
  if (sample_times.empty()) {
    if (o.duration * o.rate > 1e7) throw std::runtime_error("more than 10 million samples: lower --duration or --rate");
    const auto samples = static_cast<std::size_t>(std::llround(o.duration * o.rate));
    sample_times.reserve(samples);
    for (std::size_t k = 0; k < samples; ++k) sample_times.push_back(o.start_time + static_cast<double>(k) / o.rate);
  } else {
    if (sample_times.size() > 10000000) throw std::runtime_error("more than 10 million samples: lower --duration");
    for (std::size_t k = 0; k < sample_times.size(); ++k) {
      if (!std::isfinite(sample_times[k]) || sample_times[k] < o.start_time ||
          (k > 0 && !(sample_times[k] > sample_times[k - 1]))) {
        throw std::runtime_error("sample times must rise from the start time");
      }
    }
  }
  const InputProfile& prof = o.profile;
  if (prof.any() && !(o.start_time >= prof.t.front())) {
    throw std::runtime_error("the run starts before the input profile's first row");
  }
  const bool ramps = prof.any() && prof.hold == InputHold::kLinear && prof.t.size() >= 2;
  std::vector<InputStep> steps = o.steps;
  sort_steps(steps);
  host::HostCircuit desc = c.file.circuit;
  desc.stiff_mask = 0;  // the full equations: every volume a state
  const std::size_t n_inputs = c.file.inputs.size();
  Model::Inputs held = c.values.inputs;  // nominal, then stepped; the profile's inputs on top
  std::vector<bool> follows(n_inputs, false);
  for (std::size_t i = 0; i < n_inputs; ++i) follows[i] = prof.drives(i);
  Model::Params p = c.values.params;
  bool params_changed = false;
  std::size_t next = 0;
  auto apply_steps_until = [&](double t) {
    while (next < steps.size() && steps[next].t <= t + 1e-12) {
      const InputStep& st = steps[next];
      if (st.param >= 0) {
        p.v[st.param] = c.values.params.v[st.param] * st.factor;
        params_changed = true;
      } else {
        held.v[st.input] = st.value;
        follows[static_cast<std::size_t>(st.input)] = false;
      }
      ++next;
    }
  };
  // The inputs at time t in profile segment k.
  auto inputs_at = [&](double t, std::size_t k) {
    Model::Inputs u = held;
    for (std::size_t i = 0; i < n_inputs; ++i) {
      if (follows[i]) u.v[i] = prof.value(i, t, k);
    }
    return u;
  };
  std::size_t seg = prof.any() ? prof.segment(o.start_time) : 0;
  apply_steps_until(o.start_time);
  params_changed = false;
  Model::Inputs u = inputs_at(o.start_time, seg);
  Model full(desc, p, u);
  if (full.error() != circuit::CircuitError::kOk || !full.valid()) {
    throw std::runtime_error("circuit " + c.file.name + ": the values do not make a physical circuit");
  }
  Model::State x0 = full.rest_state();
  if (!o.from_rest && !full.steady_state(x0)) {
    throw std::runtime_error("circuit " + c.file.name +
                             ": no steady state for the inputs at the start (try --start rest)");
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
  // With ramping inputs the integrated state has one more entry: the time since the
  // segment's anchor, tau (dtau/dt = 1), the inputs u_anchor + tau·slope.
  const int m = ramps ? n + 1 : n;
  std::vector<double> abs_tol(static_cast<std::size_t>(m));
  for (int s = 0; s < n; ++s) {
    abs_tol[static_cast<std::size_t>(s)] =
        full.state_z(s) < Model::kNodes ? 1e-7 * full.pressure_envelope() : 1e-7 * full.speed_envelope();
  }
  if (ramps) abs_tol[static_cast<std::size_t>(n)] = 1e-9;
  std::vector<double> x(x0.data(), x0.data() + n);
  if (ramps) x.push_back(0.0);
  std::optional<sim::StiffIntegrator> ref;
  if (n > 0) ref.emplace(abs_tol, 1e-9, 1e-7);
  auto to_state = [n](const double* xs) {
    Model::State s = Model::State::Zero();
    for (int i = 0; i < n; ++i) s[i] = xs[i];
    return s;
  };
  // The current segment's anchor inputs and slopes (ramps only).
  Model::Inputs anchor = u;
  std::vector<double> slope(n_inputs, 0.0);
  double seg_length = 1.0;
  bool sloped = false;
  auto slopes_in = [&](std::size_t k) {
    std::vector<double> s(n_inputs, 0.0);
    for (std::size_t i = 0; i < n_inputs; ++i) {
      if (follows[i]) s[i] = prof.slope(i, k);
    }
    return s;
  };
  auto ramped = [&anchor, &slope, n_inputs](double tau) {
    Model::Inputs v = anchor;
    for (std::size_t i = 0; i < n_inputs; ++i) v.v[i] += tau * slope[i];
    return v;
  };
  // kink: the inputs meet the last segment's without a jump (a linear profile's row), so
  // the integrator goes on at its last step rather than from the first trial step.
  auto restart = [&](double t, bool kink = false) {  // t: since the start [s]
    if (params_changed) full.set_params(p);
    params_changed = false;
    full.set_inputs(u);
    if (!ref) return;
    if (!ramps) {
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
      return;
    }
    anchor = u;
    slope = slopes_in(seg);
    sloped = std::any_of(slope.begin(), slope.end(), [](double v) { return v != 0.0; });
    seg_length = seg + 1 < prof.t.size() ? prof.t[seg + 1] - prof.t[seg] : 1.0;
    x[static_cast<std::size_t>(n)] = 0.0;
    auto rhs = [&](const double* xs, double* dx) {
      if (sloped) full.set_inputs(ramped(xs[n]));
      const Model::State d = full.derivative(to_state(xs));
      for (int i = 0; i < n; ++i) dx[i] = d[i];
      dx[n] = 1.0;
    };
    auto jacobian = [&](const double* xs, double* jac) {
      const Model::State xs_state = to_state(xs);
      if (sloped) full.set_inputs(ramped(xs[n]));
      Model::StateMatrix J;
      full.jacobian(xs_state, J);
      for (int r = 0; r < m; ++r) {
        for (int k = 0; k < m; ++k) jac[r * m + k] = r < n && k < n ? J(r, k) : 0.0;
      }
      if (!sloped) return;
      // d f / d tau = (d f / d u)·slope, by a forward difference along the ramp.
      const double h = 1e-6 * seg_length;
      const Model::State f0 = full.derivative(xs_state);
      full.set_inputs(ramped(xs[n] + h));
      const Model::State f1 = full.derivative(xs_state);
      for (int r = 0; r < n; ++r) jac[r * m + n] = (f1[r] - f0[r]) / h;
    };
    if (kink) {
      ref->restart(t, x.data(), rhs, jacobian, ref->next_step());
    } else {
      ref->restart(t, x.data(), rhs, jacobian);
    }
  };
  // The integrator's clock starts at 0: a log's clock may be far from it (a logger's Unix
  // time, 1.7e9 s, resolves only 2e-7 s), the time since the start never is.
  const double t0 = o.start_time;
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
  log.inputs.assign(n_inputs, {});
  log.sensors.assign(channels, {});
  log.t.reserve(sample_times.size());
  std::vector<double> truth(channels), meas(channels);
  double t_last = o.start_time;
  // The next row of the profile after the start: a hard stop.
  std::size_t next_row = prof.any() ? seg + 1 : prof.t.size();
  auto next_break = [&]() {
    double b = INFINITY;
    if (next < steps.size()) b = steps[next].t;
    if (next_row < prof.t.size()) b = std::min(b, prof.t[next_row]);
    return b;
  };
  for (std::size_t k = 0; k < sample_times.size(); ++k) {
    const double ts = sample_times[k];
    // Steps and rows up to this sample, each met exactly by a hard stop.
    bool stepped_here = false;
    for (double tb = next_break(); tb <= ts + 1e-12; tb = next_break()) {
      if (ref && tb - t0 > ref->time()) ref->advance_to(tb - t0);
      if (ref) x = ref->state();
      const double t_now = ref ? ref->time() : tb - t0;
      bool jump = false;
      if (next < steps.size() && steps[next].t <= tb + 1e-12) {
        apply_steps_until(tb);
        jump = true;
      }
      const std::vector<double> slope_before = ramps ? slopes_in(seg) : std::vector<double>{};
      const Model::Inputs before = inputs_at(tb, seg);
      while (next_row < prof.t.size() && prof.t[next_row] <= tb + 1e-12) seg = next_row++;
      u = inputs_at(tb, seg);
      // A row where no input's value (step profile) or slope (linear) changes needs no
      // restart; a linear profile's value is continuous at a row.
      bool changed = false;
      for (std::size_t i = 0; i < n_inputs && !ramps && !changed; ++i) changed = u.v[i] != before.v[i];
      jump = jump || changed;
      if (jump || (ramps && slopes_in(seg) != slope_before)) restart(t_now, !jump);
      stepped_here = stepped_here || (jump && std::fabs(tb - ts) <= 1e-12);
    }
    if (ref && ts - t0 > ref->time()) ref->advance_to(ts - t0);
    if (ref) x = ref->state();
    u = inputs_at(ts, seg);
    full.set_inputs(u);
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
    for (std::size_t i = 0; i < n_inputs; ++i) log.inputs[i].push_back(u.v[i]);
    for (std::size_t ch = 0; ch < channels; ++ch) log.sensors[ch].push_back(meas[ch]);
  }
  return log;
}

}  // namespace hstmon::circuit_tools
