// The generated circuit's values in float and the observer on it (fw_circuit.hpp).
#include "fw_circuit.hpp"

namespace hstmon::fw {

CircuitFwModel::Params circuit_params() noexcept {
  CircuitFwModel::Params p;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = static_cast<float>(gen::kParams[i]);
  return p;
}

CircuitFwModel::Inputs circuit_inputs() noexcept {
  CircuitFwModel::Inputs u;
  for (int i = 0; i < gen::Cap::kInputs; ++i) u.v[i] = static_cast<float>(gen::kInputs[i]);
  return u;
}

Status configure_circuit_observer(CircuitFwObserver& obs) noexcept {
  CircuitFwObserver::Config cfg;
  cfg.tick = static_cast<float>(kTick);
  return obs.configure(gen::kCircuit, circuit_params(), cfg);
}

}  // namespace hstmon::fw
