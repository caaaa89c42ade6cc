#pragma once
/// @file sensor_presets.hpp
/// Sensor configurations of the two rigs. Numbers not in the sources are assumptions,
/// marked so; all are plain data and can be edited by the caller.
///
/// Thesis rig (Table 2.1): WIKA S-10 pressure transmitters, 4–20 mA, 0–200 bar, on Pmi, Pmo
/// and Ppp; a speed sensor on ωm; DAS sampling every 4 s (§2.5.2).
///  - Ranges: p_mi, p_mo 0–200 bar (as listed). p_pp 0–250 bar — an assumption: Ppp reaches
///    226.8 bar with kp halved, which a 0–200 bar transmitter would clip (the part number
///    S10-250 suggests a 250 bar variant exists). Outputs are clipped at the range ends.
///  - Lag τ = 1 ms for pressures (assumed, typical of piezoresistive transmitters), 10 ms
///    for speed (assumed, frequency-to-analogue conversion).
///  - Noise σ = 0.05 bar for pressures, 0.5 rpm for speed (assumed).
///  - ADC: 12 bits over the range for thesis_das (0.0488 bar steps over 200 bar),
///    16 bits for fast (0.00305 bar); speed counted to 1 rpm, range 0–3000 rpm.
/// Rig with fast transducers (as a modern logger on the thesis rig, and the independent
/// simulator's logs of ../shared/validation): no transducer lag, σ = 0.04 bar / 0.5 rpm,
/// ADC step 0.01 bar, speed resolved to 0.01 rpm, ranges as the thesis rig but Ppp 0–400 bar
/// (with no lag, Ppp overshoots a PRV step by 100–180 bar for a few ms: an installation
/// with fast transducers sizes the transmitter for it) and ωm ±3000 rpm (a standing motor
/// reads ±noise), outputs in NAMUR NE 43's band (noise at 0 bar reads
/// slightly negative, not clipped to the range end).
/// Paper rig: Hydac HMG 3010 logger every 2 ms (§5.4); sensors assumed 0–250 bar, 12 bits,
/// same lag and noise as above; speed 1 rpm, 0–5000 rpm.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon_sensors/sensor_chain.hpp"

namespace hstmon::sim {

/// 1 bar in Pa.
inline constexpr double kPaPerBar = 1e5;
/// 1 rpm in rad/s.
inline constexpr double kRadPerSecPerRpm = 3.14159265358979323846 / 30.0;

/// A measurement set-up: channels in the model's output order, sample period and the
/// internal step at which the lags are fed.
struct SensorConfig {
  std::vector<ChannelSpec>
      channels;  ///< thesis: p_mi, p_mo, p_pp, w_m; paper: p_s, p_mi, p_pp, w_m (the names of the circuits' sensors)
  double sample_period = 4.0;         ///< logger sampling period [s]
  double lag_step = 1e-4;             ///< largest internal step of the lag integration [s]
};

/// Thesis rig with its DAS: 4 s period, 12-bit ADC.
SensorConfig thesis_das_sensors();

/// Thesis rig with a fast logger: rate_hz [Hz] (default 1 kHz), 16-bit ADC.
SensorConfig thesis_fast_sensors(double rate_hz = 1000.0);

/// Thesis rig with fast transducers (see file note): rate_hz [Hz] (default 1 kHz).
SensorConfig rig_fast_sensors(double rate_hz = 1000.0);

/// The same set-up sampled at rate_hz [Hz] (> 0).
SensorConfig with_rate(SensorConfig c, double rate_hz);

/// The same set-up with every channel's transducer lag τ = tau [s] (0 = no lag).
SensorConfig with_lag(SensorConfig c, double tau);

/// The same set-up with the pressure channels' ADC step set to step [Pa] (0 = none);
/// speed kept.
SensorConfig with_pressure_step(SensorConfig c, double step);

/// The same set-up with a `bits`-bit ADC over each pressure transmitter's range.
SensorConfig with_pressure_adc_bits(SensorConfig c, int bits);

/// Paper rig with its HMG 3010 logger: rate_hz [Hz] (default 500 Hz = every 2 ms).
SensorConfig paper_logger_sensors(double rate_hz = 500.0);

/// The same set-up without noise (σ = 0); lag, clipping and quantisation kept.
SensorConfig without_noise(SensorConfig c);

/// The same set-up with ideal sensors: no lag, noise, clipping or quantisation (the log
/// then holds the reference solution at the sample times).
SensorConfig ideal_sensors(SensorConfig c);

/// Names of the presets: "thesis_das", "fast", "rig_fast", "paper_logger".
std::vector<std::string> sensor_preset_names();

/// Preset by name at its default rate; std::nullopt for an unknown name.
std::optional<SensorConfig> sensor_preset(std::string_view name);

}  // namespace hstmon::sim
