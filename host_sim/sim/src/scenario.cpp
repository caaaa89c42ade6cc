/// @file scenario.cpp
#include "hstmon_sim/scenario.hpp"

#include <cmath>

namespace hstmon::sim {

std::vector<double> uniform_times(double duration, double period) {
  if (!(std::isfinite(period) && period > 0.0 && std::isfinite(duration) && duration >= 0.0)) {
    throw std::invalid_argument("uniform_times: need period > 0 and duration >= 0");
  }
  const double n = std::floor(duration / period * (1.0 + 1e-9) + 1e-9);
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(n) + 1);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(n); ++k) {
    t.push_back(std::fmin(static_cast<double>(k) * period, duration));
  }
  return t;
}

}  // namespace hstmon::sim
