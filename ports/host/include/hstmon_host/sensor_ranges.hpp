#pragma once
/// @file sensor_ranges.hpp
/// Transmitter ranges of the four measured channels, for the monitor's sensor checks
/// (hstmon::SensorCheck): a reading at or below a channel's low end is out of range — a
/// 4–20 mA loop break reads ≤ 4 mA — and so a sensor problem; a reading at its high end
/// (up to NAMUR NE 43's 20.5 mA, 1/32 of the span above it) is saturated, masked as
/// evidence but not a fault; beyond that it is out of range.

#include <array>
#include <limits>

namespace hstmon::host {

/// Range ends per channel in output order (Pmi, Pmo, Ppp [Pa], ωm [rad/s]).
struct SensorRanges {
  std::array<double, 4> lo{};  ///< low end (the transmitter's live zero) [Pa, rad/s]; −∞: none
  std::array<double, 4> hi{};  ///< high end, > lo [Pa, rad/s]; +∞: none
};

/// The thesis rig's transmitters (seed 000, Table 2.1), the default of `hstmon replay`:
///  - Pmi, Pmo: 0–200 bar (WIKA S-10, 4–20 mA, 0–200 bar, as listed);
///  - Ppp: 0–250 bar — assumed, as host_sim's sensor presets do: the table lists 0–200
///    bar, but the thesis's own 50 % PRV blockage reads 226.8 bar on Ppp, which a 200 bar
///    transmitter could not show (the part number S10-250 suggests a 250 bar variant);
///    the shipped logs are made with 250 bar;
///  - ωm: −3000…3000 rpm — assumed: the thesis gives no range for the speed sensor;
///    3000 rpm as host_sim, both signs because the DCV reverses the motor and a standing
///    motor (0 rpm) is a reading, not a broken loop.
inline SensorRanges thesis_sensor_ranges() noexcept {
  constexpr double kBar = 1e5;                                     // [Pa]
  constexpr double kRpm = 3.14159265358979323846 / 30.0;           // [rad/s]
  SensorRanges r;
  r.lo = {0.0, 0.0, 0.0, -3000.0 * kRpm};
  r.hi = {200.0 * kBar, 200.0 * kBar, 250.0 * kBar, 3000.0 * kRpm};
  return r;
}

/// What `hstmon replay` assumes of a log that declares no ranges (no "sensors" section in
/// the parameter file): the thesis rig's live zeros — a reading there is a loop break
/// only where the model says the channel cannot be at zero (Monitor) — and no high ends.
/// A log's transmitters are unknown, and a reading above an assumed high end is not
/// evidence of a fault: a fast transducer shows Ppp overshooting by 100–180 bar at a PRV
/// step, physically, far past the 250 bar assumed above.
inline SensorRanges log_default_sensor_ranges() noexcept {
  SensorRanges r = thesis_sensor_ranges();
  r.hi.fill(std::numeric_limits<double>::infinity());
  return r;
}

/// No range ends (±∞): only the non-finite and stuck checks apply.
inline SensorRanges unbounded_sensor_ranges() noexcept {
  SensorRanges r;
  r.lo.fill(-std::numeric_limits<double>::infinity());
  r.hi.fill(std::numeric_limits<double>::infinity());
  return r;
}

}  // namespace hstmon::host
