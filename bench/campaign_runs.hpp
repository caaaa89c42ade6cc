#pragma once
/// @file campaign_runs.hpp
/// Building blocks of the fault campaign (bench/fault_campaign.cpp, docs/fault_campaign.md):
/// the rig conditions, the fault list, one monitored log (the thesis reference's synthetic
/// log → the built-in thesis.json through replay_circuit, exactly what `hstmon replay`
/// runs) and its scoring.

#include <cstdint>
#include <string>
#include <vector>

#include "campaign_score.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_sim/load_profile.hpp"
#include "hstmon_sim/param_fault.hpp"
#include "hstmon_sim/rig_run.hpp"

namespace hstmon_campaign {

using Inputs = hstmon::ThesisInputs<double>;
using Params = hstmon::ThesisParams<double>;

/// One rig condition: the baseline with one factor changed (docs/fault_campaign.md).
struct Condition {
  std::string name;                 ///< e.g. "lag 10 ms"
  std::string factor;               ///< what it varies: base, lag, rate, start, load, quant, param
  double rate = 1000.0;             ///< [Hz]
  double lag = 0.0;                 ///< transducer time constant, every channel [s]
  double quant = 0.01e5;            ///< pressure ADC step [Pa]; 0 none
  int adc_bits = 0;                 ///< > 0: pressure ADC of that many bits over the range (instead of quant)
  double spread = 0.02;             ///< machine parameter error, uniform ± [-]
  bool from_rest = true;            ///< logger runs before the supply
  double supply_on = 0.0;           ///< [s] from the first sample (from rest)
  hstmon::sim::LoadShape load = hstmon::sim::LoadShape::kSteps;
  double ppp_range = 400e5;         ///< Ppp transmitter's high end [Pa] (output clipped in NE 43's band)
  bool declare_ranges = false;      ///< replay told the transmitter ranges (a parameter file's "sensors")
};

/// Baseline (a rig like ../shared/validation's: rig_fast sensors at 1 kHz, no lag, 0.01 bar
/// ADC, ±2 % machine, start from rest, PRV steps every 2 s) and one-factor variations.
std::vector<Condition> campaign_conditions();

/// Time scale of a condition: 1, or 20 for sample periods ≥ 0.1 s (the 4 s DAS), so a
/// run holds enough samples (load periods, fault time and run length scale with it).
double time_scale(const Condition& c);

/// Sensors of a condition (rig_fast_sensors with rate, lag and ADC set).
hstmon::sim::SensorConfig sensors_of(const Condition& c);

/// A run of the condition: `duration` [s], load from kp factor `level`, load seed;
/// with_cycles: one stop/start (supply off at 60 %, on again at 70 % of the duration).
hstmon::sim::RigRun run_of(const Condition& c, double duration, double level, std::uint64_t load_seed,
                           bool with_cycles);

/// What a fault changes.
enum class Target { kParam, kInput, kSensor };

/// One fault at one magnitude.
struct FaultCase {
  std::string row;          ///< truth ("kp-", "sensor_p_mi")
  std::string label;        ///< row plus magnitude / kind
  std::string group;        ///< report group: "kp- 50%", "param", "loop break", "stuck", "bias 2%FS", "bias 5%FS"
  Target target = Target::kParam;
  double Params::*param = nullptr;  ///< for kParam
  double Inputs::*input = nullptr;  ///< for kInput
  double factor = 1.0;      ///< multiplies the parameter / input
  hstmon::sim::SensorFault sensor{};  ///< for kSensor (t_start set by the run)
};

/// Parameter faults: every row of the thesis table except J±, K± (zero steady-state
/// signature by design) at two magnitudes; the kp- 50 % blockage is its own group.
std::vector<FaultCase> parameter_faults();
/// Sensor faults per channel: loop break, stuck, bias ±2 % and ±5 % of full scale.
std::vector<FaultCase> sensor_faults(const hstmon::sim::SensorConfig& sensors);

/// A synthetic log replayed as `hstmon replay` does: the built-in thesis.json, its fault
/// table (fdi::circuit_signature_table, built once), default options; with declare_ranges,
/// told the transmitter ranges of the sensor set-up (as an installation's parameter file
/// would), else thesis.json's.
hstmon::circuit_tools::CircuitReplayResult replay_log(const hstmon::sim::ThesisMeasurements& log,
                                                      const hstmon::sim::SensorConfig& sensors, bool declare_ranges);

/// A synthetic log as a thesis.json log's text (`hstmon replay` reads it), note as its comment.
std::string log_text(const hstmon::sim::ThesisMeasurements& log, const std::string& note);

/// False alarms of a nominal log: detected events.
struct NominalStats {
  double seconds = 0.0;
  long rows = 0;
  long detections = 0;
  long nonfinite = 0;      ///< rows whose residual statistics turned non-finite
  std::uint32_t health = 0;
  std::vector<double> times;         ///< [s] of each false detection
  std::vector<std::string> calls;    ///< best candidate of the decision that followed
};
NominalStats score_nominal(const hstmon::circuit_tools::CircuitReplayResult& r);

}  // namespace hstmon_campaign
