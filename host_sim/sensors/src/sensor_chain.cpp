/// @file sensor_chain.cpp
#include "hstmon_sensors/sensor_chain.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace hstmon::sim {

double adc_step(double lo, double hi, int bits) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && hi > lo) || bits < 1 || bits > 52) {
    throw std::invalid_argument("adc_step: need finite lo < hi and 1..52 bits");
  }
  return (hi - lo) / (std::ldexp(1.0, bits) - 1.0);
}

double lag_update(double y, double x0, double x1, double h, double tau) {
  if (!(tau > 0.0)) return x1;
  const double r = h / tau;
  const double a = std::exp(-r);
  const double one_minus_a = -std::expm1(-r);
  // b = 1 − (1 − a)/r, the weight of the ramp; series below r = 1e-3 avoids cancellation.
  const double b = (r < 1e-3) ? r * (0.5 - r * (1.0 / 6.0 - r / 24.0)) : 1.0 - one_minus_a / r;
  return a * y + one_minus_a * x0 + (x1 - x0) * b;
}

double clip_and_quantise(double v, const ChannelSpec& c) {
  if (std::isnan(v)) return v;
  const double span = c.range_hi - c.range_lo;
  // Band ends; an infinite range has no band (inf·0 would be NaN).
  const double lo = c.under_range > 0.0 ? c.range_lo - c.under_range * span : c.range_lo;
  const double hi = c.over_range > 0.0 ? c.range_hi + c.over_range * span : c.range_hi;
  double out = std::fmin(std::fmax(v, lo), hi);
  if (c.quant_step > 0.0) {
    const double origin = std::isfinite(c.range_lo) ? c.range_lo : 0.0;
    out = origin + std::nearbyint((out - origin) / c.quant_step) * c.quant_step;
    // Rounding to the grid never leaves the band (its ends are codes or clip again).
    out = std::fmin(std::fmax(out, lo), hi);
  }
  return out;
}

SensorChain::SensorChain(std::vector<ChannelSpec> channels, std::uint64_t seed)
    : ch_(std::move(channels)), y_(ch_.size(), 0.0), x_last_(ch_.size(), 0.0), noise_(seed) {
  for (const ChannelSpec& c : ch_) {
    const bool ok = std::isfinite(c.tau) && c.tau >= 0.0 && std::isfinite(c.noise_std) && c.noise_std >= 0.0 &&
                    std::isfinite(c.quant_step) && c.quant_step >= 0.0 && !std::isnan(c.range_lo) &&
                    std::isfinite(c.under_range) && c.under_range >= 0.0 && std::isfinite(c.over_range) &&
                    c.over_range >= 0.0 &&
                    !std::isnan(c.range_hi) && c.range_lo < c.range_hi;
    if (!ok) throw std::invalid_argument("SensorChain: invalid specification of channel " + c.name);
  }
}

void SensorChain::reset(const double* truth) {
  for (std::size_t i = 0; i < ch_.size(); ++i) {
    y_[i] = truth[i];
    x_last_[i] = truth[i];
  }
}

void SensorChain::advance(const double* truth, double h) {
  if (!(h > 0.0)) throw std::invalid_argument("SensorChain::advance: h must be > 0");
  for (std::size_t i = 0; i < ch_.size(); ++i) {
    y_[i] = lag_update(y_[i], x_last_[i], truth[i], h, ch_[i].tau);
    x_last_[i] = truth[i];
  }
}

void SensorChain::measure(double* out) {
  for (std::size_t i = 0; i < ch_.size(); ++i) {
    double v = y_[i];
    if (ch_[i].noise_std > 0.0) v += ch_[i].noise_std * noise_.next();
    out[i] = clip_and_quantise(v, ch_[i]);
  }
}

}  // namespace hstmon::sim
