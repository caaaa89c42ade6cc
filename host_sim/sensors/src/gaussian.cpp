/// @file gaussian.cpp
#include "hstmon_sensors/gaussian.hpp"

#include <cmath>

namespace hstmon::sim {

double GaussianSource::next() {
  if (have_spare_) {
    have_spare_ = false;
    return spare_;
  }
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  constexpr double kInv53 = 1.0 / 9007199254740992.0;  // 2^-53
  // u1 in (0, 1] (log-safe), u2 in [0, 1).
  const double u1 = static_cast<double>((engine_() >> 11) + 1) * kInv53;
  const double u2 = static_cast<double>(engine_() >> 11) * kInv53;
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(kTwoPi * u2);
  have_spare_ = true;
  return r * std::cos(kTwoPi * u2);
}

}  // namespace hstmon::sim
