#pragma once
/// @file thesis_inputs_as.hpp
/// A log's (double) thesis inputs in the scalar type of the monitor under test.

#include "hstmon/thesis_params.hpp"

namespace hstmon_test {

template <typename T>
hstmon::ThesisInputs<T> thesis_inputs_as(const hstmon::ThesisInputs<double>& d) {
  hstmon::ThesisInputs<T> u;
  u.Psupl = static_cast<T>(d.Psupl);
  u.Ps = static_cast<T>(d.Ps);
  u.Pbp = static_cast<T>(d.Pbp);
  u.kp = static_cast<T>(d.kp);
  return u;
}

}  // namespace hstmon_test
