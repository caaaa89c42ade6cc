/// @file measure.cpp
#include "hstmon_sim/measure.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon_sim/paper_reference.hpp"
#include "fine_grid.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/thesis_reference.hpp"

namespace hstmon::sim {

namespace {

void state_to_array(const PaperModel<double>::State& x, double* out) {
  for (int i = 0; i < 4; ++i) out[i] = x[i];
}

void state_to_array(const ThesisState<double>& x, double* out) { to_array(x, out); }

template <class Reference, class Inputs>
std::vector<Measurement<Inputs>> run(Reference& ref, const Scenario<Inputs>& sc, const SensorConfig& cfg,
                                     std::uint64_t seed) {
  using State = typename Reference::State;
  const detail::FineGrid grid(cfg, sc.duration, "measure");
  const std::size_t m = grid.m;

  SensorChain chain(cfg.channels, seed);
  std::vector<Measurement<Inputs>> out;
  out.reserve(grid.last / m + 1);
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
  batch.reserve(detail::kBatch);
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    const double seg_end = segment_end(sc, k);
    for (;;) {
      batch.clear();
      for (std::size_t j = i + 1; j <= grid.last && batch.size() < detail::kBatch && grid.at(j) <= seg_end; ++j) {
        batch.push_back(grid.at(j));
      }
      const bool last_batch = batch.size() < detail::kBatch;
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
