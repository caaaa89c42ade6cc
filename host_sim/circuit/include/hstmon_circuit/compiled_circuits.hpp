#pragma once
/// @file compiled_circuits.hpp
/// The circuits this program carries compiled: the shipped circuits' generated kernels
/// (lib/circuit/include/hstmon/generated/*_compiled.hpp, hstmon-circuit-header --compiled).
/// A host tool given a description equal to one of them (circuit::same_circuit: the same
/// topology, references and stiff mask; the values may be any) runs the kernel's
/// straight-line code instead of the interpreter: the same numbers (compiled_model.hpp:
/// the interpreter's laws, solve and order of summation), a few times faster. Any other
/// circuit runs on the interpreter, as before.

#include <type_traits>

#include "hstmon/circuit/same_circuit.hpp"
#include "hstmon/generated/closed_loop_hst_circuit_compiled.hpp"
#include "hstmon/generated/paper_circuit_compiled.hpp"
#include "hstmon/generated/thesis_circuit_compiled.hpp"
#include "hstmon_host/circuit_file.hpp"

namespace hstmon::circuit_tools {

/// Names a kernel type as a value, for a generic lambda: `[](auto k) { using K = typename decltype(k)::type; }`.
template <class Kernel>
struct KernelTag {
  using type = Kernel;
};

namespace compiled_detail {

template <class F, class Kernel, class... More>
bool first_match(const host::HostCircuit& d, F& f) {
  if (circuit::same_circuit(d, Kernel::description())) {
    f(KernelTag<Kernel>{});
    return true;
  }
  if constexpr (sizeof...(More) > 0) {
    return first_match<F, More...>(d, f);
  } else {
    return false;
  }
}

}  // namespace compiled_detail

/// Calls f(KernelTag<K>{}) for the first compiled kernel K whose circuit is d, and
/// returns true; returns false, f not called, when d is none of them.
/// @param d  a description as the circuit file and the replay's stiff-node choice made it
template <class F>
bool with_compiled_kernel(const host::HostCircuit& d, F&& f) {
  return compiled_detail::first_match<std::remove_reference_t<F>, generated::thesis_circuit::Kernel,
                                      generated::paper_circuit::Kernel, generated::closed_loop_hst_circuit::Kernel>(d,
                                                                                                                    f);
}

}  // namespace hstmon::circuit_tools
