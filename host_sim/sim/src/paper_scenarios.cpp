/// @file paper_scenarios.cpp
#include "hstmon_sim/paper_scenarios.hpp"

#include <stdexcept>

namespace hstmon::sim {

PaperScenario paper_start(double duration) {
  PaperScenario sc;
  sc.name = "paper_start";
  sc.description = "paper rig, pump B started from rest, A_dcv = 5e-6 m2, A_prv = 3.525e-6 m2";
  PaperInputs<double> u;
  u.A_dcv = 5e-6;
  u.A_prv = 3.525e-6;
  sc.schedule = {{0.0, u}};
  sc.duration = duration;
  sc.initial = InitialCondition::kRest;
  validate(sc);
  return sc;
}

std::vector<std::string> paper_scenario_names() { return {"paper_start"}; }

std::optional<PaperScenario> paper_scenario(std::string_view name) {
  if (name == "paper_start") return paper_start();
  return std::nullopt;
}

PaperModel<double>::State paper_initial_state(const PaperScenario& sc, const PaperParams<double>& p) {
  validate(sc);
  if (sc.initial != InitialCondition::kRest) {
    throw std::invalid_argument("paper_initial_state: the paper model has no closed-form steady state");
  }
  PaperModel<double> m;
  if (!m.set_params(p)) throw std::invalid_argument("paper_initial_state: invalid parameters");
  return m.rest_state();
}

}  // namespace hstmon::sim
