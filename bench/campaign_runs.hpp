#pragma once
/// @file campaign_runs.hpp
/// Building blocks of the fault campaign (bench/fault_campaign.cpp, docs/fault_campaign.md):
/// the fault list, one monitored run (synthetic log → Monitor<double>), the nominal
/// long-replay segments, and the isolable classes of the signature table.

#include <cstdint>
#include <string>
#include <vector>

#include "hstmon/monitor.hpp"
#include "hstmon_sim/param_fault.hpp"

namespace hstmon_campaign {

using Inputs = hstmon::ThesisInputs<double>;
using Params = hstmon::ThesisParams<double>;
using Mon = hstmon::Monitor<double>;

/// Operating points: PRV setting as a multiple of Table 2.2's kp.
struct OperatingPoint {
  const char* name;
  double kp_factor;
};
inline constexpr OperatingPoint kOperatingPoints[] = {{"light", 1.6}, {"nominal", 1.0}, {"heavy", 0.65}};

/// What a fault changes.
enum class Target { kParam, kInput, kSensor };

/// One fault of the campaign at one magnitude.
struct FaultCase {
  std::string row;          ///< table row that is the truth ("kp-", "sensor_p_mi")
  std::string label;        ///< row plus magnitude / kind, for the report
  Target target = Target::kParam;
  double Params::*param = nullptr;  ///< for kParam
  double Inputs::*input = nullptr;  ///< for kInput
  double factor = 1.0;      ///< multiplies the parameter / input (1 ± magnitude)
  double magnitude = 0.0;   ///< relative size (parameter faults) [-]
  hstmon::sim::SensorFault sensor{};  ///< for kSensor (t_start set by the run)
  double sensor_value_fs = 0.0;       ///< sensor fault size in % of full scale (or %FS/s)
};

/// The campaign's fault list. Parameter faults: every row of the thesis table at two
/// magnitudes each (see docs/fault_campaign.md for the choice). Sensor faults: bias ±,
/// drift ±, stuck on each channel.
std::vector<FaultCase> parameter_faults();
std::vector<FaultCase> sensor_faults(const hstmon::sim::SensorConfig& sensors);

/// Machine parameters off by a uniform random factor in [1 − spread, 1 + spread] on each of
/// Dm, Dp, Rlkg, Ripl, Rf, Rbl, kf, J, K (the monitor keeps Table 2.2).
Params perturbed_machine(std::uint64_t seed, double spread);

/// The monitor as the campaign runs it: Table 2.2 parameters, generated table, default
/// evaluator/matcher configuration, sensor ranges and noise from the sensor set-up.
Mon::Config monitor_config(const hstmon::sim::SensorConfig& sensors);

/// Result of one monitored log.
struct RunResult {
  bool detected = false;          ///< an episode started at or after the fault time
  double t_detect = -1.0;         ///< first detection at or after the fault time [s]
  int false_events = 0;           ///< detections before the fault time
  long alarm_ticks_before = 0;    ///< ticks with a channel alarm before the fault
  bool decided = false;           ///< a decision event (isolated/ambiguous/unexplained) after the fault
  double t_decide = -1.0;         ///< first decision after the fault [s]
  hstmon::MatchEvent<double> first_decision{};  ///< first decision event after the fault
  hstmon::MatchEvent<double> last_decision{};   ///< last decision event after the fault (the standing diagnosis)
  /// Matcher evidence at the last decision: first-deviating channels (bit per channel),
  /// magnitude and slope symbols per channel (QualSign; slope kQualAny = channel never alarmed).
  std::uint8_t first_channels = 0;
  std::int8_t magnitude[4] = {}, slope[4] = {};
  hstmon::MatchStatus final_status = hstmon::MatchStatus::kNominal;
  std::uint32_t health = 0;       ///< OR of the observer's health flags
};

/// Feeds a log through a fresh monitor started at the steady state of the first row's
/// logged inputs. Events before fault_time count as false alarms.
RunResult monitor_log(const hstmon::sim::ThesisMeasurements& log, const Mon::Config& cfg, double fault_time);

/// Nominal replay: statistics over a log with no fault.
struct NominalStats {
  long ticks = 0;
  long alarm_ticks = 0;
  long detections = 0;             ///< episodes started (false alarms)
  std::uint32_t health = 0;
  std::vector<std::string> first_candidates;  ///< best candidate of each false alarm's decision
  std::vector<double> detection_times;        ///< [s] into the segment
  std::vector<std::uint8_t> alarm_channels;   ///< evaluator alarm bits at each detection
};
NominalStats monitor_nominal(const hstmon::sim::ThesisMeasurements& log, const Mon::Config& cfg);

/// A nominal segment of the long replay: `duration` [s] on a machine off by ±spread.
/// Constant load: steady at one operating point. Slow load changes: every 10 s a new PRV
/// setting drawn in [0.65, 1.6]·kp0, reached by a ramp of 100 ms steps over 4 s.
hstmon::sim::ThesisScenario nominal_segment(std::uint64_t seed, double duration, bool load_changes);

/// Isolable classes of the table: rows k, j share a class when their qualitative
/// signatures are compatible on every channel (magnitude and slope equal or one of them
/// kQualAny, equal order) and their directions lie within tie_margin of each other (both
/// zero counts as equal). class_of[k] lists the rows of k's class, k included.
std::vector<std::vector<int>> isolable_classes(const hstmon::FaultSignature* table, int count, double tie_margin);

/// Row index of a name in the thesis table; −1 if absent.
int row_index(const std::string& name);

/// Largest steady-state deviation of the fault over the detection threshold (model bound +
/// k_drift·σ) at the operating point, for the monitor's nominal parameters [-]: ≥ 1 means
/// the steady effect alone clears the threshold.
double predicted_visibility(const FaultCase& f, const Inputs& u, const Mon::Config& cfg);

}  // namespace hstmon_campaign
