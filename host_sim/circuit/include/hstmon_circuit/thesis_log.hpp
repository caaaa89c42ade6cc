#pragma once
/// @file thesis_log.hpp
/// The thesis rig's inputs by the names thesis.json gives them, and the thesis reference
/// simulator's measurements (hstmon_sim/measure.hpp) as a log of a circuit with those
/// inputs and the sensors p_mi, p_mo, p_pp, w_m: what the thesis campaign and tests replay
/// through replay_circuit, and what hstmon-sim's thesis scenarios set on a circuit.

#include "hstmon/thesis_params.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_sim/measure.hpp"

namespace hstmon::circuit_tools {

/// One of the thesis rig's inputs: its name in thesis.json and its field [SI].
struct ThesisInputField {
  const char* name;
  double ThesisInputs<double>::*member;
};

/// The four inputs of ThesisInputs, in thesis.json's order.
inline constexpr ThesisInputField kThesisInputFields[] = {{"Psupl", &ThesisInputs<double>::Psupl},
                                                          {"Ps", &ThesisInputs<double>::Ps},
                                                          {"Pbp", &ThesisInputs<double>::Pbp},
                                                          {"kp", &ThesisInputs<double>::kp}};

/// ms (the logged inputs and the readings, SI) as a log of circuit c, by input and sensor
/// name; c's other inputs and sensors are left out of the log.
/// @throws std::invalid_argument when c lacks one of the thesis rig's inputs or sensors
CircuitLog thesis_circuit_log(const sim::ThesisMeasurements& ms, const host::CircuitFile& c);

}  // namespace hstmon::circuit_tools
