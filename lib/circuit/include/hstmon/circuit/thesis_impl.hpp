#pragma once
/// @file thesis_impl.hpp
/// The choice between the thesis rig's two implementations of its equations, for the host
/// tools that offer it: the engine's (thesis_circuit_model.hpp) and the hand-written
/// specialisation (thesis_reduced.hpp).

namespace hstmon {

/// Which implementation of the thesis rig's equations a host tool runs where it lets the
/// user choose (`hstmon replay --thesis-model`, gap::SimOptions::thesis). The two agree to
/// rounding (test_circuit_thesis, test_circuit_thesis_model, test_replay_thesis_model,
/// test_gap_model); the specialisation is the faster (docs/circuits.md, "The thesis rig on
/// the engine").
enum class ThesisImpl {
  kSpecialised,  ///< the hand-written ThesisReducedModel (thesis_reduced.hpp)
  kEngine,       ///< ThesisCircuitModel: thesis.json compiled
};

}  // namespace hstmon
