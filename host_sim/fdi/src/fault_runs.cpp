#include "fault_runs.hpp"

#include <exception>
#include <utility>

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_sim.hpp"

namespace hstmon::fdi {

FaultRun simulate_fault(const circuit_tools::LoadedCircuit& c, const std::string& base, double factor,
                        double duration) {
  circuit_tools::CircuitSimOptions o;
  o.noise = false;
  o.rate = 1000.0;
  constexpr double kFaultTime = 0.01;  // [s] a few samples of the steady start first
  o.duration = kFaultTime + duration;
  circuit_tools::InputStep step;
  step.t = kFaultTime;
  step.param = c.file.param_index(base);
  if (step.param >= 0) {
    step.factor = factor;
  } else {
    step.input = c.file.input_index(base);
    step.value = c.values.inputs.v[step.input] * factor;
  }
  o.steps = {step};
  host::HostCircuitModel::Params p = c.values.params;
  host::HostCircuitModel::Inputs u = c.values.inputs;
  if (step.param >= 0) {
    circuit_tools::apply_param_fault(c.file, p, c.values.params, static_cast<std::size_t>(step.param), factor);
  } else {
    u.v[step.input] = step.value;
  }
  FaultRun run;
  const host::HostCircuitModel faulted(c.file.circuit, p, u);
  host::HostCircuitModel::State xs;
  if (!faulted.valid() || !faulted.steady_state(xs)) {
    run.steady = false;
    return run;
  }
  try {
    run.sensors = circuit_tools::simulate_circuit(c, o).sensors;
  } catch (const std::exception&) {
    run.failed = true;
  }
  return run;
}

SharedFaultRuns::SharedFaultRuns(circuit_tools::LoadedCircuit all) : all_(std::move(all)) {}

FaultRun SharedFaultRuns::run(const std::string& base, double factor, double duration,
                              const std::vector<std::size_t>& channels) {
  const auto key = std::make_tuple(base, factor, duration);
  auto it = done_.find(key);
  if (it == done_.end()) it = done_.emplace(key, simulate_fault(all_, base, factor, duration)).first;
  const FaultRun& all = it->second;
  FaultRun out;
  out.steady = all.steady;
  out.failed = all.failed;
  if (all.sensors.empty()) return out;
  for (const std::size_t ch : channels) out.sensors.push_back(all.sensors.at(ch));
  return out;
}

}  // namespace hstmon::fdi
