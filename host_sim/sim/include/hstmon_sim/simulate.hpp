#pragma once
/// @file simulate.hpp
/// One-call reference runs of a scenario: the true (noise-free, lag-free) trajectory at
/// given sample times.

#include <vector>

#include "hstmon_sim/paper_reference.hpp"
#include "hstmon_sim/paper_scenarios.hpp"
#include "hstmon_sim/stiff_integrator.hpp"
#include "hstmon_sim/thesis_reference.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim {

/// One point of a reference trajectory.
template <class Inputs, class State>
struct TrajectoryPoint {
  double t = 0.0;  ///< time [s]
  Inputs u{};      ///< inputs in force at t (right-continuous schedule)
  State x{};       ///< true state at t (SI: Pa, rad/s)
};

/// Trajectory of the thesis model.
using ThesisTrajectory = std::vector<TrajectoryPoint<ThesisInputs<double>, ThesisState<double>>>;
/// Trajectory of the paper model (state Ps, Pmi, Ppp [Pa], ωm [rad/s]).
using PaperTrajectory = std::vector<TrajectoryPoint<PaperInputs<double>, PaperModel<double>::State>>;

/// Integrates scenario sc with the full thesis model from its initial state, restarting at
/// every input change, and returns the state at each of `times`.
/// @param times  ascending sample times within [0, sc.duration] [s]
/// @param p      parameters (Table 2.2 by default)
/// @param tol    integration tolerances
/// @param stats  optional out: integrator statistics of the run
/// @throws std::invalid_argument on unsorted or out-of-range times or an invalid scenario
ThesisTrajectory simulate(const ThesisScenario& sc, const std::vector<double>& times,
                          const ThesisParams<double>& p = ThesisParams<double>{},
                          const ReferenceTolerances& tol = ReferenceTolerances{},
                          IntegratorStats* stats = nullptr);

/// As above for the paper model.
PaperTrajectory simulate(const PaperScenario& sc, const std::vector<double>& times,
                         const PaperParams<double>& p = PaperParams<double>{},
                         const ReferenceTolerances& tol = ReferenceTolerances{},
                         IntegratorStats* stats = nullptr);

/// Throws std::invalid_argument unless times are ascending and within [0, duration].
void check_sample_times(const std::vector<double>& times, double duration);

}  // namespace hstmon::sim
