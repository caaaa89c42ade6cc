#pragma once
/// @file fault_words.hpp
/// A circuit's faults and sensors in the words an engineer uses, derived from the circuit
/// file's elements, nodes and shafts (never from one circuit's names):
///  - a fault row `<name><+|->` is what the change does to the elements, nodes or shafts
///    that read `name`: a laminar resistance or an orifice coefficient that lets more flow
///    through is a leak, less flow a restriction; a machine's displacement, fraction or
///    driven speed that moves less flow is a pump's delivery loss (a machine on a driven
///    shaft) or a motor's displacement loss (on a free shaft); a poppet's cracking or
///    full-open pressure set lower is a valve opening early; a load torque, a friction, a
///    held (boundary) pressure up or down. A `sensor_<channel>` row is a fault of that sensor.
///  - a set of faults shares a class description when their effects agree: all leaks
///    touching one volume node ("a leak from line B"), all delivery losses of one pump
///    ("a delivery loss at pump"), leaks and delivery losses draining one node alike ("a
///    flow loss from line A (a leak or a delivery loss)"); otherwise the distinct effects
///    are listed ("a leak from line A or a fault of sensor p_a").
///  - an added channel of the sensor placement (circuit_isolability.hpp: "p(X)", "w(S)",
///    "q(E)") is a pressure sensor at a node, a speed sensor on a shaft, a flow meter on an
///    element.

#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// What a fault does to the circuit (see the file comment).
enum class FaultEffect {
  kLeak,              ///< more flow through a leakage path, orifice or valve
  kRestriction,       ///< less flow through it
  kDeliveryLoss,      ///< a pump (or flow source) delivers less
  kDeliveryGain,      ///< a pump (or flow source) delivers more
  kDisplacementLoss,  ///< a motor takes less volume per turn (runs faster per unit flow)
  kDisplacementGain,  ///< a motor takes more volume per turn
  kOpensEarly,        ///< a valve's cracking or full-open pressure set lower
  kOpensLate,         ///< set higher
  kSettingLow,        ///< a pump compensator setting lower
  kSettingHigh,       ///< higher
  kMoreTorque,        ///< more load torque or friction on a shaft
  kLessTorque,        ///< less
  kPressureLow,       ///< a held (boundary) pressure lower
  kPressureHigh,      ///< higher
  kSensor,            ///< a sensor reads wrong
  kOther,             ///< none of the above (a parameter the words do not cover)
};

/// One fault in words.
struct FaultMeaning {
  std::string fault;              ///< the row name, e.g. "R_ext_b-"
  FaultEffect effect = FaultEffect::kOther;
  std::vector<int> elements;      ///< elements it acts on (indices into the circuit file's)
  std::vector<int> nodes;         ///< volume nodes whose flow balance it changes (indices)
  int shaft = -1;                 ///< the shaft it acts on, or −1
  std::string words;              ///< "a leak from line B to tank", "a fault of sensor p_a"
};

/// The meaning of fault row `fault` of c (see the file comment); effect kOther and the row
/// name as its words when the name is no parameter, input or sensor of c.
FaultMeaning fault_meaning(const LoadedCircuit& c, const std::string& fault);

/// A description of what every fault of `faults` shares, e.g. "a leak from line A", or
/// the distinct effects joined by "or" when they share none; "" for an empty list.
std::string class_words(const LoadedCircuit& c, const std::vector<std::string>& faults);

/// An added channel of the sensor placement ("p(X)", "w(S)", "q(E)") in words: "a pressure
/// sensor at node X", "a speed sensor on shaft S", "a flow meter on E"; other names as given.
std::string added_sensor_words(const std::string& channel);

}  // namespace hstmon::circuit_tools
