#include "hstmon_circuit/machine_spread.hpp"

#include <cstddef>

#include "hstmon_circuit/circuit_faults.hpp"

namespace hstmon::circuit_tools {

LoadedCircuit spread_machine(const LoadedCircuit& c, double spread, std::mt19937_64& rng) {
  LoadedCircuit m = c;
  std::uniform_real_distribution<double> u(-spread, spread);
  for (std::size_t p = 0; p < c.file.params.size(); ++p) {
    if (moves_steady_state(c.file.params[p])) m.values.params.v[p] *= 1.0 + u(rng);
  }
  return m;
}

}  // namespace hstmon::circuit_tools
