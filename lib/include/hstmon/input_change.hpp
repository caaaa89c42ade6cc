#pragma once
/// @file input_change.hpp
/// Whether a model's inputs have moved, relative. The monitor (model_monitor.hpp)
/// recomputes its model bound only once some input has moved more than
/// Config::input_tolerance from its value at the last bound: a logged input that is
/// measured (a test stand's drive speed, a supply pressure) differs on every row by its
/// noise, and an exact comparison made every tick an input change, a bound of about 20
/// steady solves per tick.
///
/// An Inputs type offers `friend bool inputs_within(const Inputs& a, const Inputs& b, T
/// tol)`, which inputs_close finds by ADL: ThesisInputs, the circuit engine's Inputs. For
/// one without, every change counts. Multiplications and comparisons only (firmware
/// flash and stack): a NaN is never within.

#include <type_traits>
#include <utility>

namespace hstmon {

namespace input_change_detail {
template <class I, typename T, typename = void>
struct HasWithin : std::false_type {};
template <class I, typename T>
struct HasWithin<I, T,
                 std::void_t<decltype(inputs_within(std::declval<const I&>(), std::declval<const I&>(), T(0)))>>
    : std::true_type {};
}  // namespace input_change_detail

/// True when every input of b lies within tol [-] of a's, relative to a's (the type's
/// inputs_within); tol = 0, or a type without inputs_within: a == b.
template <typename T, class Inputs>
bool inputs_close(const Inputs& a, const Inputs& b, T tol) noexcept {
  if constexpr (input_change_detail::HasWithin<Inputs, T>::value) {
    return inputs_within(a, b, tol);
  } else {
    (void)tol;
    return a == b;
  }
}

}  // namespace hstmon
