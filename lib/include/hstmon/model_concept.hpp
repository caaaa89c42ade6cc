#pragma once
/// @file model_concept.hpp
/// What the Observer needs of a model, written as code (C++17 detection idiom): one
/// static_assert in Observer names the first missing piece instead of a page of template
/// errors. ThesisReducedModel, PaperModel and the circuit engine satisfy it;
/// tests/core/tiny_model.hpp is the smallest model that does.
///
/// A model M, with T = M::Scalar, provides:
///  - types Scalar, State, Output (Eigen fixed-size column vectors), Inputs; constants
///    kStates, kOutputs (≤ 8: channel masks are 8 bits);
///  - static bool inputs_valid(const Inputs&), void set_inputs(const Inputs&),
///    const Inputs& inputs();
///  - Output outputs(const State&) [output units];
///  - State rest_state(), bool steady_state(State&) (false: none for the inputs),
///    bool state_plausible(const State&) (false for any non-finite state);
///  - int state_channel(int i): output channel that measures state i, or −1
///    (initial_state.hpp), static or not;
///  - State derivative(const State&) [state units per s] (the RK4 stages, rk4.hpp);
///  - State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok):
///    derivative(x) with y = outputs(x), rho = spectral radius of ∂f/∂x [1/s] (or 0 when
///    it is ≤ rho_max), alg_ok = the model's algebraic solve contracts at x.
/// It may also provide (model_detail::HasStateCount, HasStateEnvelope):
///  - int n_states(): the states in use, when its State is padded to a larger capacity
///    (the circuit interpreter), and static constexpr int kUsedStates where that count is
///    known at compile time (a compiled circuit; HasUsedStates);
///  - State state_envelope(): each state's largest plausible magnitude [state units];
///  - static constexpr bool kPressureThresholds: false when no element's conductance steps
///    at a pressure (no valve can open within a step, so the observer's stage check is
///    off); true when not declared.
/// Nothing here allocates or runs code: it is checked at compile time only.

#include <type_traits>
#include <utility>

namespace hstmon {

namespace model_detail {

template <typename M>
using scalar_t = typename M::Scalar;
template <typename M>
using state_t = typename M::State;
template <typename M>
using output_t = typename M::Output;
template <typename M>
using inputs_t = typename M::Inputs;

template <typename M, typename = void>
struct HasTypes : std::false_type {};
template <typename M>
struct HasTypes<M, std::void_t<scalar_t<M>, state_t<M>, output_t<M>, inputs_t<M>, decltype(M::kStates),
                               decltype(M::kOutputs)>> : std::true_type {};

template <typename M, typename = void>
struct HasInputs : std::false_type {};
template <typename M>
struct HasInputs<M, std::void_t<decltype(bool{M::inputs_valid(std::declval<const inputs_t<M>&>())}),
                                decltype(std::declval<M&>().set_inputs(std::declval<const inputs_t<M>&>())),
                                decltype(std::declval<const M&>().inputs())>> : std::true_type {};

template <typename M, typename = void>
struct HasStates : std::false_type {};
template <typename M>
struct HasStates<
    M, std::void_t<decltype(output_t<M>{std::declval<const M&>().outputs(std::declval<const state_t<M>&>())}),
                   decltype(state_t<M>{std::declval<const M&>().rest_state()}),
                   decltype(bool{std::declval<const M&>().steady_state(std::declval<state_t<M>&>())}),
                   decltype(bool{std::declval<const M&>().state_plausible(std::declval<const state_t<M>&>())}),
                   decltype(int{std::declval<const M&>().state_channel(0)})>> : std::true_type {};

template <typename M, typename = void>
struct HasDerivatives : std::false_type {};
template <typename M>
struct HasDerivatives<
    M, std::void_t<decltype(state_t<M>{std::declval<const M&>().derivative(std::declval<const state_t<M>&>())}),
                   decltype(state_t<M>{std::declval<const M&>().tick_derivative(
                       std::declval<const state_t<M>&>(), std::declval<scalar_t<M>>(), std::declval<output_t<M>&>(),
                       std::declval<scalar_t<M>&>(), std::declval<bool&>())})>> : std::true_type {};

/// True when M offers `int n_states() const` (optional; see the file comment).
template <typename M, typename = void>
struct HasStateCount : std::false_type {};
template <typename M>
struct HasStateCount<M, std::void_t<decltype(std::declval<const M&>().n_states())>> : std::true_type {};

/// True when M states its states in use at compile time (static constexpr int
/// kUsedStates: a compiled circuit, whose State may still be padded to a capacity).
template <typename M, typename = void>
struct HasUsedStates : std::false_type {};
template <typename M>
struct HasUsedStates<M, std::void_t<decltype(M::kUsedStates)>> : std::true_type {};

/// True when M offers `State state_envelope() const` (optional; see the file comment).
template <typename M, typename = void>
struct HasStateEnvelope : std::false_type {};
template <typename M>
struct HasStateEnvelope<M, std::void_t<decltype(std::declval<const M&>().state_envelope())>> : std::true_type {};

/// M::kPressureThresholds where M declares it, else true (optional; see the file comment).
template <typename M, typename = void>
struct PressureThresholds : std::true_type {};
template <typename M>
struct PressureThresholds<M, std::void_t<decltype(M::kPressureThresholds)>>
    : std::integral_constant<bool, M::kPressureThresholds> {};

}  // namespace model_detail

/// The model parts in four groups, so a failed check says which group is missing.
template <typename M>
struct ObserverModelParts {
  static constexpr bool kTypes = model_detail::HasTypes<M>::value;             ///< Scalar, State, Output, Inputs, kStates, kOutputs
  static constexpr bool kInputs = kTypes && model_detail::HasInputs<M>::value;  ///< inputs_valid, set_inputs, inputs
  static constexpr bool kStates = kTypes && model_detail::HasStates<M>::value;  ///< outputs, rest/steady state, plausibility, state_channel
  static constexpr bool kDerivatives = kTypes && model_detail::HasDerivatives<M>::value;  ///< derivative, tick_derivative
};

/// True when M is a model the Observer can run (see the file comment).
template <typename M>
inline constexpr bool is_observer_model_v = ObserverModelParts<M>::kTypes && ObserverModelParts<M>::kInputs &&
                                            ObserverModelParts<M>::kStates && ObserverModelParts<M>::kDerivatives;

}  // namespace hstmon
