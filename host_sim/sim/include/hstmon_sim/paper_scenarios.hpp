#pragma once
/// @file paper_scenarios.hpp
/// Scenarios of the paper rig (seed 001). The paper model has no closed-form steady state,
/// so its scenarios start from rest (all pressures at tank, shaft still).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon/paper_model.hpp"
#include "hstmon_sim/scenario.hpp"

namespace hstmon::sim {

/// A scenario of the paper model.
using PaperScenario = Scenario<PaperInputs<double>>;

/// Pump B started from rest with A_dcv = 5e-6 m² (§5.4, Fig. 10) and A_prv = 3.525e-6 m²
/// (§4.3, A1), run for `duration` [s] (default 5 s: ωm rises to ≈ 2266 rpm by 2.6 s and is
/// within 0.01 % of its final ≈ 2249 rpm by 5 s).
PaperScenario paper_start(double duration = 5.0);

/// Names of the paper scenarios.
std::vector<std::string> paper_scenario_names();

/// Scenario by name; std::nullopt for an unknown name.
std::optional<PaperScenario> paper_scenario(std::string_view name);

/// Initial state of a paper scenario: PaperModel::rest_state() (kSteady is refused).
/// @throws std::invalid_argument for InitialCondition::kSteady or invalid parameters
PaperModel<double>::State paper_initial_state(const PaperScenario& sc,
                                              const PaperParams<double>& p = PaperParams<double>{});

}  // namespace hstmon::sim
