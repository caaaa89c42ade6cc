#pragma once
/// @file hstmon.hpp
/// Umbrella header of the hstmon core.
#include "hstmon/observer.hpp"
#include "hstmon/paper_model.hpp"
#include "hstmon/pump_curve.hpp"
#include "hstmon/rk4.hpp"
#include "hstmon/signed_root.hpp"
#include "hstmon/status.hpp"
#include "hstmon/thesis_model.hpp"
#include "hstmon/thesis_params.hpp"
#include "hstmon/thesis_reduced.hpp"
