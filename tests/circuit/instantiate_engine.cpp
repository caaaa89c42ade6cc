// Instantiates the circuit engine and an observer on it in float and double under the
// firmware flags (-fno-exceptions -fno-rtti, the strict warning set), so the engine's
// headers stay firmware-clean although the circuit tests themselves are host code.
#include "hstmon/circuit/engine.hpp"
#include "hstmon/fault_matcher.hpp"
#include "hstmon/generated/closed_loop_hst_signatures.hpp"
#include "hstmon/generated/paper_signatures.hpp"
#include "hstmon/generated/test_stand_signatures.hpp"
#include "hstmon/generated/thesis_circuit.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"
#include "hstmon/observer.hpp"

namespace hstmon::circuit {
using FirmwareThesisCap = Capacity<7, 1, 10, 4, 4, 16, 2>;  // thesis.json: 7 nodes, 10 elements, 15 parameters
template class CircuitModel<float, HostCapacity>;
template class CircuitModel<double, HostCapacity>;
template class CircuitModel<float, FirmwareThesisCap>;
// The firmware's own: thesis.json's generated header, its tight capacity.
template class CircuitModel<float, generated::thesis_circuit::Cap>;
// Its compiled model (hstmon-circuit-header --compiled), what the firmware images run.
template class CompiledModel<float, generated::thesis_circuit::Kernel>;
template class CompiledModel<double, generated::thesis_circuit::Kernel>;
template std::uint32_t auto_stiff_mask<float, HostCapacity>(const Circuit<HostCapacity>&,
                                                           const CircuitModel<float, HostCapacity>::Params&,
                                                           const CircuitModel<float, HostCapacity>::Inputs&, float,
                                                           float, int*) noexcept;
}  // namespace hstmon::circuit

namespace hstmon::circuit {
// Observer<Model> cannot be instantiated whole: reset_measured's choose_initial_state asks
// for a static state_channel, which a model whose circuit is data cannot offer (issue 14,
// docs/circuits.md). Every other member the observer has is used here.
template <typename Model>
std::uint32_t use_observer(const Model& m, const typename Model::Inputs& u);
template <typename Model>
std::uint32_t use_observer(const Model& m, const typename Model::Inputs& u) {
  hstmon::Observer<Model, false> o;
  typename hstmon::Observer<Model, false>::Config cfg;
  (void)o.configure(m, cfg);
  (void)o.reset_rest(u);
  (void)o.reset_steady(u);
  typename hstmon::Observer<Model, false>::Measurement y;
  return o.step(u, y);
}
template std::uint32_t use_observer(const hstmon::circuit::CircuitModel<float, hstmon::circuit::HostCapacity>&,
                                    const hstmon::circuit::CircuitModel<float, hstmon::circuit::HostCapacity>::Inputs&);
template std::uint32_t use_observer(const hstmon::circuit::CircuitModel<double, hstmon::circuit::HostCapacity>&,
                                    const hstmon::circuit::CircuitModel<double, hstmon::circuit::HostCapacity>::Inputs&);
template std::uint32_t use_observer(
    const hstmon::circuit::CircuitModel<float, hstmon::circuit::FirmwareThesisCap>&,
    const hstmon::circuit::CircuitModel<float, hstmon::circuit::FirmwareThesisCap>::Inputs&);

// The firmware's observer set-up: bound in place to the generated constexpr description.
std::uint32_t use_generated_observer();
std::uint32_t use_generated_observer() {
  namespace gen = generated::thesis_circuit;
  using M = CircuitModel<float, gen::Cap>;
  hstmon::Observer<M, false> o;
  M::Params p;
  for (int i = 0; i < gen::Cap::kParams; ++i) p.v[i] = static_cast<float>(gen::kParams[i]);
  (void)o.configure(gen::kCircuit, p, hstmon::Observer<M, false>::Config{});
  return o.step(M::Inputs{}, hstmon::Observer<M, false>::Measurement{});
}
}  // namespace hstmon::circuit

// The shipped circuits' generated fault tables, with a matcher of their channel count, under
// the firmware flags: what a firmware monitor of those circuits compiles.
namespace hstmon {
template class FaultMatcher<float, 64, 2, 1, generated::paper_signatures::kChannels>;
template class FaultMatcher<float, 64, 2, 1, generated::test_stand_signatures::kChannels>;
static_assert(generated::paper_signatures::kSignatureCount > generated::paper_signatures::kChannels,
              "parameter rows besides the sensor rows");
static_assert(generated::closed_loop_hst_signatures::kSignatureCount <= 64, "fits the matcher above");
}  // namespace hstmon
