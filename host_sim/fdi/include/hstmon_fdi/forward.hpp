#pragma once
/// @file forward.hpp
/// Hypothesis validation (thesis §2.5.2): forward propagation of a hypothesised fault
/// along the temporal causal graph. A fault is a step in one or more edge parameters
/// (or effort sources) at t = 0+; the propagation gives, for every node, the sign of its
/// deviation and of its time derivatives at 0+ up to a chosen order: a dt edge moves an
/// effect one derivative up. Two variants: purely qualitative (opposite paths meeting give
/// ?), and weighted by the operating-point gains (the Markov parameters of the linearised
/// model). The linearised steady state (−A⁻¹·b) is given alongside.

#include <array>
#include <string>
#include <vector>

#include "hstmon/fault_signature.hpp"
#include "hstmon_fdi/causal_graph.hpp"

namespace hstmon::fdi {

/// One parameter (or source) of a hypothesised fault and its direction.
struct ParamStep {
  std::string param;  ///< edge parameter or source node name
  int sign;           ///< +1 increase, −1 decrease
};

/// Prediction for one measured node.
struct ChannelPrediction {
  std::vector<QualSign> derivative;  ///< sign of the k-th derivative of the deviation at 0+, k = 0…max_order
  int order;                         ///< first k with a non-zero sign; −1 if none up to max_order
  QualSign slope;                    ///< derivative[order] (kQualZero if order < 0)
  QualSign magnitude;                ///< thesis reading: the first effect persists = slope
};

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

/// forward_qualitative for any measured nodes (a circuit's sensor channels), in the given order.
/// @throws std::invalid_argument as forward_qualitative, or for a name that is not a node
std::vector<ChannelPrediction> forward_qualitative_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                      int max_order, const std::vector<std::string>& measured);

/// forward_weighted for any measured nodes, in the given order.
std::vector<ChannelPrediction> forward_weighted_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                   int max_order, const std::vector<std::string>& measured);

/// Nodes with an integrating (dt) in-edge: the states of the linearised model, in node order.
std::vector<int> integrated_nodes(const CausalGraph& g);

/// linear_steady_change for any number of integrated nodes and any measured nodes
/// [measured units per unit ln θ].
/// @throws std::invalid_argument without integrated nodes, for a singular A or an unknown name
std::vector<double> linear_steady_change_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                            const std::vector<std::string>& measured);

/// Renders derivative signs as "0 0 + -" (k = 0…max_order).
std::string render_derivatives(const ChannelPrediction& c);

}  // namespace hstmon::fdi
