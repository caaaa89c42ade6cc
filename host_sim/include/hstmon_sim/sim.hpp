#pragma once
/// @file sim.hpp
/// Umbrella header of the host reference simulator (namespace hstmon::sim).
#include "hstmon_sim/gaussian.hpp"
#include "hstmon_sim/log_layout.hpp"
#include "hstmon_sim/measure.hpp"
#include "hstmon_sim/paper_jacobian.hpp"
#include "hstmon_sim/paper_reference.hpp"
#include "hstmon_sim/paper_scenarios.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/scenario.hpp"
#include "hstmon_sim/sensor_chain.hpp"
#include "hstmon_sim/sensor_presets.hpp"
#include "hstmon_sim/simulate.hpp"
#include "hstmon_sim/stiff_integrator.hpp"
#include "hstmon_sim/thesis_reference.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"
