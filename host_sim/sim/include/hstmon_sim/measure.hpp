#pragma once
/// @file measure.hpp
/// Synthetic measurements of a scenario: the reference solution passed through a sensor
/// chain and sampled at the logger's period.
///
/// The lags are fed the reference's dense output on a fine grid of step
/// h = sample_period / m, m = ceil(sample_period / lag_step) (m = 1 when no channel has a
/// lag), so every sample instant k·sample_period is a grid point. The sensor lags start
/// settled at the initial state.

#include <array>
#include <cstdint>
#include <vector>

#include "hstmon_sim/paper_scenarios.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim {

/// One logged sample.
template <class Inputs>
struct Measurement {
  double t = 0.0;              ///< sample time [s]
  Inputs u{};                  ///< inputs in force at t
  std::array<double, 4> y{};   ///< measured channels in SI (Pa, rad/s), in the config's order
};

/// Measurements of the thesis rig: y = (p_mi, p_mo, p_pp [Pa], w_m [rad/s]).
using ThesisMeasurements = std::vector<Measurement<ThesisInputs<double>>>;
/// Measurements of the paper rig: y = (p_pump, p_mi, p_pp [Pa], w_m [rad/s]).
using PaperMeasurements = std::vector<Measurement<PaperInputs<double>>>;

/// Simulates scenario sc and samples it through the sensors of cfg at t = k·sample_period,
/// 0 ≤ t ≤ sc.duration.
/// @param cfg   sensor set-up with exactly 4 channels (thesis order p_mi, p_mo, p_pp, w_m)
/// @param seed  noise seed
/// @throws std::invalid_argument on an invalid scenario or set-up
ThesisMeasurements measure(const ThesisScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                           const ThesisParams<double>& p = ThesisParams<double>{},
                           const ReferenceTolerances& tol = ReferenceTolerances{});

/// As above for the paper rig (channel order p_pump, p_mi, p_pp, w_m).
PaperMeasurements measure(const PaperScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                          const PaperParams<double>& p = PaperParams<double>{},
                          const ReferenceTolerances& tol = ReferenceTolerances{});

}  // namespace hstmon::sim
