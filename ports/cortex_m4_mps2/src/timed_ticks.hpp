#pragma once
// How the circuit cost images (main_circuit_footprint.cpp, main_circuit_monitor_cost.cpp)
// time a step: the same alternating measurement noise, so their counts compare.
#include <cstdint>

#include "fw_circuit.hpp"
#include "hstmon_mps2/cycles.h"

namespace hstmon::fw {

/// SysTick counts for `ticks` calls of f(u, m), m being `base` with each of its first
/// `channels` channels alternating by 50 Pa (pressures, flows) or 0.05 rad/s (speeds), as
/// main_footprint.c; every result is written to `sink` (the calls stay observable).
template <class StepFn, class Inputs, class Meas>
std::uint32_t time_alternating(StepFn f, const Inputs& u, const Meas& base, int channels, int ticks,
                               volatile std::uint32_t& sink) noexcept {
  Meas m = base;
  const std::uint32_t a = cycles_now();
  for (int k = 0; k < ticks; ++k) {
    const float d = (k & 1) ? 1.0f : -1.0f;
    for (int c = 0; c < channels; ++c) {
      const bool speed = gen::kCircuit.channels[c].kind == circuit::ChannelKind::kSpeed;
      m.y[c] = base.y[c] + (speed ? 0.05f : 50.0f) * d;
    }
    sink = f(u, m);
  }
  return cycles_elapsed(a, cycles_now());
}

}  // namespace hstmon::fw
