#pragma once
/// @file thesis_forward.hpp
/// Forward propagation to the thesis graph's four measurement nodes (ThesisChannel order):
/// the hand-written graph's reading of forward.hpp, for the test oracle.

#include <array>
#include <vector>

#include "hstmon_fdi/forward.hpp"

namespace hstmon::fdi {

/// Forward propagation result for the four measurement nodes (ThesisChannel order).
struct ForwardResult {
  std::array<ChannelPrediction, 4> channel;
};

/// Qualitative forward propagation (signs only; parameter influence signs of the edges).
/// @param max_order  highest derivative predicted, ≥ 0
/// @throws std::invalid_argument for an unknown parameter, a derivative edge, or an algebraic loop
ForwardResult forward_qualitative(const CausalGraph& g, const std::vector<ParamStep>& fault, int max_order);

/// Forward propagation weighted by the edges' gains and injections at the operating point:
/// the signs of the linearised model's derivatives at 0+ for a unit relative step.
/// A contribution within 1e-9 of the sum of absolute contributions counts as zero.
ForwardResult forward_weighted(const CausalGraph& g, const std::vector<ParamStep>& fault, int max_order);

/// Steady-state change of the four measurements in the linearised model for a unit
/// relative step (x_ss = −A⁻¹·b over the dt-edge targets) [Pa or rad/s per unit ln θ].
/// @throws std::invalid_argument if the graph does not have exactly 4 integrated nodes
///         or A is singular
std::array<double, 4> linear_steady_change(const CausalGraph& g, const std::vector<ParamStep>& fault);

}  // namespace hstmon::fdi
