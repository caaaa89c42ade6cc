#pragma once
/// @file forward.hpp
/// Hypothesis validation (thesis §2.5.2): forward propagation of a hypothesised fault
/// along the temporal causal graph. A fault is a step in one or more edge parameters
/// (or effort sources) at t = 0+; the propagation gives, for every node, the sign of its
/// deviation and of its time derivatives at 0+ up to a chosen order: a dt edge moves an
/// effect one derivative up. Two variants: purely qualitative (opposite paths meeting give
/// ?), and weighted by the operating-point gains (the Markov parameters of the linearised
/// model). The linearised steady state (−A⁻¹·b) is given alongside.

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

/// Qualitative forward propagation (signs only; parameter influence signs of the edges) to
/// the measured nodes (a circuit's sensor channels), in the given order.
/// @param max_order  highest derivative predicted, ≥ 0
/// @throws std::invalid_argument for an unknown parameter or node, a derivative edge, or an algebraic loop
std::vector<ChannelPrediction> forward_qualitative_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                      int max_order, const std::vector<std::string>& measured);

/// Forward propagation weighted by the edges' gains and injections at the operating point:
/// the signs of the linearised model's derivatives at 0+ for a unit relative step, at the
/// measured nodes in the given order. A contribution within 1e-9 of the sum of absolute
/// contributions counts as zero.
std::vector<ChannelPrediction> forward_weighted_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                                   int max_order, const std::vector<std::string>& measured);

/// Nodes with an integrating (dt) in-edge: the states of the linearised model, in node order.
std::vector<int> integrated_nodes(const CausalGraph& g);

/// Steady-state change of the measured nodes in the linearised model for a unit relative
/// step (x_ss = −A⁻¹·b over the dt-edge targets) [measured units per unit ln θ].
/// @throws std::invalid_argument without integrated nodes, for a singular A or an unknown name
std::vector<double> linear_steady_change_at(const CausalGraph& g, const std::vector<ParamStep>& fault,
                                            const std::vector<std::string>& measured);

/// Renders derivative signs as "0 0 + -" (k = 0…max_order).
std::string render_derivatives(const ChannelPrediction& c);

}  // namespace hstmon::fdi
