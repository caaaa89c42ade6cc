#pragma once
/// @file circuit_header.hpp
/// A circuit as a C++ header for firmware (hstmon-circuit-header): the engine's
/// description as a `constexpr circuit::Circuit<Cap>` with a capacity exactly as large as
/// the circuit (the stiff mask for the tick decides the state count), the parameter
/// values, the nominal inputs, the sensors' noise σ and ranges, the parameters'
/// relative uncertainty and every name. Numbers are written with 17 significant digits,
/// so the header's doubles are the loaded ones bit for bit; the firmware rounds them to
/// float exactly as a float host build does.

#include <string>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// What the generated header is called and where its values came from.
struct CircuitHeaderOptions {
  double tick = 1e-3;         ///< observer tick the stiff mask is chosen for [s], > 0
  std::string name;           ///< C++ namespace under hstmon::generated (e.g. "thesis_circuit")
  std::string source_note;    ///< the command line or file names, written into the comment
};

/// The header text for c. Deterministic: the same files and options give the same bytes.
/// @return "" with `error` set when the circuit has no valid description at these values
std::string circuit_header(const LoadedCircuit& c, const CircuitHeaderOptions& o, std::string& error);

}  // namespace hstmon::circuit_tools
