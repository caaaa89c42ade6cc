#pragma once
/// @file param_fault.hpp
/// Fault injection for synthetic logs of the thesis rig (fault campaign, bench/fault_campaign.cpp).
///
/// Parameter faults: measure_with_fault() integrates the stiff reference with the machine's
/// parameters up to the fault time, then restarts the reference from that state with the
/// faulty parameters; the same sensor chain (lags, noise, ADC) is fed throughout, so the
/// log is continuous and the noise sequence is that of measure() with the same seed.
/// Input faults (supply, booster, PRV blockage) are scenario changes instead: a schedule
/// entry at the fault time with the faulty inputs and a `logged` schedule that keeps the
/// operator's settings (as thesis_prv_blockage() does); measure_with_fault() handles both.
///
/// Sensor faults act on the sampled values: bias (constant offset), drift (offset growing
/// linearly from the fault time) and stuck (the last value before the fault, held). Bias
/// and drift are added before the ADC (the value is clipped to the transmitter's range and
/// re-quantised), as in a transducer whose zero has moved. A loop break reads the NE 43
/// failure level (3.6 mA: range_lo − kNe43LoopBreak·span) from the fault on.

#include <cstdint>

#include "hstmon_sim/measure.hpp"

namespace hstmon::sim {

/// Simulates scenario sc with parameters p before fault_time [s] and faulty from then on,
/// sampled through the sensors of cfg as measure() does.
/// @param fault_time  time the parameters change [s]; ≥ sc.duration means no fault
/// @throws std::invalid_argument on an invalid scenario, set-up or parameters
ThesisMeasurements measure_with_fault(const ThesisScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                                      const ThesisParams<double>& p, double fault_time,
                                      const ThesisParams<double>& faulty,
                                      const ReferenceTolerances& tol = ReferenceTolerances{});

/// Kind of a sensor fault.
enum class SensorFaultKind {
  kBias,   ///< y + value from t_start on
  kDrift,  ///< y + value·(t − t_start) from t_start on
  kStuck,  ///< the last sample before t_start, held (value unused)
  kLoopBreak,  ///< the 4–20 mA loop's failure level (value unused)
};

/// One sensor fault on one channel of a thesis log.
struct SensorFault {
  int channel = 0;                          ///< 0 p_mi, 1 p_mo, 2 p_pp, 3 w_m
  SensorFaultKind kind = SensorFaultKind::kBias;
  double t_start = 0.0;                     ///< onset [s]
  double value = 0.0;                       ///< bias [SI] or drift rate [SI/s]
};

/// Scenario sc with an input fault: from t_fault on, the true `field` of every schedule
/// entry is multiplied by factor (an entry is added at t_fault); the logged inputs stay
/// sc's (a blockage or a supply fault is not a setting the logger sees).
ThesisScenario with_input_fault(const ThesisScenario& sc, double ThesisInputs<double>::*field, double factor,
                                double t_fault);

/// Applies f to the samples of ms in place (bias/drift clipped to the channel's range and
/// re-quantised with cfg's channel spec).
/// @throws std::invalid_argument on a channel outside 0…3 or a cfg without 4 channels
void inject_sensor_fault(ThesisMeasurements& ms, const SensorConfig& cfg, const SensorFault& f);

}  // namespace hstmon::sim
