#pragma once
/// @file rig_run.hpp
/// A run of the thesis rig as it happens on a real one: the logger may start before the
/// supply is switched on (machine at rest, first sample ≈ 0 bar), the supply may be
/// switched off and on again (start/stop cycles), and the load (PRV setting) follows a
/// LoadProfile. Each condition is a separate field, so each can be switched alone.
/// Supply off means Psupl = Ps (the pump's line at tank pressure); the logged p_sup
/// column shows it, as a logger recording the supply pressure would.

#include "hstmon_sim/load_profile.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"

namespace hstmon::sim {

/// Conditions of one run.
struct RigRun {
  double duration = 30.0;     ///< [s]
  bool from_rest = true;      ///< machine at rest at t = 0 (else steady, supply on)
  double supply_on = 0.0;     ///< from rest: time the supply steps on [s] (0: at the first sample)
  double run_time = 0.0;      ///< > 0: start/stop cycles, supply on for run_time [s] …
  double stop_time = 0.0;     ///< … then off for stop_time [s], repeated
  LoadProfile load;           ///< PRV setting, factors of inputs.kp
  ThesisInputs<double> inputs{};  ///< Psupl while on, Ps, Pbp, and kp0 (Table 2.2)
};

/// The scenario of run r ("rig"): schedule of supply and load changes merged, initial
/// condition kRest or kSteady.
/// @throws std::invalid_argument on negative times, a steady start with a delayed supply,
///         or an invalid load profile
ThesisScenario thesis_rig_run(const RigRun& r);

}  // namespace hstmon::sim
