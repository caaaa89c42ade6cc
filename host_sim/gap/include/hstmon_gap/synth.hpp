#pragma once
/// @file synth.hpp
/// Synthetic "machine" logs for blind tests and the benchmark: the extended model with
/// chosen effects switched on (the truth), driven by a kp / p_sup staircase, plus Gaussian
/// sensor noise. Two profiles with different staircases and hold times ('A' to fit, 'B'
/// to check).
#include <cstdint>

#include "hstmon_gap/effects.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hstmon::gap {

/// Input staircase: profile 'A' or 'B', `duration` [s] sampled at `rate` [Hz].
InputSeries staircase_profile(char profile, double duration, double rate,
                              const ThesisInputs<double>& base = ThesisInputs<double>{});

/// Noise of the synthetic sensors (standard deviations, SI).
struct SynthNoise {
  double pressure = 5e3;  ///< [Pa] (0.05 bar)
  double speed = 0.3;     ///< [rad/s]
};

/// Simulates `truth` through `u` (fine internal step) and adds noise: a log with t, p_sup,
/// kp, p_bp, p_mi, p_mo, p_pp, w_m (SI). `ok()` false with error message on failure.
host::LogData synth_log(const ExtendedModel& truth, const InputSeries& u, const SynthNoise& noise, std::uint64_t seed,
                        const std::string& name = "synthetic");

}  // namespace hstmon::gap
