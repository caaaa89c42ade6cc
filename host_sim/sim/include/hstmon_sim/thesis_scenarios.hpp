#pragma once
/// @file thesis_scenarios.hpp
/// Scenarios of the thesis rig (seed 000) and their initial states. All use Table 2.2
/// inputs (Psupl = 35 bar, Ps = 0, Pbp = 10 bar) except where kp is varied.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_sim/scenario.hpp"

namespace hstmon::sim {

/// A scenario of the thesis model.
using ThesisScenario = Scenario<ThesisInputs<double>>;

/// kp of Table 2.2 [m³/(s·√Pa)].
inline constexpr double kThesisKpNominal = 4.41e-8;

/// PRV settings of prv_staircase, as multiples of kThesisKpNominal (open → restricted).
inline constexpr double kStaircaseFactors[] = {1.6, 1.3, 1.0, 0.8, 0.65, 0.5};

/// Start from rest: all pressures at tank (Pmi = Pmo = Ps), Ppp = Pbp, ωm = 0, Table 2.2
/// inputs applied at t = 0, run for `duration` [s] (default 2 s; the state is steady to
/// rounding well before 1 s).
ThesisScenario thesis_start_from_rest(double duration = 2.0);

/// PRV staircase: steady at kp = 1.6·kp0, then kp steps through kStaircaseFactors, each
/// held `hold` [s] (default 2 s; the slowest mode, −153 ± 307i 1/s at kp0/2, settles in
/// well under 0.1 s). Duration = 6·hold.
ThesisScenario thesis_prv_staircase(double hold = 2.0);

/// The thesis's blockage experiment (§2.4, Fig. 2.13): steady at Table 2.2, kp halved
/// (50 % PRV blockage) at t = 80 s, run to 120 s.
ThesisScenario thesis_prv_blockage();

/// Names of the thesis scenarios, in a stable order.
std::vector<std::string> thesis_scenario_names();

/// Scenario by name. For prv_staircase the hold is max(2 s, 10·sample_period) so that a
/// slow logger (thesis DAS: 4 s) still records 10 samples per PRV setting.
/// @param sample_period  sampling period the run will use [s]
/// @return               std::nullopt for an unknown name
std::optional<ThesisScenario> thesis_scenario(std::string_view name, double sample_period = 1e-3);

/// Rest state for inputs u: Pmi = Pmo = Ps, Ppp = Pbp, ωm = 0.
ThesisState<double> thesis_rest_state(const ThesisInputs<double>& u);

/// Steady state of the full model for inputs u, from ThesisCircuitModel::steady_state
/// (Ppp, ωm) and its outputs (Pmi, Pmo).
/// @throws std::invalid_argument if the inputs admit no steady state (e.g. kp = 0)
ThesisState<double> thesis_steady_state(const ThesisInputs<double>& u,
                                        const ThesisParams<double>& p = ThesisParams<double>{});

/// Initial state of scenario sc under parameters p.
ThesisState<double> thesis_initial_state(const ThesisScenario& sc,
                                         const ThesisParams<double>& p = ThesisParams<double>{});

}  // namespace hstmon::sim
