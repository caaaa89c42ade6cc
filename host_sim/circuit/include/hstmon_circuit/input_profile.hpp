#pragma once
/// @file input_profile.hpp
/// Inputs that follow a logged run (hstmon-sim --inputs): each logged input column is a
/// sampled signal, its value between two rows either
///  - linear (the default): the straight line between the rows' values. A logged input is
///    a sample of a continuous signal (a throttle, a swash plate, a speed, a load torque):
///    a ramp is re-simulated as the ramp it was, where holding each row would lag it by
///    half a row on average; a step that fell between two rows is spread over that one
///    row interval, never more;
///  - step (zero-order hold): each row's value held until the next row, as the monitor
///    applies a row's inputs over its tick.
/// Before the first row an input has the first row's value, after the last the last's.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace hstmon::circuit_tools {

/// How a logged input goes from one row to the next.
enum class InputHold { kLinear, kStep };

/// "linear" | "step", or nothing.
std::optional<InputHold> input_hold_from(std::string_view name);
/// "linear" | "step".
const char* input_hold_name(InputHold h) noexcept;

/// Logged inputs over time, SI.
struct InputProfile {
  std::vector<double> t;                     ///< row times [s], strictly rising
  std::vector<std::vector<double>> inputs;   ///< by input index, t.size() values; empty: not logged
  InputHold hold = InputHold::kLinear;

  /// True when input i follows the profile.
  bool drives(std::size_t i) const noexcept {
    return i < inputs.size() && !inputs[i].empty() && inputs[i].size() == t.size();
  }
  /// True when some input follows it.
  bool any() const noexcept;
  /// The row segment holding time `at`: the last row k with t[k] <= at (0 before the first row).
  std::size_t segment(double at) const noexcept;
  /// Input i (drives(i)) at time `at` in segment k (= segment(at)).
  double value(std::size_t i, double at, std::size_t k) const noexcept;
  /// Its rate of change [SI/s] in segment k: 0 for a step profile, before the first row and
  /// after the last.
  double slope(std::size_t i, std::size_t k) const noexcept;
};

}  // namespace hstmon::circuit_tools
