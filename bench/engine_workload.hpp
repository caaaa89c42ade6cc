#pragma once
/// @file engine_workload.hpp
/// The circuit engine's share of the tick benchmarks: examples/circuits/thesis.json read
/// on the host, copied into a description sized to it (ThesisCap: the capacity a firmware
/// build of this circuit would use, so state vectors are 2 long, not the host's 16), the
/// observer on it at the nominal operating point, and the Boost.Odeint observer on the same
/// engine model — the like-for-like baseline of issue 14 ("the engine tick at ≤ 0.8× Boost.
/// Odeint's rk4 on the same model").

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "hstmon/circuit/engine.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"
#include "hstmon/observer.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "perturbed_measurements.hpp"

namespace hstmon_bench {

/// Compiler barrier (as bench_common.hpp's escape; this header stands alone).
inline void escape_engine(const void* p) noexcept { asm volatile("" : : "g"(p) : "memory"); }

/// thesis.json's counts: 7 nodes, 1 shaft, 10 elements, 4 channels, 4 inputs, 16
/// parameters (named and literal), 2 states once the DCV nodes are quasi-steady.
using ThesisCap = hstmon::circuit::Capacity<7, 1, 10, 4, 4, 16, 2>;
template <typename T>
using Engine = hstmon::circuit::CircuitModel<T, ThesisCap>;
template <typename T>
using EngineObs = hstmon::Observer<Engine<T>, false>;

/// thesis.json with its values, in ThesisCap, stiff mask for a 1 ms tick.
struct ThesisCircuit {
  hstmon::circuit::Circuit<ThesisCap> desc{};
  std::array<double, 16> params{};
  std::array<double, 4> inputs{};

  explicit ThesisCircuit(const std::string& source_dir) {
    hstmon::circuit_tools::LoadedCircuit c;
    if (auto err = hstmon::circuit_tools::load_circuit(source_dir + "/examples/circuits/thesis.json", "", c)) {
      throw std::runtime_error(err->to_string());
    }
    const auto& h = c.file.circuit;
    if (h.n_nodes > 7 || h.n_shafts > 1 || h.n_elements > 10 || h.n_channels > 4 || h.n_inputs > 4 ||
        h.n_params > 16) {
      throw std::runtime_error("thesis.json outgrew ThesisCap");
    }
    desc.n_nodes = h.n_nodes;
    desc.n_shafts = h.n_shafts;
    desc.n_elements = h.n_elements;
    desc.n_channels = h.n_channels;
    desc.n_inputs = h.n_inputs;
    desc.n_params = h.n_params;
    desc.pressure_max = h.pressure_max;
    desc.speed_max = h.speed_max;
    for (int i = 0; i < h.n_nodes; ++i) desc.nodes[i] = h.nodes[i];
    for (int i = 0; i < h.n_shafts; ++i) desc.shafts[i] = h.shafts[i];
    for (int i = 0; i < h.n_elements; ++i) desc.elements[i] = h.elements[i];
    for (int i = 0; i < h.n_channels; ++i) desc.channels[i] = h.channels[i];
    for (int i = 0; i < h.n_params; ++i) params[static_cast<std::size_t>(i)] = c.values.params.v[i];
    for (int i = 0; i < h.n_inputs; ++i) inputs[static_cast<std::size_t>(i)] = c.values.inputs.v[i];
    typename Engine<double>::Params p;
    typename Engine<double>::Inputs u;
    for (std::size_t i = 0; i < params.size(); ++i) p.v[i] = params[i];
    for (std::size_t i = 0; i < inputs.size(); ++i) u.v[i] = inputs[i];
    desc.stiff_mask = hstmon::circuit::auto_stiff_mask<double>(desc, p, u, 1e-3);
  }

