#pragma once
/// @file compiled_bound.hpp
/// The model bound (model_bound.hpp) of a compiled circuit: the interpreter's
/// (circuit_bound.hpp) on the CircuitModel the compiled model holds. The bound runs once per
/// input change, off the hot path, where the compiled model itself is the interpreter: one
/// place for the bound's rule, and the same numbers as a monitor on the interpreter.

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/compiled_model.hpp"

namespace hstmon {

/// The compiled circuit's model bound: ModelBound<CircuitModel> on model.engine().
template <typename T, class Kernel>
struct ModelBound<circuit::CompiledModel<T, Kernel>> : ModelBound<typename circuit::CompiledModel<T, Kernel>::Engine> {
  using Model = circuit::CompiledModel<T, Kernel>;
  using Base = ModelBound<typename Model::Engine>;
  using Base::compute;
  using Base::kN;
  using typename Base::Uncertainty;

  /// Base::compute on the interpreter inside (same arguments, units and status).
  static Status compute(const Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>],
                        T* slowest_tau = nullptr, circuit::BoundLead<T, kN>* lead = nullptr) noexcept {
    return Base::compute(model.engine(), eps, m, slowest_tau, lead);
  }
  /// Base::compute_in_place on the interpreter inside: the compiled model is left bit for
  /// bit as it was (its own state is derived from the interpreter's values, which come back).
  static Status compute_in_place(Model& model, const Uncertainty& eps, T (&m)[circuit::kExtent<kN>],
                                 T* slowest_tau = nullptr, circuit::BoundLead<T, kN>* lead = nullptr) noexcept {
    return Base::compute_in_place(model.borrow_engine(), eps, m, slowest_tau, lead);
  }
};

}  // namespace hstmon
