#pragma once
/// @file capacity.hpp
/// Compile-time capacities of a circuit: how many nodes, shafts, elements, sensor
/// channels, inputs and parameters a description may hold, and how many states the model
/// built from it may integrate. Everything the engine stores is sized by these, so a
/// build's RAM is known at compile time and nothing is allocated.

#include <cstddef>

namespace hstmon::circuit {

/// A capacity as an array extent (the capacities are ints; extents are std::size_t).
template <int N>
inline constexpr std::size_t kExtent = static_cast<std::size_t>(N);

/// Capacities of one circuit build.
/// @tparam Nodes     pressure nodes, boundaries included (≤ 32: the stiff set is a 32-bit mask)
/// @tparam Shafts    shafts, driven ones included
/// @tparam Elements  flow and torque elements after lowering (a directional valve is four)
/// @tparam Channels  sensor channels, the model's outputs (≤ 8: the observer's masks are 8 bits)
/// @tparam Inputs    named inputs; even, so the observer can compare them a 64-bit word at a time
/// @tparam Params    named and literal parameters (≤ 255: referenced by 8-bit index)
/// @tparam States    states the model integrates: volume nodes not taken quasi-steady + free shafts
/// @tparam Unknowns  volume nodes + free shafts (states and quasi-steady nodes): sizes the
///                   Jacobian and steady-state scratch, so a tight value keeps them off the
///                   boundaries' rows (firmware stack)
template <int Nodes, int Shafts, int Elements, int Channels, int Inputs, int Params, int States = Nodes + Shafts,
          int Unknowns = Nodes + Shafts>
struct Capacity {
  static constexpr int kNodes = Nodes;
  static constexpr int kShafts = Shafts;
  static constexpr int kElements = Elements;
  static constexpr int kChannels = Channels;
  static constexpr int kInputs = Inputs;
  static constexpr int kParams = Params;
  static constexpr int kStates = States;
  static constexpr int kUnknowns = Unknowns;
  static_assert(Nodes >= 1 && Nodes <= 32, "the stiff-node set is a 32-bit mask");
  static_assert(Shafts >= 0 && Elements >= 1 && Elements <= 255, "elements are referenced by 8-bit index");
  static_assert(Channels >= 1 && Channels <= 8, "the observer's channel masks are 8 bits wide");
  static_assert(Inputs >= 2 && Inputs % 2 == 0 && Inputs <= 254, "inputs: even (word-wise compare), 8-bit index");
  static_assert(Params >= 1 && Params <= 255, "parameters are referenced by 8-bit index");
  static_assert(States >= 1 && States <= Nodes + Shafts, "states: at most one per node and shaft");
  static_assert(Unknowns >= States && Unknowns <= Nodes + Shafts, "unknowns: the states and the stiff nodes");
};

/// What the host tools build with: room for the shipped circuits and a user's machine of
/// a dozen volumes and half a dozen shafts.
using HostCapacity = Capacity<12, 6, 40, 8, 16, 96, 16>;

}  // namespace hstmon::circuit
