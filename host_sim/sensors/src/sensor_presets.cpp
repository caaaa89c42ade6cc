/// @file sensor_presets.cpp
#include "hstmon_sensors/sensor_presets.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hstmon::sim {

namespace {

constexpr double kPressureTau = 1e-3;               // [s], assumed
constexpr double kSpeedTau = 10e-3;                 // [s], assumed
constexpr double kPressureNoise = 0.05 * kPaPerBar;  // [Pa], assumed
constexpr double kSpeedNoise = 0.5 * kRadPerSecPerRpm;  // [rad/s], assumed

ChannelSpec pressure(const char* name, double hi_bar, int bits) {
  ChannelSpec c;
  c.name = name;
  c.tau = kPressureTau;
  c.noise_std = kPressureNoise;
  c.range_lo = 0.0;
  c.range_hi = hi_bar * kPaPerBar;
  c.quant_step = adc_step(c.range_lo, c.range_hi, bits);
  return c;
}

ChannelSpec speed(double hi_rpm) {
  ChannelSpec c;
  c.name = "w_m";
  c.tau = kSpeedTau;
  c.noise_std = kSpeedNoise;
  c.range_lo = 0.0;
  c.range_hi = hi_rpm * kRadPerSecPerRpm;
  c.quant_step = kRadPerSecPerRpm;  // 1 rpm
  return c;
}

double period_of(double rate_hz) {
  if (!(std::isfinite(rate_hz) && rate_hz > 0.0)) throw std::invalid_argument("sample rate must be > 0");
  return 1.0 / rate_hz;
}

SensorConfig thesis_sensors(int bits, double period) {
  SensorConfig c;
  c.channels = {pressure("p_mi", 200.0, bits), pressure("p_mo", 200.0, bits), pressure("p_pp", 250.0, bits),
                speed(3000.0)};
  c.sample_period = period;
  return c;
}

}  // namespace

SensorConfig thesis_das_sensors() { return thesis_sensors(12, 4.0); }

SensorConfig thesis_fast_sensors(double rate_hz) { return thesis_sensors(16, period_of(rate_hz)); }

SensorConfig rig_fast_sensors(double rate_hz) {
  SensorConfig c = thesis_sensors(16, period_of(rate_hz));
  for (ChannelSpec& ch : c.channels) {
    ch.tau = 0.0;
    ch.noise_std = 0.04 * kPaPerBar;
    ch.quant_step = 0.01 * kPaPerBar;
    ch.under_range = kNe43Under;
    ch.over_range = kNe43Over;
  }
  c.channels[2].range_hi = 400.0 * kPaPerBar;  // Ppp overshoots a load step by 100–180 bar
  ChannelSpec& w = c.channels[3];
  w.noise_std = kSpeedNoise;
  w.quant_step = 0.01 * kRadPerSecPerRpm;
  w.range_lo = -w.range_hi;
  return c;
}

SensorConfig with_rate(SensorConfig c, double rate_hz) {
  c.sample_period = period_of(rate_hz);
  return c;
}

SensorConfig with_lag(SensorConfig c, double tau) {
  if (!(std::isfinite(tau) && tau >= 0.0)) throw std::invalid_argument("transducer lag must be >= 0");
  for (ChannelSpec& ch : c.channels) ch.tau = tau;
  return c;
}

SensorConfig with_pressure_step(SensorConfig c, double step) {
  if (!(std::isfinite(step) && step >= 0.0)) throw std::invalid_argument("ADC step must be >= 0");
  // Pressures are every channel but the last (speed), in both rigs' channel orders.
  for (std::size_t i = 0; i + 1 < c.channels.size(); ++i) c.channels[i].quant_step = step;
  return c;
}

SensorConfig with_pressure_adc_bits(SensorConfig c, int bits) {
  for (std::size_t i = 0; i + 1 < c.channels.size(); ++i) {
    c.channels[i].quant_step = adc_step(c.channels[i].range_lo, c.channels[i].range_hi, bits);
  }
  return c;
}

SensorConfig paper_logger_sensors(double rate_hz) {
  SensorConfig c;
  c.channels = {pressure("p_s", 250.0, 12), pressure("p_mi", 250.0, 12), pressure("p_pp", 250.0, 12), speed(5000.0)};
  c.sample_period = period_of(rate_hz);
  return c;
}

SensorConfig without_noise(SensorConfig c) {
  for (ChannelSpec& ch : c.channels) ch.noise_std = 0.0;
  return c;
}

SensorConfig ideal_sensors(SensorConfig c) {
  for (ChannelSpec& ch : c.channels) {
    ch.tau = 0.0;
    ch.noise_std = 0.0;
    ch.quant_step = 0.0;
    ch.range_lo = -std::numeric_limits<double>::infinity();
    ch.range_hi = std::numeric_limits<double>::infinity();
    ch.under_range = 0.0;
    ch.over_range = 0.0;
  }
  return c;
}

std::vector<std::string> sensor_preset_names() { return {"thesis_das", "fast", "rig_fast", "paper_logger"}; }

std::optional<SensorConfig> sensor_preset(std::string_view name) {
  if (name == "thesis_das") return thesis_das_sensors();
  if (name == "fast") return thesis_fast_sensors();
  if (name == "rig_fast") return rig_fast_sensors();
  if (name == "paper_logger") return paper_logger_sensors();
  return std::nullopt;
}

}  // namespace hstmon::sim
