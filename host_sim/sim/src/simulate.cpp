/// @file simulate.cpp
#include "hstmon_sim/simulate.hpp"

#include <algorithm>
#include <stdexcept>

namespace hstmon::sim {

namespace {

/// Runs any reference (ThesisReference / PaperReference) over a scenario, segment by
/// segment, collecting the samples.
template <class Reference, class Inputs, class Traj>
void run_segments(Reference& ref, const Scenario<Inputs>& sc, const std::vector<double>& times, Traj& out) {
  using State = typename Reference::State;
  out.clear();
  out.reserve(times.size());
  // Samples at t = 0 (the initial state) before any integration.
  auto it = times.begin();
  for (; it != times.end() && *it <= 0.0; ++it) out.push_back({*it, inputs_at(sc, *it), ref.state()});
  for (std::size_t k = 0; k < sc.schedule.size(); ++k) {
    const Inputs& u = sc.schedule[k].u;
    ref.advance_to(segment_end(sc, k), u, times,
                   [&out, &sc](double t, const State& x) { out.push_back({t, inputs_at(sc, t), x}); });
  }
}

}  // namespace

void check_sample_times(const std::vector<double>& times, double duration) {
  if (!std::is_sorted(times.begin(), times.end())) throw std::invalid_argument("sample times must be ascending");
  if (!times.empty() && (times.front() < 0.0 || times.back() > duration)) {
    throw std::invalid_argument("sample times must lie within [0, duration]");
  }
  if (std::adjacent_find(times.begin(), times.end()) != times.end()) {
    throw std::invalid_argument("sample times must be distinct");
  }
}

namespace {

/// A scenario through Reference from initial_state(sc, p), sampled at `times`.
template <class Reference, class Traj, class Scen, class Params, class InitialState>
Traj simulate_on(const Scen& sc, const std::vector<double>& times, const Params& p, InitialState initial_state,
                 const ReferenceTolerances& tol, IntegratorStats* stats) {
  validate(sc);
  check_sample_times(times, sc.duration);
  Reference ref(p, initial_state(sc, p), 0.0, tol);
  Traj out;
  run_segments(ref, sc, times, out);
  if (stats != nullptr) *stats = ref.stats();
  return out;
}

}  // namespace

ThesisTrajectory simulate(const ThesisScenario& sc, const std::vector<double>& times, const ThesisParams<double>& p,
                          const ReferenceTolerances& tol, IntegratorStats* stats) {
  return simulate_on<ThesisReference, ThesisTrajectory>(sc, times, p, thesis_initial_state, tol, stats);
}

PaperTrajectory simulate(const PaperScenario& sc, const std::vector<double>& times, const PaperParams<double>& p,
                         const ReferenceTolerances& tol, IntegratorStats* stats) {
  return simulate_on<PaperReference, PaperTrajectory>(sc, times, p, paper_initial_state, tol, stats);
}

}  // namespace hstmon::sim
