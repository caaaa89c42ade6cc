#pragma once
// A circuit simulation's options in a test: run length, sample rate and noise seed, the rest
// as CircuitSimOptions has them.
#include <cstdint>

#include "hstmon_circuit/circuit_sim.hpp"

namespace hstmon_test {

/// `duration` [s] sampled at `rate` [Hz], the default seed.
inline hstmon::circuit_tools::CircuitSimOptions sim_options(double duration, double rate) {
  hstmon::circuit_tools::CircuitSimOptions o;
  o.duration = duration;
  o.rate = rate;
  return o;
}

/// `duration` [s] sampled at `rate` [Hz], noise seed `seed`.
inline hstmon::circuit_tools::CircuitSimOptions sim_options(double duration, double rate, std::uint64_t seed) {
  hstmon::circuit_tools::CircuitSimOptions o = sim_options(duration, rate);
  o.seed = seed;
  return o;
}

}  // namespace hstmon_test
