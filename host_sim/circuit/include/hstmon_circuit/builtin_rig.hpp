#pragma once
/// @file builtin_rig.hpp
/// The thesis rig (seed 000) built into the host tools: examples/circuits/thesis.json, with
/// Table 2.2 as its values, as text compiled into the program, so that a command given no
/// --circuit runs on it wherever the program is installed.
/// circuit_tools::load_circuit loads it for an empty circuit path.

#include <string_view>

namespace hstmon::circuit_tools {

/// Name under which the built-in circuit appears in messages ("thesis.json (built in)").
inline constexpr std::string_view kBuiltinCircuitName = "thesis.json (built in)";

/// The text of examples/circuits/thesis.json.
std::string_view builtin_thesis_circuit() noexcept;

}  // namespace hstmon::circuit_tools
