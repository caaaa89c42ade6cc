#pragma once
/// @file monitor_setup.hpp
/// The settings a circuit's monitor derives from the circuit and the first log row, in
/// one place for the host replay (`hstmon replay --circuit`) and the firmware's
/// (ports/cortex_m4_mps2/portable/fw_circuit_monitor.cpp), so the two configure the same
/// monitor: the noise σ of a channel, the allowances for what a circuit file does not say,
/// and the choice to start at the steady state. Templates on the
/// model (CircuitModel<T, Cap>); no heap, no exceptions.

#include <cmath>

namespace hstmon::circuit {

/// The noise σ the monitor assumes for a sensor [channel SI unit]: its stated noise, else
/// 1 % of its range (of 100 when the range is unbounded).
/// @param noise  stated noise standard deviation [SI], ≤ 0 or NaN = not stated
/// @param lo, hi transmitter range [SI], ±inf when not stated
template <typename T>
T sensor_sigma(T noise, T lo, T hi) noexcept {
  const T span = std::isfinite(hi - lo) ? hi - lo : T(100);
  return noise > T(0) ? noise : T(0.01) * span;
}

/// What a circuit file does not say, allowed for in the monitor's configuration:
///  - its damping: the model's whole transient after an input step counts as model error
///    (ModelMonitor::Config::model_transient = 1), decaying with the circuit's slowest time
///    constant — milliseconds for a PRV-loaded rig, a second for a lightly damped closed
///    circuit ringing at a few hertz;
///  - its valves' opening in the ±ε machine: after an input step the old operating
///    point's bound is carried on top of the new one, decaying with the slower of the
///    two points' time constants (ModelMonitor::Config::bound_carry = 1), since a machine
///    whose relief valve stays shut where the model's cracks leaves the old model error at
///    its own, slower pace;
///  - the timing of its valves' opening in the ±ε machine: after an input step the machine
///    may run its transient up to ε·τ ahead of the model (ModelMonitor::Config::timing_lead
///    = 1), so a valve on the way (a check valve as a main line falls below the charge
///    pressure) opens that much earlier in the machine, and the model's own change over
///    that time ahead counts as model error;
///  - how far a fault moves the model error with the operating point: a channel that moved
///    no further than the model bound reads as unchanged in a signature
///    (FaultMatcher::Config::k_zero_bound = 1);
///  - how long its transients last where the machine runs: the fault table's magnitudes are
///    steady-state ones, so after a detection the matcher settles for 3 and averages over 1
///    of the slowest time constants at the operating point of the last input change
///    (ModelMonitor::Config::settle_taus = 3; the configured windows, 50 ms and 100 ms by
///    default, where the circuit is faster).
/// The thesis rig's monitor (Monitor<T>) keeps all five off: its transients are milliseconds
/// long and its table and thresholds are validated as they are.
/// @param cfg  a ModelMonitor configuration, changed in place
template <class MonitorConfig>
void set_circuit_allowances(MonitorConfig& cfg) noexcept {
  cfg.model_transient = 1;
  cfg.bound_carry = 1;
  cfg.timing_lead = 1;
  cfg.matcher.k_zero_bound = 1;
  cfg.settle_taus = 3;
}

/// True when each of the first `channels` channels is measured (bit in valid) with a
/// stated noise σ > 0 and reads within 3σ of the model's output at the steady state for
/// inputs u: then a replay starts at that steady state, since the readings' noise would
/// otherwise be the initial error of a parallel model (a lightly damped circuit rings
/// with it for seconds).
/// @param model  the circuit's model; left with inputs u (a scratch copy on the host;
///               firmware passes a static one, so no model is copied onto its stack)
/// @param noise  stated noise σ per channel [channel SI unit]
/// @param y      readings per channel [channel SI unit]
/// @param valid  bit ch set: channel ch was read
template <class Model>
bool at_steady_within_noise(Model& model, const typename Model::Inputs& u, const typename Model::Output& y,
                            unsigned valid, const typename Model::Scalar* noise, int channels) noexcept {
  using T = typename Model::Scalar;
  if (channels <= 0) return false;
  model.set_inputs(u);
  typename Model::State xs;
  if (!model.steady_state(xs)) return false;
  const typename Model::Output ys = model.outputs(xs);
  for (int ch = 0; ch < channels; ++ch) {
    const T sigma = noise[ch];
    if ((valid & (1u << ch)) == 0 || !(sigma > T(0))) return false;
    if (!(std::fabs(y[ch] - ys[ch]) <= T(3) * sigma)) return false;
  }
  return true;
}

}  // namespace hstmon::circuit
