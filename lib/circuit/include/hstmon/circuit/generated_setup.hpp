#pragma once
/// @file generated_setup.hpp
/// A circuit's monitor set up from the values of a generated circuit header
/// (hstmon-circuit-header: description, parameter values, sensor noise and ranges,
/// parameter uncertainty, tick) the way `hstmon replay --circuit` sets it up from the
/// circuit file: one function for the configuration and one for the start, shared by the
/// firmware replay (ports/cortex_m4_mps2 fw_circuit_monitor.cpp) and the circuit C API
/// (ports/c_api hstmon_circuit_c.cpp), so that they configure the same monitor.
/// Templates on the monitor (CircuitMonitor<T, Cap, …>); no heap, no exceptions.

#include <cstddef>

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/monitor_setup.hpp"
#include "hstmon/initial_state.hpp"
#include "hstmon/status.hpp"

namespace hstmon::circuit {

/// The capacity of a circuit description type (Circuit<Cap> → Cap).
template <class Description>
struct CapacityOf;
template <class Cap>
struct CapacityOf<Circuit<Cap>> {
  using type = Cap;
};
/// The capacity of a monitor's circuit model.
template <class Mon>
using MonitorCapacity = typename CapacityOf<typename Mon::Model::Description>::type;

/// Pointers into a generated circuit header (namespace hstmon::generated::<name>): all
/// arrays live in flash there. Units are SI.
template <class Cap>
struct GeneratedValues {
  const Circuit<Cap>* circuit;  ///< kCircuit
  const double* params;         ///< kParams: Cap::kParams values [SI]
  const double* noise;          ///< kNoiseSigma: stated noise σ per channel [channel SI unit], ≤ 0 = not stated
  const double* range_lo;       ///< kRangeLo: transmitter range per channel [channel SI unit]
  const double* range_hi;       ///< kRangeHi
  const double* uncertainty;    ///< kUncertainty: relative uncertainty per parameter [-]
  double tick;                  ///< kTick: the tick the stiff mask was chosen for [s]
};

/// Binds `model` to the generated circuit and its parameter values, then configures `mon`
/// as the host replay does: sensor σ (circuit::sensor_sigma) and ranges, parameter
/// uncertainty, the circuit allowances (circuit::set_circuit_allowances: among them the
/// matcher's windows, which follow the operating point). `model` is left with inputs u0; it is the setup's
/// scratch and the monitor copies it (firmware passes a static one, so no model lands on
/// the stack).
/// @param mon    the monitor to configure
/// @param model  scratch model (bound here)
/// @param g      the generated values
/// @param u0     inputs of the first sample [SI]
/// @param table, count  the generated fault table (rows of Mon::Signature)
/// @return kOk; kInvalidParams when the description or the values make no physical
///         circuit; otherwise the monitor's configure() status
template <class Mon>
Status configure_from_generated(Mon& mon, typename Mon::Model& model, const GeneratedValues<MonitorCapacity<Mon>>& g,
                                const typename Mon::Inputs& u0, const typename Mon::Signature* table,
                                int count) noexcept {
  using Model = typename Mon::Model;
  using T = typename Model::Scalar;
  constexpr int kCh = Mon::kChannels;
  if (model.bind(*g.circuit) != CircuitError::kOk) return Status::kInvalidParams;
  typename Model::Params p;
  for (int i = 0; i < MonitorCapacity<Mon>::kParams; ++i) p.v[i] = static_cast<T>(g.params[i]);
  model.set_params(p);
  model.set_inputs(u0);
  if (!model.valid()) return Status::kInvalidParams;
  typename Mon::Config cfg;
  cfg.observer.tick = static_cast<T>(g.tick);
  for (int i = 0; i < kCh; ++i) {
    const double sigma = sensor_sigma(g.noise[i], g.range_lo[i], g.range_hi[i]);
    cfg.evaluator.noise_sigma[i] = static_cast<T>(sigma);
    cfg.sensors.noise[i] = static_cast<T>(sigma);
    cfg.sensors.range_lo[i] = static_cast<T>(g.range_lo[i]);
    cfg.sensors.range_hi[i] = static_cast<T>(g.range_hi[i]);
  }
  for (int k = 0; k < MonitorCapacity<Mon>::kParams; ++k) cfg.uncertainty.rel[k] = static_cast<T>(g.uncertainty[k]);
  set_circuit_allowances(cfg);
  return mon.configure(model, cfg, table, count);
}

/// Starts `mon` as `hstmon replay --circuit --init auto` does: from the first sample's
/// measured states; at the steady state for u0 instead when every channel reads within
/// 3σ of it (circuit::at_steady_within_noise); at rest when neither is accepted.
/// @param model  the scratch model of configure_from_generated (left with inputs u0)
/// @param g      the generated values (their stated noise decides "within 3σ")
/// @param u0, m  inputs and measurement of the first sample [SI]
/// @param how    out: how the state was chosen
/// @return kOk, or the status of reset_rest when even that refused u0
template <class Mon>
Status start_from_first_sample(Mon& mon, typename Mon::Model& model,
                               const GeneratedValues<MonitorCapacity<Mon>>& g, const typename Mon::Inputs& u0,
                               const typename Mon::Measurement& m, InitialState& how) noexcept {
  using T = typename Mon::Model::Scalar;
  constexpr int kCh = Mon::kChannels;
  T noise[static_cast<std::size_t>(kCh)];
  for (int i = 0; i < kCh; ++i) noise[i] = static_cast<T>(g.noise[i]);
  how = InitialState::kRest;
  Status s = mon.reset_measured(u0, m, &how);
  if (s == Status::kOk && at_steady_within_noise(model, u0, m.y, m.valid, noise, g.circuit->n_channels)) {
    s = mon.reset_steady(u0);
    how = InitialState::kSteady;
  }
  if (s != Status::kOk) {
    how = InitialState::kRest;
    s = mon.reset_rest(u0);
  }
  return s;
}

}  // namespace hstmon::circuit
