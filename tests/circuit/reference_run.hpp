#pragma once
// The observer on the engine against a stiff reference of the same circuit: the engine
// with no node taken quasi-steady (the full equations) integrated by host_sim's
// Rosenbrock-4 (Boost.Odeint rosenbrock4), inputs piecewise constant and met exactly at
// their steps. Used by the accuracy tests.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <string>
#include <vector>

#include "circuit_fixture.hpp"
#include "hstmon/observer.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace circuit_test {

/// An input step: at time t [s] input `name` becomes `value` [SI].
struct InputStep {
  double t;
  std::string name;
  double value;
};

/// What a run measured.
struct RunResult {
  double worst = 0;          ///< largest |ŷ − y_ref| / scale over channels and ticks from t_skip on
  int worst_channel = -1;
  double worst_t = 0;        ///< when [s]
  int max_substeps = 0;
  std::uint32_t health = 0;  ///< observer health, OR-ed
  int states = 0, stiff = 0;
};

/// Runs the observer at `tick` from rest and the reference over [0, t_end], with the
/// steps applied at tick boundaries; errors from t_skip on, scaled per channel by the
/// largest |y_ref| of the run.
inline RunResult run_against_reference(const Loaded& l_in, double tick, double t_end, const std::vector<InputStep>& steps,
                                       double t_skip = 0.01) {
  RunResult res;
  Loaded l = l_in;
  l.file.circuit.stiff_mask =
      hstmon::circuit::auto_stiff_mask<double>(l.file.circuit, l.values.params, l.values.inputs, tick);
  hstmon::host::HostCircuit full_desc = l.file.circuit;
  full_desc.stiff_mask = 0;
  Model full(full_desc, l.values.params, l.values.inputs);
  Model reduced(l.file.circuit, l.values.params, l.values.inputs);
  res.states = reduced.n_states();
  res.stiff = reduced.n_stiff();

  using Obs = hstmon::Observer<Model, false>;
  Obs obs;
  Obs::Config cfg;
  cfg.tick = tick;
  EXPECT_EQ(obs.configure(reduced, cfg), hstmon::Status::kOk);
  Model::Inputs u = l.values.inputs;
  EXPECT_EQ(obs.reset_rest(u), hstmon::Status::kOk);

  const int n = full.n_states();
  std::vector<double> abs_tol(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) {
    abs_tol[static_cast<std::size_t>(s)] = full.state_z(s) < Model::kNodes ? 1e-7 * full.pressure_envelope() : 1e-7 * full.speed_envelope();
  }
  hstmon::sim::StiffIntegrator ref(abs_tol, 1e-9, 1e-7);
  Model::State x0 = full.rest_state();
  auto restart = [&](double t, const double* x) {
    full.set_inputs(u);
    ref.restart(
        t, x,
        [&full, n](const double* xs, double* dx) {
          Model::State s = Model::State::Zero();
          for (int i = 0; i < n; ++i) s[i] = xs[i];
          const Model::State d = full.derivative(s);
          for (int i = 0; i < n; ++i) dx[i] = d[i];
        },
        [&full, n](const double* xs, double* jac) {
          Model::State s = Model::State::Zero();
          for (int i = 0; i < n; ++i) s[i] = xs[i];
          Model::StateMatrix J;
          full.jacobian(s, J);
          for (int r = 0; r < n; ++r) {
            for (int c = 0; c < n; ++c) jac[r * n + c] = J(r, c);
          }
        });
  };
  restart(0.0, x0.data());

  const int ticks = static_cast<int>(std::lround(t_end / tick));
  std::vector<std::vector<double>> y_ref(static_cast<std::size_t>(ticks)), y_obs(static_cast<std::size_t>(ticks));
  const int channels = reduced.n_outputs();
  std::size_t next_step = 0;
  Obs::Measurement none;
  for (int k = 0; k < ticks; ++k) {
    const double t = k * tick;
    bool changed = false;
    while (next_step < steps.size() && steps[next_step].t <= t + 0.5 * tick) {
      u.v[l.file.input_index(steps[next_step].name)] = steps[next_step].value;
      ++next_step;
      changed = true;
    }
    if (changed) restart(t, ref.state().data());
    Model::State xr = Model::State::Zero();
    for (int i = 0; i < n; ++i) xr[i] = ref.state()[static_cast<std::size_t>(i)];
    const Model::Output yr = full.outputs(xr);
    res.health |= obs.step(u, none);
    res.max_substeps = std::max<int>(res.max_substeps, obs.substeps());
    for (int c = 0; c < channels; ++c) {
      y_ref[static_cast<std::size_t>(k)].push_back(yr[c]);
      y_obs[static_cast<std::size_t>(k)].push_back(obs.estimate()[c]);
    }
    if (std::getenv("CIRCUIT_TRACE") != nullptr && k < 40) {
      std::printf("t %.3f", t);
      for (int c = 0; c < channels; ++c) std::printf("  %.6g/%.6g", obs.estimate()[c], yr[c]);
      std::printf("  sub %d\n", obs.substeps());
    }
    ref.advance_to((k + 1) * tick);
  }
  std::vector<double> scale(static_cast<std::size_t>(channels), 0.0);
  for (const auto& row : y_ref) {
    for (int c = 0; c < channels; ++c) scale[static_cast<std::size_t>(c)] = std::max(scale[static_cast<std::size_t>(c)], std::fabs(row[static_cast<std::size_t>(c)]));
  }
  for (int k = 0; k < ticks; ++k) {
    if (k * tick < t_skip - 1e-12) continue;
    for (int c = 0; c < channels; ++c) {
      const std::size_t kc = static_cast<std::size_t>(c), kk = static_cast<std::size_t>(k);
      const double e = std::fabs(y_obs[kk][kc] - y_ref[kk][kc]) / scale[kc];
      if (e > res.worst) {
        res.worst = e;
        res.worst_channel = c;
        res.worst_t = k * tick;
      }
    }
  }
  return res;
}

}  // namespace circuit_test
