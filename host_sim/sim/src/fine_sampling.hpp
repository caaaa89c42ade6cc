#pragma once
/// @file fine_sampling.hpp
/// Internal: a run's outputs fed to the sensor chain at every point of the fine grid
/// (fine_grid.hpp), a measurement kept at every sample point; for measure() and
/// measure_with_fault().

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "fine_grid.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/scenario.hpp"

namespace hstmon::sim::detail {

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
