#pragma once
/// @file paper_reference.hpp
/// Reference integration of the paper model (hstmon::PaperModel<double>, seed 001
/// equations 1–8) with the Rosenbrock-4 integrator and the analytic Jacobian of
/// paper_jacobian.hpp. Same piecewise-constant input handling as ThesisReference.

#include <functional>
#include <vector>

#include "hstmon/paper_model.hpp"
#include "hstmon_sim/reference_tolerances.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace hstmon::sim {

/// Paper model integrated with Rosenbrock-4. Not copyable; movable.
class PaperReference {
 public:
  using Model = PaperModel<double>;   ///< the model integrated (lib/, double)
  using Params = PaperParams<double>;  ///< Table I by default
  using Inputs = PaperInputs<double>;  ///< A_dcv, A_prv [m²]
  using State = Model::State;          ///< Ps (pump B), Pmi, Ppp [Pa], ωm [rad/s]
  /// Receives one sample: time [s] and state.
  using Sampler = std::function<void(double t, const State& x)>;

  /// @param p    parameters (rejected by PaperModel::set_params → exception)
  /// @param x0   state at t0
  /// @param t0   initial time [s]
  /// @param tol  tolerances (pressures in Pa, speed in rad/s)
  /// @throws std::invalid_argument on invalid parameters or a non-finite x0
  explicit PaperReference(const Params& p = Params{}, const State& x0 = State::Zero(), double t0 = 0.0,
                          const ReferenceTolerances& tol = ReferenceTolerances{});

  /// Integrates to t_end [s] with inputs u; restarts the integrator when u changes.
  /// @throws std::invalid_argument on invalid inputs or t_end < time();
  ///         std::runtime_error if the integration fails
  void advance_to(double t_end, const Inputs& u);

  /// As advance_to(t_end, u), sampling at each ts in sample_times (ascending) with
  /// time() < ts ≤ t_end.
  void advance_to(double t_end, const Inputs& u, const std::vector<double>& sample_times,
                  const Sampler& on_sample);

  /// Replaces the state at time t [s]; the next advance_to() restarts the integrator.
  void reset(const State& x, double t);

  /// Current state.
  State state() const;
  /// Current time [s].
  double time() const noexcept;
  /// The model (parameters and pump curve) in use.
  const Model& model() const noexcept { return model_; }
  /// Step statistics of the integrator.
  const IntegratorStats& stats() const noexcept { return integ_.stats(); }

 private:
  void begin_segment(const Inputs& u);

  Model model_;
  bool segment_open_ = false;
  State x_pending_ = State::Zero();
  double t_pending_ = 0.0;
  StiffIntegrator integ_;
};

}  // namespace hstmon::sim
