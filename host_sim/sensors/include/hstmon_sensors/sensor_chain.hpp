#pragma once
/// @file sensor_chain.hpp
/// Model of the measurement chain of one rig: per channel a first-order transducer lag,
/// additive Gaussian white noise, clipping to the transmitter's range and ADC
/// quantisation, in that order. All values are SI (Pa, rad/s).
///
/// Lag: τ·dy/dt = x(t) − y. The caller feeds the true signal at a fine internal rate; between
/// two feeds the signal is taken linear and the lag is integrated exactly for that ramp:
///   y ← a·y + (1 − a)·x0 + (x1 − x0)·(1 − (τ/h)·(1 − a)),  a = exp(−h/τ),
/// so the only error is the linear interpolation of x (≤ h²·max|x''|/8), whatever h/τ.
/// Noise: one independent N(0, σ²) draw per channel and per measure() — white noise sampled
/// at the logger rate (its bandwidth is taken to exceed the sample rate).
/// Clip: to [range_lo − under·span, range_hi + over·span] (span = range_hi − range_lo): a
/// 4–20 mA transmitter's output band; 0 by default (clipped at the range ends), NAMUR
/// NE 43's 3.8–20.5 mA band with under = 0.2/16, over = 0.5/16, so noise around 0 bar
/// reads slightly negative, as on a real rig.
/// Quantisation: to range_lo + k·quant_step, k integer (rounding to nearest).

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hstmon_sensors/gaussian.hpp"

namespace hstmon::sim {

/// Specification of one measured channel. Units are the channel's SI unit (Pa or rad/s).
struct ChannelSpec {
  std::string name;         ///< column stem in logs, e.g. "p_mi"
  double tau = 0.0;         ///< first-order lag time constant [s]; 0 = no lag
  double noise_std = 0.0;   ///< standard deviation of the additive white noise [SI]
  double range_lo = -std::numeric_limits<double>::infinity();  ///< lower range end [SI]
  double range_hi = std::numeric_limits<double>::infinity();   ///< upper range end [SI]
  double quant_step = 0.0;  ///< quantisation step [SI]; 0 = none
  double under_range = 0.0; ///< output band below range_lo, fraction of the span [-]
  double over_range = 0.0;  ///< output band above range_hi, fraction of the span [-]
};

/// NAMUR NE 43 output band of a 4–20 mA transmitter (3.8–20.5 mA), fractions of the span.
inline constexpr double kNe43Under = 0.2 / 16.0;
inline constexpr double kNe43Over = 0.5 / 16.0;
/// NE 43 failure level of a broken loop (≤ 3.6 mA) below range_lo, fraction of the span.
inline constexpr double kNe43LoopBreak = 0.4 / 16.0;

/// Step of an ADC with `bits` bits spanning [lo, hi] (2^bits codes, the ends included):
/// (hi − lo) / (2^bits − 1) [unit of lo, hi].
double adc_step(double lo, double hi, int bits);

/// Exact lag update over h [s] for a signal ramping linearly from x0 to x1 (see file note).
/// @param y    lag output at the start of the interval [SI]
/// @param tau  time constant [s]; tau ≤ 0 returns x1
double lag_update(double y, double x0, double x1, double h, double tau);

/// Clips v to the channel's output band and rounds it to its quantisation grid [SI].
double clip_and_quantise(double v, const ChannelSpec& c);

/// The sensor chain of several channels, seeded for reproducibility.
class SensorChain {
 public:
  /// @param channels  channel specifications (τ ≥ 0, σ ≥ 0, step ≥ 0, lo < hi)
  /// @param seed      noise seed; equal seeds and feeds give identical measurements
  /// @throws std::invalid_argument on an invalid specification
  SensorChain(std::vector<ChannelSpec> channels, std::uint64_t seed);

  /// Number of channels.
  std::size_t size() const noexcept { return ch_.size(); }
  /// Channel specifications.
  const std::vector<ChannelSpec>& channels() const noexcept { return ch_; }

  /// Settles every lag at the true values `truth` (size() entries, SI).
  void reset(const double* truth);

  /// Advances the lags by h [s] > 0 to the new true values `truth`, the signal taken
  /// linear between the previous feed and this one.
  void advance(const double* truth, double h);

  /// Samples all channels: out[i] = Q(clip(y_i + σ_i·n_i)) [SI], n_i ~ N(0, 1).
  void measure(double* out);

  /// Lag outputs y_i before noise and ADC [SI].
  const std::vector<double>& lagged() const noexcept { return y_; }

 private:
  std::vector<ChannelSpec> ch_;
  std::vector<double> y_;       // lag outputs
  std::vector<double> x_last_;  // last fed truth
  GaussianSource noise_;
};

}  // namespace hstmon::sim
