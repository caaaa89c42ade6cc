#pragma once
/// @file model_bound.hpp
/// What a monitor needs of its model beyond the Observer's concept (model_concept.hpp):
/// the model bound — the largest steady-state output change that the parameters'
/// uncertainty can make at the current operating point (residual_evaluator.hpp uses it
/// as the deterministic part of each channel's threshold).
///
/// ModelBound<M> is specialised per model family:
///  - using Uncertainty: the relative uncertainty of each parameter [-];
///  - static Status compute(const M&, const Uncertainty&, T (&m)[M::kOutputs]): the bound
///    per channel [channel unit] at the steady state for the model's inputs; kOk,
///    kInvalidParams (uncertainty out of range) or kNoSteadyState.
/// The thesis rig's is in residual_bounds.hpp, the circuit engine's in
/// circuit/circuit_bound.hpp. Nothing here allocates.

namespace hstmon {

/// Primary template: deliberately undefined, so a model without a bound fails to compile
/// at the point of use with its name in the message.
template <class Model>
struct ModelBound;

}  // namespace hstmon
