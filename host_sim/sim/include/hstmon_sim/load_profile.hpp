#pragma once
/// @file load_profile.hpp
/// The load of the thesis rig over time: the PRV setting kp as the controller commands it.
/// Steps are instantaneous; ramps and sinusoids are sent as setpoints every `update`
/// seconds (a controller's output), so the schedule stays piecewise constant and the
/// logged kp equals the true one at every sample.

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace hstmon::sim {

/// Shape of the load.
enum class LoadShape {
  kConstant,  ///< kp = level·kp0 throughout
  kSteps,     ///< every `period` a new level drawn uniformly in [lo, hi]·kp0
  kRamp,      ///< triangle between lo and hi, each leg `period` long, from `level`
  kSine,      ///< (lo + hi)/2 + (hi − lo)/2·sin(2π t/period), times kp0
};

/// Name ("constant", "steps", "ramp", "sine") → shape; nullopt if unknown.
std::optional<LoadShape> load_shape_from(std::string_view name);
/// Shape → name.
const char* to_string(LoadShape s) noexcept;

/// A load profile; kp factors are multiples of the nominal kp0.
struct LoadProfile {
  LoadShape shape = LoadShape::kConstant;
  double level = 1.0;     ///< constant level; first level of steps and ramp [-]
  double lo = 0.65;       ///< lowest factor of steps, ramp and sine [-]
  double hi = 1.6;        ///< highest factor [-]
  double period = 2.0;    ///< steps: hold time; ramp: one leg; sine: period [s]
  double first = -1.0;    ///< time of the first change [s]; < 0: `period` (steps) or 0
  double update = 0.1;    ///< setpoint interval of ramp and sine [s]
  std::uint64_t seed = 1; ///< levels of the steps
};

/// kp setpoints (t [s], kp [m³/(s·√Pa)]) over [0, duration): the first at t = 0, times
/// strictly increasing, consecutive values different.
/// @throws std::invalid_argument on a non-positive period/update/kp0 or lo > hi
std::vector<std::pair<double, double>> load_setpoints(const LoadProfile& p, double kp0, double duration);

}  // namespace hstmon::sim
