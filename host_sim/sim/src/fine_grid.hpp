#pragma once
/// @file fine_grid.hpp
/// Internal: the fine time grid on which measure() and measure_with_fault() feed the
/// sensor lags: m points per sample period, none more than lag_step apart.

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "hstmon_sensors/sensor_presets.hpp"

namespace hstmon::sim::detail {

/// Fine points fed to the lags per call of the reference (bounds memory on long runs;
/// each batch end is a sample point, so the extra hard stops change nothing visible).
constexpr std::size_t kBatch = 1u << 16;

/// Fine steps per sample period: 1 without lags, else enough that none exceeds lag_step.
/// @param who  the caller, for the messages
/// @throws std::invalid_argument unless four channels, sample period [s] > 0 and, when a
///         channel lags, lag_step [s] > 0
inline std::size_t substeps(const SensorConfig& cfg, const std::string& who) {
  if (!(std::isfinite(cfg.sample_period) && cfg.sample_period > 0.0)) {
    throw std::invalid_argument(who + ": sample_period must be > 0");
  }
  if (cfg.channels.size() != 4) throw std::invalid_argument(who + ": need 4 channels");
  bool any_lag = false;
  for (const ChannelSpec& c : cfg.channels) any_lag = any_lag || c.tau > 0.0;
  if (!any_lag) return 1;
  if (!(std::isfinite(cfg.lag_step) && cfg.lag_step > 0.0)) throw std::invalid_argument(who + ": lag_step must be > 0");
  const double m = std::ceil(cfg.sample_period / cfg.lag_step * (1.0 - 1e-12));
  if (m > 1e9) throw std::invalid_argument(who + ": lag_step too small for the sample period");
  return static_cast<std::size_t>(std::fmax(1.0, m));
}

/// Fine point i at t_i = (i / m)·period + (i % m)·h, so t_{k·m} = k·period exactly.
struct FineGrid {
  /// @param run_length  run length [s]; other parameters and throws as substeps()
  FineGrid(const SensorConfig& cfg, double run_length, const std::string& who)
      : m(substeps(cfg, who)),
        period(cfg.sample_period),
        h(period / static_cast<double>(m)),
        duration(run_length),
        last(static_cast<std::size_t>(run_length / h) + 2) {
    const double t_max = run_length * (1.0 + 1e-12);
    while (last > 0 && raw(last) > t_max) --last;
  }

  /// Time of fine point i [s] before clipping to the run's end.
  double raw(std::size_t i) const { return static_cast<double>(i / m) * period + static_cast<double>(i % m) * h; }
  /// Time of fine point i [s], not past the run's end.
  double at(std::size_t i) const { return std::fmin(raw(i), duration); }

  std::size_t m;     ///< fine points per sample period
  double period;     ///< sample period [s]
  double h;          ///< fine step [s]
  double duration;   ///< run length [s]
  std::size_t last;  ///< the last fine point within the run
};

}  // namespace hstmon::sim::detail
