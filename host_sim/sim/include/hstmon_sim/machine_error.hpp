#pragma once
/// @file machine_error.hpp
/// The simulated machine is not the monitor's model: its parameters differ from Table 2.2
/// by a few per cent (manufacturing spread, wear, temperature). The monitor keeps Table 2.2.

#include <cstdint>

#include "hstmon/thesis_params.hpp"

namespace hstmon::sim {

/// Table 2.2 (or `base`) with each of Dm, Dp, Rlkg, Ripl, Rf, Rbl, kf, J, K multiplied by a
/// uniform random factor in [1 − spread, 1 + spread] (std::mt19937_64 seeded with seed,
/// drawn in that order). spread = 0 returns base.
ThesisParams<double> perturbed_params(std::uint64_t seed, double spread,
                                      const ThesisParams<double>& base = ThesisParams<double>{});

}  // namespace hstmon::sim
