#pragma once
/// @file engine.hpp
/// The circuit engine in one include: description, laws, model, stiff-node choice.

#include "hstmon/circuit/capacity.hpp"
#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/circuit/laws.hpp"
#include "hstmon/circuit/stiffness.hpp"
#include "hstmon/circuit/validate.hpp"
