#pragma once
/// @file tiny_model.hpp
/// The smallest model the Observer runs (model_concept.hpp), as a worked example: one
/// pressure node of capacitance C fed by a flow source Q and drained through a laminar
/// leakage R to tank,
///   dP/dt = (Q − P/R)/C,   output: P (measured),
/// so P(t) = Q·R + (P0 − Q·R)·e^(−t/(R·C)) exactly, and the spectral radius is 1/(R·C).

#include <Eigen/Core>
#include <cmath>

namespace hstmon_test {

template <typename T>
class TinyNodeModel {
 public:
  using Scalar = T;
  static constexpr int kStates = 1;   ///< P
  static constexpr int kOutputs = 1;  ///< P
  using State = Eigen::Matrix<T, 1, 1>;
  using Output = Eigen::Matrix<T, 1, 1>;
  /// The one input: the source flow [m³/s].
  struct Inputs {
    T Q = T(1e-4);  ///< source flow [m³/s]
  };

  T C = T(1e-11);  ///< node capacitance V/β [m³/Pa]
  T R = T(1e11);   ///< leakage resistance [Pa·s/m³] (τ = R·C = 1 s)

  static bool inputs_valid(const Inputs& u) noexcept { return std::isfinite(u.Q); }
  void set_inputs(const Inputs& u) noexcept { u_ = u; }
  const Inputs& inputs() const noexcept { return u_; }

  Output outputs(const State& x) const noexcept { return x; }
  State rest_state() const noexcept { return State(T(0)); }
  bool steady_state(State& x) const noexcept {
    x = State(u_.Q * R);
    return true;
  }
  bool state_plausible(const State& x) const noexcept { return std::isfinite(x[0]) && std::fabs(x[0]) < T(1e12); }
  static constexpr int state_channel(int i) noexcept { return i; }

  State derivative(const State& x) const noexcept { return State((u_.Q - x[0] / R) / C); }
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok) const noexcept {
    y = x;
    const T r = T(1) / (R * C);
    rho = r > rho_max ? r : T(0);
    alg_ok = true;
    return derivative(x);
  }

 private:
  Inputs u_{};
};

}  // namespace hstmon_test
