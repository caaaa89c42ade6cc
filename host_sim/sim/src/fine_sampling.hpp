#pragma once
/// @file fine_sampling.hpp
/// Internal: measure() and measure_with_fault() feed a run's outputs to the sensor chain
/// at every point of a fine grid (m points per sample period, none more than lag_step
/// apart, so the lags see the run) and keep a measurement at every sample point.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/scenario.hpp"

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

template <class Inputs>
class FineSampling {
 public:
  /// @param x0  the four outputs at t = 0 (three pressures [Pa], a speed [rad/s]): the first row
  FineSampling(const SensorConfig& cfg, std::uint64_t seed, const Scenario<Inputs>& sc, const FineGrid& grid,
               const double* x0)
      : chain_(cfg.channels, seed), sc_(sc), grid_(grid) {
    out_.reserve(grid.last / grid.m + 1);
    chain_.reset(x0);
    keep(0.0);
    batch_.reserve(kBatch);
  }

  /// The four outputs v at the next fine point, time t [s].
  void feed(double t, const double* v) {
    ++fed_;
    chain_.advance(v, t - t_last_);
    t_last_ = t;
    if (fed_ % grid_.m == 0) keep(t);
  }

  /// Calls advance(t_end, points) over the fine points up to seg_end [s], at most kBatch
  /// points a call; advance integrates to t_end and feed()s each point.
  template <class Advance>
  void through(double seg_end, Advance advance) {
    for (;;) {
      batch_.clear();
      for (std::size_t j = fed_ + 1; j <= grid_.last && batch_.size() < kBatch && grid_.at(j) <= seg_end; ++j) {
        batch_.push_back(grid_.at(j));
      }
      const bool last_batch = batch_.size() < kBatch;
      advance(last_batch ? seg_end : batch_.back(), batch_);
      if (last_batch) break;
    }
  }

  /// The measurements so far.
  std::vector<Measurement<Inputs>> take() { return std::move(out_); }

 private:
  void keep(double t) {
    Measurement<Inputs> r;
    r.t = t;
    r.u = logged_inputs_at(sc_, t);
    chain_.measure(r.y.data());
    out_.push_back(r);
  }

  SensorChain chain_;
  const Scenario<Inputs>& sc_;
  const FineGrid& grid_;
  std::vector<Measurement<Inputs>> out_;
  std::vector<double> batch_;
  std::size_t fed_ = 0;  // fine points fed
  double t_last_ = 0.0;  // the last one's time [s]
};

}  // namespace hstmon::sim::detail
