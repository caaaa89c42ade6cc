#include "hstmon_circuit/fault_table_builders.hpp"

#include <exception>

namespace hstmon::circuit_tools {

FaultTableBuilders steady_fault_tables() { return {}; }

std::vector<std::optional<CircuitFaultTable>> circuit_fault_tables_with_each(const LoadedCircuit& c,
                                                                             const std::vector<AddedSensor>& added) {
  std::vector<std::optional<CircuitFaultTable>> out(added.size());
  for (std::size_t k = 0; k < added.size(); ++k) {
    try {
      out[k] = circuit_fault_table(with_added_sensor(c, added[k]));
    } catch (const std::exception&) {
      // no table with this channel: left empty
    }
  }
  return out;
}

}  // namespace hstmon::circuit_tools
