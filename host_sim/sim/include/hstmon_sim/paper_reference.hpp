#pragma once
/// @file paper_reference.hpp
/// Reference integration of the paper model (hstmon::PaperModel<double>, seed 001
/// equations 1–8) with the Rosenbrock-4 integrator and the analytic Jacobian of
/// paper_jacobian.hpp. Same piecewise-constant input handling as ThesisReference.

#include "hstmon/paper_model.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/segmented_reference.hpp"

namespace hstmon::sim {

/// Paper model integrated with Rosenbrock-4: inputs A_dcv, A_prv [m²]; state Ps (pump B),
/// Pmi, Ppp [Pa], ωm [rad/s]. Not copyable; movable.
class PaperReference : public SegmentedReference<PaperReference, PaperModel<double>::State, PaperInputs<double>> {
 public:
  using Model = PaperModel<double>;   ///< the model integrated (lib/, double)
  using Params = PaperParams<double>;  ///< Table I by default

  /// @param p    parameters (rejected by PaperModel::set_params → exception)
  /// @param x0   state at t0
  /// @param t0   initial time [s]
  /// @param tol  tolerances (pressures in Pa, speed in rad/s)
  /// @throws std::invalid_argument on invalid parameters or a non-finite x0
  explicit PaperReference(const Params& p = Params{}, const State& x0 = State::Zero(), double t0 = 0.0,
                          const ReferenceTolerances& tol = ReferenceTolerances{});

  /// The model (parameters and pump curve) in use.
  const Model& model() const noexcept { return model_; }

 private:
  friend SegmentedReference;
  static constexpr const char* kName = "PaperReference";
  static void to_array(const State& x, double* out) noexcept {
    for (int i = 0; i < 4; ++i) out[i] = x[i];
  }
  static State from_array(const double* v) noexcept { return State(Eigen::Map<const State>(v)); }
  void begin_segment(const Inputs& u);

  Model model_;
};

}  // namespace hstmon::sim