  template <typename T>
  typename Engine<T>::Params params_as() const noexcept {
    typename Engine<T>::Params p;
    for (std::size_t i = 0; i < params.size(); ++i) p.v[i] = static_cast<T>(params[i]);
    return p;
  }
  template <typename T>
  typename Engine<T>::Inputs inputs_as() const noexcept {
    typename Engine<T>::Inputs u;
    for (std::size_t i = 0; i < inputs.size(); ++i) u.v[i] = static_cast<T>(inputs[i]);
    return u;
  }
};

/// The engine observer at the nominal point, started steady.
template <typename T>
EngineObs<T> make_engine_observer(const ThesisCircuit& c, T tick) {
  EngineObs<T> o;
  typename EngineObs<T>::Config cfg;
  cfg.tick = tick;
  const Engine<T> model(c.desc, c.params_as<T>(), c.inputs_as<T>());
  if (o.configure(model, cfg) != hstmon::Status::kOk || o.reset_steady(c.inputs_as<T>()) != hstmon::Status::kOk) {
    throw std::runtime_error("engine observer: no steady start");
  }
  return o;
}

/// The compiled thesis model (lib/circuit/include/hstmon/generated/thesis_circuit_compiled.hpp,
/// what the firmware runs) and its observers at the nominal point, started steady: the
/// host's (the fused usual tick in front of the general one) and the general tick alone
/// (what firmware runs, and the usual tick's fallback).
template <typename T>
using Compiled = hstmon::generated::thesis_circuit::CompiledModel<T>;
template <typename T>
using CompiledObs = hstmon::Observer<Compiled<T>>;
template <typename T>
using CompiledGeneralObs = hstmon::Observer<Compiled<T>, false>;
static_assert(CompiledObs<double>::kUsualTick, "host builds: the compiled model's usual tick");

/// The generated header's values (its kParams or kInputs) as the compiled model's Vec of T.
template <typename T, typename Vec, std::size_t N>
Vec compiled_values(const double (&values)[N]) noexcept {
  Vec v;
  for (std::size_t i = 0; i < N; ++i) v.v[i] = static_cast<T>(values[i]);
  return v;
}
template <typename T>
typename Compiled<T>::Params compiled_params() noexcept {
  return compiled_values<T, typename Compiled<T>::Params>(hstmon::generated::thesis_circuit::kParams);
}
template <typename T>
typename Compiled<T>::Inputs compiled_inputs() noexcept {
  return compiled_values<T, typename Compiled<T>::Inputs>(hstmon::generated::thesis_circuit::kInputs);
}

template <typename T, class Obs = CompiledObs<T>>
Obs make_compiled_observer(T tick) {
  Obs o;
  typename Obs::Config cfg;
  cfg.tick = tick;
  if (o.configure(hstmon::generated::thesis_circuit::kCircuit, compiled_params<T>(), cfg) != hstmon::Status::kOk ||
      o.reset_steady(compiled_inputs<T>()) != hstmon::Status::kOk) {
    throw std::runtime_error("compiled observer: no steady start");
  }
  return o;
}

/// Measurements fed to every variant (perturbed_measurements.hpp).
template <typename T>
using EngineMeasurements = PerturbedMeasurements<EngineObs<T>>;

/// Boost.Odeint's runge_kutta4 as the observer, one step per tick, on the same engine
/// model (outputs, residuals, one RK4 step of derivative(); no health checks).
template <typename T, class M = Engine<T>>
class OdeintEngine {
 public:
  using state_type = std::array<T, 2>;
  using Model = M;

  /// On the interpreting engine, from its observer's steady start.
  OdeintEngine(const ThesisCircuit& c, T tick) : dt_(tick) {
    const EngineObs<T> o = make_engine_observer<T>(c, tick);
    model_ = o.model();
    x_ = {o.state()[0], o.state()[1]};
  }
  /// On any two-state model (the compiled one), from state x0.
  OdeintEngine(const Model& model, const typename Model::State& x0, T tick) : model_(model), dt_(tick) {
    x_ = {x0[0], x0[1]};
  }

  void step(const typename Model::Inputs& u, const hstmon::ChannelSample<typename Model::Output>& m) noexcept {
    if (!(u == model_.inputs())) model_.set_inputs(u);
    typename Model::State xs;
    xs << x_[0], x_[1];
    r_ = m.y - model_.outputs(xs);
    const Model& model = model_;
    auto sys = [&model](const state_type& x, state_type& dxdt, T /*t*/) {
      typename Model::State s;
      s << x[0], x[1];
      const typename Model::State d = model.derivative(s);
      dxdt[0] = d[0];
      dxdt[1] = d[1];
    };
    stepper_.do_step(sys, x_, t_, dt_);
    t_ += dt_;
  }
  const typename Model::Output& residual() const noexcept { return r_; }
  const state_type& state() const noexcept { return x_; }

 private:
  Model model_{};
  boost::numeric::odeint::runge_kutta4<state_type, T, state_type, T> stepper_{};
  state_type x_{};
  typename Model::Output r_ = Model::Output::Zero();
  T t_ = T(0);
  T dt_;
};

}  // namespace hstmon_bench
