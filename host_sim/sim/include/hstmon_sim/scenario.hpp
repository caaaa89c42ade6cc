#pragma once
/// @file scenario.hpp
/// A simulation scenario: a piecewise-constant input schedule, a duration and an initial
/// condition. Inputs are right-continuous: at a change time the new inputs apply.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace hstmon::sim {

/// How a scenario's initial state is obtained.
enum class InitialCondition {
  kRest,    ///< machine at rest (model-specific rest state), supply applied at t = 0
  kSteady,  ///< steady state under the inputs at t = 0
};

/// One entry of an input schedule: inputs u apply from t_start [s] until the next entry.
template <class Inputs>
struct InputStep {
  double t_start = 0.0;  ///< time the inputs take effect [s]
  Inputs u{};            ///< inputs held from t_start on
};

/// Scenario over inputs of type Inputs (ThesisInputs<double> or PaperInputs<double>).
template <class Inputs>
struct Scenario {
  std::string name;                          ///< identifier, e.g. "prv_blockage"
  std::string description;                   ///< one line for --list and logs
  std::vector<InputStep<Inputs>> schedule;   ///< strictly increasing t_start, first at 0
  double duration = 0.0;                     ///< end time [s]; the run covers [0, duration]
  InitialCondition initial = InitialCondition::kRest;  ///< initial state at t = 0
  /// Inputs as the rig's logger records them (the operator's settings). Empty: the true
  /// schedule. A fault such as the PRV blockage changes the true inputs but not the
  /// recorded ones, so a replay has to find it from the measurements alone.
  std::vector<InputStep<Inputs>> logged;
};

/// The inputs a log records at time t: `logged` if the scenario has it, else the truth.
template <class Inputs>
const Inputs& logged_inputs_at(const Scenario<Inputs>& sc, double t) {
  const auto& steps = sc.logged.empty() ? sc.schedule : sc.logged;
  std::size_t k = 0;
  while (k + 1 < steps.size() && steps[k + 1].t_start <= t) ++k;
  return steps.at(k).u;
}

/// Throws std::invalid_argument unless the schedule is non-empty, starts at 0, has strictly
/// increasing times within [0, duration) and the duration is finite and positive.
template <class Inputs>
void validate(const Scenario<Inputs>& sc) {
  if (!(std::isfinite(sc.duration) && sc.duration > 0.0)) {
    throw std::invalid_argument("scenario " + sc.name + ": duration must be > 0");
  }
  if (sc.schedule.empty() || sc.schedule.front().t_start != 0.0) {
    throw std::invalid_argument("scenario " + sc.name + ": schedule must start at t = 0");
  }
  for (std::size_t i = 1; i < sc.schedule.size(); ++i) {
    if (!(sc.schedule[i].t_start > sc.schedule[i - 1].t_start && sc.schedule[i].t_start < sc.duration)) {
      throw std::invalid_argument("scenario " + sc.name + ": schedule times must increase within the duration");
    }
  }
}

/// Inputs in force at time t [s] (right-continuous; before 0 the first entry).
template <class Inputs>
const Inputs& inputs_at(const Scenario<Inputs>& sc, double t) {
  std::size_t k = 0;
  while (k + 1 < sc.schedule.size() && sc.schedule[k + 1].t_start <= t) ++k;
  return sc.schedule.at(k).u;
}

/// End time of schedule entry k [s]: the next entry's start, or the duration.
template <class Inputs>
double segment_end(const Scenario<Inputs>& sc, std::size_t k) {
  return (k + 1 < sc.schedule.size()) ? sc.schedule[k + 1].t_start : sc.duration;
}

/// Uniform sample times k·period [s], k = 0, 1, …, for all k·period ≤ duration (with a
/// relative slack of 1e-9 so that a duration that is a multiple of period is included).
/// @throws std::invalid_argument unless period > 0 and duration ≥ 0 are finite
std::vector<double> uniform_times(double duration, double period);

}  // namespace hstmon::sim
