/// @file machine_error.cpp
#include "hstmon_sim/machine_error.hpp"

#include <random>
#include <stdexcept>

namespace hstmon::sim {

ThesisParams<double> perturbed_params(std::uint64_t seed, double spread, const ThesisParams<double>& base) {
  if (!(spread >= 0.0 && spread < 1.0)) throw std::invalid_argument("parameter error must be in [0, 1)");
  ThesisParams<double> p = base;
  if (spread == 0.0) return p;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(-spread, spread);
  double* fields[] = {&p.Dm, &p.Dp, &p.Rlkg, &p.Ripl, &p.Rf, &p.Rbl, &p.kf, &p.J, &p.K};
  for (double* f : fields) *f *= 1.0 + uni(rng);
  return p;
}

}  // namespace hstmon::sim
