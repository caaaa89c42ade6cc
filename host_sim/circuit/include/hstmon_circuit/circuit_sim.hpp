#pragma once
/// @file circuit_sim.hpp
/// Synthetic logs of any circuit (hstmon-sim --circuit): the engine's full equations
/// (no node taken quasi-steady) integrated by host_sim's Rosenbrock-4 (StiffIntegrator,
/// the reference of tests/circuit), inputs piecewise constant and met exactly at their
/// steps, every sample a hard stop; the outputs go through the sensor chain (white noise
/// and range clipping from the circuit's sensors section; a transducer lag and an ADC
/// when asked: TransducerOptions). A sample that
/// falls on a step reads the volumes far faster than the sampling (those an observer at
/// this period takes quasi-steady) settled: no transducer follows their microseconds.
/// Logged inputs (input_profile.hpp) drive the run from a logged run's rows: each row a
/// hard stop; a linear profile's inputs ramp within the integrator between them (the time
/// since the row is one more state of the integration, so a ramp is met exactly, not as a
/// staircase).

#include <cstdint>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_circuit/input_profile.hpp"
#include "hstmon_sensors/sensor_chain.hpp"

namespace hstmon::circuit_tools {

/// What every channel's transducer adds to the sensors section's noise and range (off by
/// default: the ideal transducer).
struct TransducerOptions {
  double lag = 0.0;            ///< first-order time constant of every channel [s]; 0 = none
  int pressure_adc_bits = 0;   ///< ADC bits over each pressure channel's declared range, 1..52; 0 = none (so is
                               ///< a channel without a finite range)
  double pressure_step = 0.0;  ///< quantisation step of the pressure channels [Pa]; 0 = none (the ADC wins)
};

/// What to simulate.
struct CircuitSimOptions {
  double duration = 10.0;          ///< run length [s] > 0
  double rate = 100.0;             ///< sample rate [Hz] > 0
  std::uint64_t seed = 1;          ///< noise seed
  bool from_rest = false;          ///< start at rest; false: at the steady state of the t = 0 inputs
  bool noise = true;               ///< false: sensor noise off (clipping kept)
  std::vector<InputStep> steps;    ///< input steps on top of the nominal inputs (and of the profile: a stepped
                                   ///< input leaves the profile from its step on), times on the run's clock
  double start_time = 0.0;         ///< the run's clock at its start [s]
  std::vector<double> sample_times;  ///< the rows written [s], rising, >= start_time; empty: start_time + k/rate,
                                     ///< k < duration·rate (rate then also sets which volumes read settled)
  InputProfile profile;            ///< logged inputs driving the run (none: no input follows it)
  TransducerOptions transducers;   ///< lag and ADC of every channel (none by default)
  /// A logger set-up instead of the sensors section and transducers: one channel per
  /// sensor, in the circuit's order (noise still off without `noise`); empty: none.
  std::vector<sim::ChannelSpec> channels;
};

/// Simulates c and returns the log: every input column and every sensor column, SI.
/// @throws std::runtime_error for more than 1e7 samples, sample times not rising from start_time (or a profile's
///         first row after it), pressure_adc_bits outside 1..52, a negative lag or step, when the circuit's values are not
///         physical, there is no
///         steady state to start from, channels that are not one per sensor, or the integration fails
CircuitLog simulate_circuit(const LoadedCircuit& c, const CircuitSimOptions& o);

}  // namespace hstmon::circuit_tools
