/// @file measure.cpp
#include "hstmon_sim/measure.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon_sim/paper_reference.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/thesis_reference.hpp"

namespace hstmon::sim {

namespace {

void state_to_array(const PaperModel<double>::State& x, double* out) {
  for (int i = 0; i < 4; ++i) out[i] = x[i];
}

void state_to_array(const ThesisState<double>& x, double* out) { to_array(x, out); }

/// Number of fine steps per sample period.
std::size_t substeps(const SensorConfig& cfg) {
  if (!(std::isfinite(cfg.sample_period) && cfg.sample_period > 0.0)) {
    throw std::invalid_argument("measure: sample_period must be > 0");
  }
  if (cfg.channels.size() != 4) throw std::invalid_argument("measure: need 4 channels");
  bool any_lag = false;
  for (const ChannelSpec& c : cfg.channels) any_lag = any_lag || c.tau > 0.0;
  if (!any_lag) return 1;
  if (!(std::isfinite(cfg.lag_step) && cfg.lag_step > 0.0)) throw std::invalid_argument("measure: lag_step must be > 0");
  const double m = std::ceil(cfg.sample_period / cfg.lag_step * (1.0 - 1e-12));
  if (m > 1e9) throw std::invalid_argument("measure: lag_step too small for the sample period");
  return static_cast<std::size_t>(std::fmax(1.0, m));
}

/// Fine points fed to the lags per call of the reference (bounds memory on long runs;
/// each batch end is a sample point, so the extra hard stops change nothing visible).
constexpr std::size_t kBatch = 1u << 16;

template <class Reference, class Inputs>
std::vector<Measurement<Inputs>> run(Reference& ref, const Scenario<Inputs>& sc, const SensorConfig& cfg,
                                     std::uint64_t seed) {
  using State = typename Reference::State;
  const std::size_t m = substeps(cfg);
  const double period = cfg.sample_period;
  const double h = period / static_cast<double>(m);
  // Fine grid i: t_i = (i / m)·period + (i % m)·h, so t_{k·m} = k·period exactly.
  const double t_max = sc.duration * (1.0 + 1e-12);
  auto t_raw = [&](std::size_t i) { return static_cast<double>(i / m) * period + static_cast<double>(i % m) * h; };
  std::size_t n_last = static_cast<std::size_t>(sc.duration / h) + 2;
  while (n_last > 0 && t_raw(n_last) > t_max) --n_last;
  auto t_fine = [&](std::size_t i) { return std::fmin(t_raw(i), sc.duration); };

  SensorChain chain(cfg.channels, seed);
  std::vector<Measurement<Inputs>> out;
  out.reserve(n_last / m + 1);
  double x[4];
  state_to_array(ref.state(), x);
  chain.reset(x);
  Measurement<Inputs> row;
  row.t = 0.0;
  row.u = logged_inputs_at(sc, 0.0);
  chain.measure(row.y.data());
  out.push_back(row);

  std::size_t i = 0;  // index of the last fine point fed
  double t_last = 0.0;
  auto on_sample = [&](double t, const State& xs) {
    ++i;
    double v[4];
    state_to_array(xs, v);
    chain.advance(v, t - t_last);
    t_last = t;
    if (i % m == 0) {
      Measurement<Inputs> r;
      r.t = t;
      r.u = logged_inputs_at(sc, t);
      chain.measure(r.y.data());
      out.push_back(r);
    }
  };
  std::vector<double> batch;
  batch.reserve(kBatch);
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    const double seg_end = segment_end(sc, k);
    for (;;) {
      batch.clear();
      for (std::size_t j = i + 1; j <= n_last && batch.size() < kBatch && t_fine(j) <= seg_end; ++j) {
        batch.push_back(t_fine(j));
      }
      const bool last_batch = batch.size() < kBatch;
      ref.advance_to(last_batch ? seg_end : batch.back(), sc.schedule[k].u, batch, on_sample);
      if (last_batch) break;
    }
  }
  return out;
}

}  // namespace

ThesisMeasurements measure(const ThesisScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                           const ThesisParams<double>& p, const ReferenceTolerances& tol) {
  validate(sc);
  ThesisReference ref(p, thesis_initial_state(sc, p), 0.0, tol);
  return run(ref, sc, cfg, seed);
}

PaperMeasurements measure(const PaperScenario& sc, const SensorConfig& cfg, std::uint64_t seed,
                          const PaperParams<double>& p, const ReferenceTolerances& tol) {
  validate(sc);
  PaperReference ref(p, paper_initial_state(sc, p), 0.0, tol);
  return run(ref, sc, cfg, seed);
}

}  // namespace hstmon::sim
