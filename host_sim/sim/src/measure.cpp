/// @file measure.cpp
#include "hstmon_sim/measure.hpp"

#include <cmath>
#include <stdexcept>

#include "hstmon_sim/paper_reference.hpp"
#include "fine_sampling.hpp"
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
  double x[4];
  state_to_array(ref.state(), x);
  detail::FineSampling<Inputs> sampling(cfg, seed, sc, grid, x);
  auto on_sample = [&sampling](double t, const State& xs) {
    double v[4];
    state_to_array(xs, v);
    sampling.feed(t, v);
  };
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    sampling.through(segment_end(sc, k), [&](double t_end, const std::vector<double>& points) {
      ref.advance_to(t_end, sc.schedule[k].u, points, on_sample);
    });
  }
  return sampling.take();
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
