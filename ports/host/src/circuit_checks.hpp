#pragma once
/// @file circuit_checks.hpp
/// Internal: the checks that make a circuit physical beyond what the reader's grammar
/// and validate() (indices, required fields) see. The readers locate what they return:
/// a wiring problem at its node's or shaft's key, a value problem where the value was
/// written (circuit file or parameter file).

#include <optional>
#include <string>

#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace hstmon::host::detail {

/// A node or state the components leave unconnected.
struct WiringProblem {
  std::string pointer;  ///< JSON pointer of the node's or shaft's key ("/nodes/line")
  std::string message;
};

/// The first node with no component, or state (volume, free shaft) that no boundary,
/// driven shaft or source reaches through the components; nullopt when there is none.
std::optional<WiringProblem> wiring_problem(const CircuitFile& f);

/// A number its law cannot take (a volume ≤ 0, cracking above full open, ...).
struct ValueProblem {
  circuit::Ref ref;     ///< the parameter or input holding it (kNone: no single one)
  std::string message;  ///< names the element, the field and the value with units
};

/// The first value of v that c's laws cannot take; nullopt when the engine can run them.
std::optional<ValueProblem> value_problem(const CircuitFile& c, const CircuitValues& v);

}  // namespace hstmon::host::detail
