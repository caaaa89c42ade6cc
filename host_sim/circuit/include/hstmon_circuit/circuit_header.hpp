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

/// The description the header holds: the file's, with the stiff mask
/// circuit::auto_stiff_mask<double> picks at the tick (states: how many states that leaves).
host::HostCircuit header_description(const LoadedCircuit& c, double tick, int* states = nullptr);

/// A range of observer ticks [s].
struct TickRange {
  double lo = 0.0, hi = 0.0;
};

/// The ticks around `tick` at which header_description() picks the same stiff mask as at
/// `tick` (and so the same header): scanned in quarter octaves, out to 2^±10 × tick.
TickRange same_mask_ticks(const LoadedCircuit& c, double tick);

/// The compiled model's header (`hstmon-circuit-header --compiled`): for the circuit of
/// circuit_header() with the same options, a Kernel of straight-line code — the stiff
/// nodes' balances and their Gauss–Seidel × Newton solve, the states' rates, the outputs
/// and the unknowns' Jacobian — and `CompiledModel<T>` = circuit::CompiledModel<T, Kernel>
/// (lib/circuit compiled_model.hpp), added to the namespace hstmon::generated::<name> of
/// the header <name>.hpp, which it includes. Deterministic.
/// @return "" with `error` set when the circuit has no valid description at these values
std::string circuit_compiled_header(const LoadedCircuit& c, const CircuitHeaderOptions& o, std::string& error);

}  // namespace hstmon::circuit_tools
