#include "hstmon_circuit/input_profile.hpp"

#include <algorithm>

namespace hstmon::circuit_tools {

std::optional<InputHold> input_hold_from(std::string_view name) {
  if (name == "linear") return InputHold::kLinear;
  if (name == "step") return InputHold::kStep;
  return std::nullopt;
}

const char* input_hold_name(InputHold h) noexcept { return h == InputHold::kLinear ? "linear" : "step"; }

bool InputProfile::any() const noexcept {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (drives(i)) return true;
  }
  return false;
}

std::size_t InputProfile::segment(double at) const noexcept {
  const auto it = std::upper_bound(t.begin(), t.end(), at);
  return it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1;
}

double InputProfile::slope(std::size_t i, std::size_t k) const noexcept {
  if (hold == InputHold::kStep || k + 1 >= t.size()) return 0.0;
  return (inputs[i][k + 1] - inputs[i][k]) / (t[k + 1] - t[k]);
}

double InputProfile::value(std::size_t i, double at, std::size_t k) const noexcept {
  const std::vector<double>& v = inputs[i];
  if (at <= t.front()) return v.front();
  if (k + 1 >= t.size()) return v.back();
  if (hold == InputHold::kStep) return v[k];
  return v[k] + (at - t[k]) * slope(i, k);
}

}  // namespace hstmon::circuit_tools
