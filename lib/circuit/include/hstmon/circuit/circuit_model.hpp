#pragma once
/// @file circuit_model.hpp
/// The model engine: a circuit description (circuit.hpp) as the Observer's model.
///
/// States are the pressures of the volume nodes outside the stiff mask and the speeds of
/// the free shafts, in node then shaft order. Stiff nodes (stiffness.hpp picks them) are
/// taken quasi-steady: each evaluation solves their flow balances for their pressures
/// given the states, by Gauss–Seidel sweeps of exact scalar solves (safeguarded Newton),
/// which contract because every element is monotone and every stiff node keeps a
/// guaranteed conductance to fixed pressures (docs/circuits.md gives the argument and
/// contraction_bound() its number). Outputs are what the sensor channels measure.
///
/// Everything is in the object: capacity-sized arrays, no heap, no exceptions, no RTTI.
/// The description is referred to by pointer (it can live in flash) and must outlive the
/// model. The last quasi-steady solution is kept as the next solve's start (a warm start;
/// results agree to rounding whatever the start), so a model must not be evaluated from
/// two threads at once.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/decay_rate.hpp"
#include "hstmon/circuit/dense.hpp"
#include "hstmon/circuit/laws.hpp"
#include "hstmon/circuit/pseudo_transient.hpp"
#include "hstmon/circuit/quasi_steady.hpp"
#include "hstmon/circuit/stiffness_certificate.hpp"
#include "hstmon/circuit/validate.hpp"
#include "hstmon/code_size.hpp"
#include "hstmon/pump_curve.hpp"

namespace hstmon::circuit {

/// Spectral radius of ∂f/∂x at x [1/s] of a circuit model (CircuitModel, CompiledModel):
/// its tick_derivative's rho with rho_max = 0.
template <class Model>
typename Model::Scalar tick_spectral_radius(const Model& m, const typename Model::State& x) noexcept {
  typename Model::Output y;
  typename Model::Scalar rho;
  bool ok;
  (void)m.tick_derivative(x, typename Model::Scalar(0), y, rho, ok);
  return rho;
}

template <typename T, class Cap = HostCapacity>
class CircuitModel {
 public:
  using Scalar = T;
  using Description = Circuit<Cap>;
  static constexpr int kStates = Cap::kStates;
  static constexpr int kOutputs = Cap::kChannels;
  static constexpr int kNodes = Cap::kNodes;
  static constexpr int kElements = Cap::kElements;
  /// Size of the full unknown space: every node, then every shaft.
  static constexpr int kZ = Cap::kNodes + Cap::kShafts;
  /// Room for the unknowns (volume nodes and free shafts): the Jacobian's and the
  /// steady-state solve's scratch is kU × kU, not kZ × kZ (no rows for boundaries).
  static constexpr int kU = Cap::kUnknowns;
  using State = Eigen::Matrix<T, kStates, 1>;
  using Output = Eigen::Matrix<T, kOutputs, 1>;
  using StateMatrix = Eigen::Matrix<T, kStates, kStates>;

  /// Parameter values by index (SI units of each parameter; the host's circuit file
  /// says which is which).
  struct Params {
    T v[kExtent<Cap::kParams>]{};
  };
  /// Input values by index (SI), held over a tick.
  struct Inputs {
    T v[kExtent<Cap::kInputs>]{};

    /// True when every input is equal (the monitor's test for an input change).
    friend bool operator==(const Inputs& a, const Inputs& b) noexcept {
      for (int i = 0; i < Cap::kInputs; ++i) {
        if (!(a.v[i] == b.v[i])) return false;
      }
      return true;
    }
    /// True when each input of b is within tol [-] of a's, relative to a's
    /// (input_change.hpp); an input at 0 in a changes with any move. False for a NaN.
    friend bool inputs_within(const Inputs& a, const Inputs& b, T tol) noexcept {
      for (int i = 0; i < Cap::kInputs; ++i) {
        if (!(std::fabs(b.v[i] - a.v[i]) <= tol * std::fabs(a.v[i]))) return false;
      }
      return true;
    }
  };

  /// Gauss–Seidel sweeps and Newton iterations per node before a solve is declared failed.
  static constexpr int kMaxSweeps = circuit::kMaxSweeps;
  static constexpr int kMaxNewton = circuit::kMaxNewton;
  /// Laminar transition of an orifice or poppet when the circuit does not give one [Pa].
  static constexpr double kDefaultDpT = 1e3;

  CircuitModel() noexcept = default;

  /// bind(c), set_params(p), set_inputs(u).
  CircuitModel(const Description& c, const Params& p, const Inputs& u = Inputs{}) noexcept {
    bind(c);
    u_ = u;
    set_params(p);
  }

  /// Takes a description (kept by pointer) and builds the index maps. O(elements).
  /// @return kOk, or the structural error (the model then has no states and no outputs)
  CircuitError bind(const Description& c) noexcept {
    c_ = nullptr;
    n_states_ = n_stiff_ = n_unknowns_ = 0;
    error_ = validate(c);
    if (error_ != CircuitError::kOk) return error_;
    c_ = &c;
    for (int k = 0; k < kZ; ++k) state_of_z_[k] = unknown_of_z_[k] = -1;
    for (int i = 0; i < c.n_nodes; ++i) {
      if (c.nodes[i].kind != NodeKind::kVolume) continue;
      unknown_of_z_[i] = static_cast<std::int8_t>(n_unknowns_);
      unknown_z_[n_unknowns_++] = static_cast<std::uint8_t>(i);
      if (((c.stiff_mask >> i) & 1u) != 0) {
        stiff_[n_stiff_++] = static_cast<std::uint8_t>(i);
      } else {
        state_of_z_[i] = static_cast<std::int8_t>(n_states_);
        z_of_state_[n_states_++] = static_cast<std::uint8_t>(i);
      }
    }
    for (int s = 0; s < c.n_shafts; ++s) {
      if (c.shafts[s].driven) continue;
      const int z = kNodes + s;
      unknown_of_z_[z] = static_cast<std::int8_t>(n_unknowns_);
      unknown_z_[n_unknowns_++] = static_cast<std::uint8_t>(z);
      state_of_z_[z] = static_cast<std::int8_t>(n_states_);
      z_of_state_[n_states_++] = static_cast<std::uint8_t>(z);
    }
    for (int j = 0; j < n_stiff_; ++j) stiff_u_[j] = static_cast<std::uint8_t>(unknown_of_z_[stiff_[j]]);
    for (int k = 0; k < n_states_; ++k) state_u_[k] = static_cast<std::uint8_t>(unknown_of_z_[z_of_state_[k]]);
    // Incidence lists (node → elements with a port on it), compressed rows.
    int k = 0;
    stiff_coupled_ = false;
    for (int i = 0; i < c.n_nodes; ++i) {
      inc_start_[i] = static_cast<std::uint16_t>(k);
      for (int e = 0; e < c.n_elements; ++e) {
        const Element& el = c.elements[e];
        if (!has_ports(el.kind) || (el.a != i && el.b != i)) continue;
        inc_[k++] = static_cast<std::uint8_t>(e);
        const int o = el.a == i ? el.b : el.a;
        if (is_stiff(i) && is_stiff(o)) stiff_coupled_ = true;
      }
    }
    inc_start_[c.n_nodes] = static_cast<std::uint16_t>(k);
    // Per element, the unknown index of each port and of its shaft (−1: fixed), and per
    // shaft its torque elements in element order (the Jacobian's and rates' loops).
    int t = 0;
    for (int e = 0; e < c.n_elements; ++e) {
      const Element& el = c.elements[e];
      el_unknown_[e][0] = has_ports(el.kind) ? unknown_of_z_[el.a] : std::int8_t{-1};
      el_unknown_[e][1] = has_ports(el.kind) ? unknown_of_z_[el.b] : std::int8_t{-1};
      el_unknown_[e][2] = el.shaft >= 0 ? unknown_of_z_[kNodes + el.shaft] : std::int8_t{-1};
    }
    for (int sh = 0; sh < c.n_shafts; ++sh) {
      shaft_start_[sh] = static_cast<std::uint8_t>(t);
      for (int e = 0; e < c.n_elements; ++e) {
        if (has_shaft(c.elements[e].kind) && c.elements[e].shaft == sh) shaft_inc_[t++] = static_cast<std::uint8_t>(e);
      }
    }
    shaft_start_[c.n_shafts] = static_cast<std::uint8_t>(t);
    set_inputs(u_);
    return error_;
  }

  /// True when every parameter is finite (the static check the observer can make;
  /// whether the values make a physical circuit is valid()).
  static bool params_valid(const Params& p) noexcept { return all_finite(p.v); }
  /// True when every input is finite. Negative openings are taken as shut.
  static bool inputs_valid(const Inputs& u) noexcept { return all_finite(u.v); }

  /// Replaces the parameter values and re-resolves the coefficients. O(elements).
  void set_params(const Params& p) noexcept {
    p_ = p;
    set_inputs(u_);
  }

  /// Sets the inputs held over the next evaluations and resolves every element's
  /// coefficients, the capacitances, boundary pressures, driven speeds and the rest
  /// state. O(elements); the observer calls it only when the inputs change.
  void set_inputs(const Inputs& u) noexcept {
    u_ = u;
    if (c_ == nullptr) return;
    resolve();
  }

  const Params& params() const noexcept { return p_; }
  const Inputs& inputs() const noexcept { return u_; }
  const Description* description() const noexcept { return c_; }
  /// The structural error of the last bind (kOk once bound, kUnbound before).
  CircuitError error() const noexcept { return error_; }
  /// True when bound and every resolved number is physical (capacitances, inertias,
  /// transitions > 0, poppets with full > crack, a consistent pump curve, finite all).
  bool valid() const noexcept { return c_ != nullptr && values_ok_; }

  int n_states() const noexcept { return n_states_; }
  int n_stiff() const noexcept { return n_stiff_; }
  int n_outputs() const noexcept { return c_ != nullptr ? c_->n_channels : 0; }
  /// Node index (< n_nodes) or kNodes + shaft index of state s.
  int state_z(int s) const noexcept { return z_of_state_[s]; }
  /// Node index of the j-th stiff node.
  int stiff_node(int j) const noexcept { return stiff_[j]; }
  /// Capacitance K of node i [Pa/m³] (0 for a boundary) after the last set_inputs.
  T node_stiffness(int i) const noexcept { return inv_mass_[i]; }
  T pressure_envelope() const noexcept { return p_env_; }  ///< [Pa]
  T speed_envelope() const noexcept { return w_env_; }     ///< [rad/s]
  const Coeffs<T>& coeffs(int e) const noexcept { return coef_[e]; }
  /// Entry k of the full vector that no state sets: a boundary's pressure [Pa], a driven
  /// shaft's speed [rad/s], else 0 (after the last set_inputs).
  T fixed_value(int k) const noexcept { return fixed_z_[k]; }
  /// Pressure of the j-th stiff node the next quasi-steady solve starts from [Pa].
  T warm_start(int j) const noexcept { return guess_[j]; }
  /// Sets the j-th stiff node's warm start [Pa]: for a caller that perturbs the model in
  /// place and puts it back as it was (the model bound, circuit_bound.hpp).
  void set_warm_start(int j, T p) noexcept { guess_[j] = p; }

  /// Full vector z at state x: node pressures (boundaries, states, stiff nodes solved)
  /// then shaft speeds (states, driven).
  /// @param z  out: kZ values [Pa, rad/s]
  /// @return   true when the quasi-steady solve converged
  bool full_vector(const State& x, T (&z)[kExtent<kZ>]) const noexcept {
    fill(x, z);
    return solve_stiff(z);
  }

  /// Time derivative of the states [Pa/s, rad/s²] and, if y is given, the outputs.
  State derivative(const State& x, Output* y = nullptr) const noexcept {
    T z[kExtent<kZ>];
    fill(x, z);
    (void)solve_stiff(z);
    if (y != nullptr) *y = outputs_at(z);
    return rates(z);
  }

  /// derivative(x, &y) with the observer's per-tick checks (Observer's model interface).
  /// @param rho_max  ρ at or below which its value is not needed [1/s]
  /// @param y        out: outputs at x
  /// @param rho      out: spectral radius of ∂f/∂x [1/s] — exact for up to two states, an
  ///                 upper bound beyond (dense.hpp radius_bound) — or 0 if at most rho_max
  /// @param alg_ok   out: the quasi-steady solve converged and contracts at x by < 0.5
  /// @param rho_stiff the radius above which only "above" matters (radius_bound) [1/s]
  State tick_derivative(const State& x, T rho_max, Output& y, T& rho, bool& alg_ok,
                        T rho_stiff = std::numeric_limits<T>::infinity()) const noexcept {
    T z[kExtent<kZ>];
    fill(x, z);
    const bool conv = solve_stiff(z);
    y = outputs_at(z);
    T jr[kExtent<kStates>][kExtent<kStates>];
    T q = T(0);
    reduced_jacobian(z, jr, q);
    rho = radius_bound(jr, n_states_, rho_max, rho_stiff);
    alg_ok = conv && q < T(0.5);
    return rates(z);
  }

  /// Outputs at x: what each channel measures, in SI units.
  Output outputs(const State& x) const noexcept {
    T z[kExtent<kZ>];
    fill(x, z);
    (void)solve_stiff(z);
    return outputs_at(z);
  }

  /// Spectral radius of ∂f/∂x at x (tick_derivative's rho with rho_max = 0) [1/s].
  T spectral_radius(const State& x) const noexcept { return tick_spectral_radius(*this, x); }

  /// Jacobian ∂f/∂x of the (reduced) state equations at x [1/s in state units]; the
  /// stiff nodes enter through the Schur complement of their block.
  void jacobian(const State& x, StateMatrix& J) const noexcept {
    T z[kExtent<kZ>];
    fill(x, z);
    (void)solve_stiff(z);
    // Zeroed: GCC at -O1 cannot see that reduced_jacobian writes every used entry.
    T jr[kExtent<kStates>][kExtent<kStates>] = {};
    T q;
    reduced_jacobian(z, jr, q);
    J.setZero();
    for (int r = 0; r < n_states_; ++r) {
      for (int c = 0; c < n_states_; ++c) J(r, c) = jr[r][c];
    }
  }

  /// Slowest decay rate of the linearised dynamics at x [1/s]: min −Re λ over the
  /// eigenvalues of jacobian(x); 0 when some mode does not decay (Re λ ≥ 0) or the
  /// eigen-solve fails. The monitor's start-up hold-off is (1/rate)·ln D.
  T slowest_rate(const State& x) const noexcept {
    StateMatrix J;
    jacobian(x, J);
    // The unused rows and columns (n_states() < kStates) are zero: give them a mode
    // faster than any of the used block's (Gershgorin: |λ| ≤ the largest row sum), so
    // the slowest is the used block's.
    T s = T(0);
    for (int r = 0; r < n_states_; ++r) s = std::max(s, J.row(r).cwiseAbs().sum());
    for (int r = n_states_; r < kStates; ++r) J(r, r) = -(T(1) + T(10) * s);
    return slowest_decay_rate(J);
  }

  /// Local contraction factor of the quasi-steady solve at x [-]: the largest row sum
  /// Σ_{j≠i} |∂F_i/∂p_j| / |∂F_i/∂p_i| over the stiff nodes, the Jacobi iteration's
  /// ∞-norm factor there (Gauss–Seidel's is no larger). 0 without stiff nodes.
  T contraction_factor(const State& x) const noexcept {
    T z[kExtent<kZ>];
    fill(x, z);
    (void)solve_stiff(z);
    T jr[kExtent<kStates>][kExtent<kStates>];
    T q;
    reduced_jacobian(z, jr, q);
    return q;
  }

  /// A-priori contraction factor over the whole envelope [-]: for each stiff node,
  /// S/(S + G) with S the largest conductance it can have to other stiff nodes and G the
  /// least it keeps to fixed pressures (laws.hpp's bounds); the largest over the stiff
  /// nodes. < 1 means the solve contracts at every state; ≥ 1 (or no G) that the stiff
  /// mask is not admissible for these values.
  T contraction_bound() const noexcept { return q_bound_; }

  /// Conductance bounds of node i for stiff set `mask` [m³/(s·Pa)]: g_min the least
  /// total conductance over the envelope, g_fix the least to nodes outside the mask,
  /// s_max the most to nodes inside it (stiffness.hpp's classification).
  void conductance_bounds(int i, std::uint32_t mask, T& g_min, T& g_fix, T& s_max) const noexcept {
    g_min = g_fix = s_max = T(0);
    if (c_ == nullptr) return;
    for (int k = inc_start_[i]; k < inc_start_[i + 1]; ++k) {
      const Element& el = c_->elements[inc_[k]];
      const int o = el.a == i ? el.b : el.a;
      const T gmin = min_conductance(el.kind, coef_[inc_[k]], p_env_);
      g_min += gmin;
      if (c_->nodes[o].kind == NodeKind::kVolume && ((mask >> o) & 1u) != 0) {
        s_max += max_conductance(el.kind, coef_[inc_[k]]);
      } else {
        g_fix += gmin;
      }
    }
  }

  /// Output channel that measures state s, or −1.
  int state_channel(int s) const noexcept {
    if (c_ == nullptr || s >= n_states_) return -1;
    const int z = z_of_state_[s];
    for (int ch = 0; ch < c_->n_channels; ++ch) {
      const Channel& h = c_->channels[ch];
      if ((h.kind == ChannelKind::kPressure && h.index == z) || (h.kind == ChannelKind::kSpeed && kNodes + h.index == z)) {
        return ch;
      }
    }
    return -1;
  }

  /// Each state's envelope: the pressure envelope for a node, the speed envelope for a
  /// shaft [Pa, rad/s]; 0 beyond n_states().
  State state_envelope() const noexcept {
    State e = State::Zero();
    for (int s = 0; s < n_states_; ++s) e[s] = z_of_state_[s] < kNodes ? p_env_ : w_env_;
    return e;
  }

  /// True when every state is finite and within twice the envelope (pressures ±2·
  /// pressure_max, speeds ±2·speed_max).
  bool state_plausible(const State& x) const noexcept {
    if (!((x * T(0)).sum() == T(0))) return false;
    for (int s = 0; s < n_states_; ++s) {
      const T lim = z_of_state_[s] < kNodes ? p_env_ : w_env_;
      if (!(std::fabs(x[s]) <= T(2) * lim)) return false;
    }
    return true;
  }

  /// The state at rest: free shafts still, every volume at the pressure of the first
  /// boundary it reaches through orifices, leakages and valves (0 if none).
  State rest_state() const noexcept { return from_z(rest_z_); }

  /// Steady state under the current inputs, by pseudo_transient() on the full circuit
  /// (every volume node and free shaft) from rest.
  /// @param x  out: the states there (untouched on failure)
  /// @return   false if no steady state was found
  bool steady_state(State& x) const noexcept {
    T z[kExtent<kZ>];
    if (!steady_full(z)) return false;
    x = from_z(z);
    return true;
  }

  /// steady_state() as the full vector z (stiff nodes included) [Pa, rad/s]; on failure z
  /// holds the solve's last iterate.
  bool steady_full(T (&z)[kExtent<kZ>]) const noexcept {
    if (c_ == nullptr || !values_ok_) return false;
    for (int k = 0; k < kZ; ++k) z[k] = rest_z_[k];
    T u[kExtent<kU>], mass[kExtent<kU>], scale[kExtent<kU>];
    for (int k = 0; k < n_unknowns_; ++k) {
      const int zk = unknown_z_[k];
      u[k] = z[zk];
      mass[k] = T(1) / inv_mass_[zk];
      scale[k] = zk < kNodes ? p_env_ : w_env_;
    }
    // z itself is the solve's full vector (its fixed entries stay the rest ones), and only
    // the unknowns' rows are evaluated: no kZ-sized copies on the stack (firmware).
    auto eval = [&](const T(&uu)[kExtent<kU>], T(&g)[kExtent<kU>], T(&J)[kExtent<kU>][kExtent<kU>]) {
      for (int k = 0; k < n_unknowns_; ++k) z[unknown_z_[k]] = uu[k];
      unknowns_net(z, g);
      unknowns_jacobian(z, J);
    };
    if (!pseudo_transient(eval, mass, scale, n_unknowns_, u)) return false;
    for (int k = 0; k < n_unknowns_; ++k) z[unknown_z_[k]] = u[k];
    for (int k = 0; k < n_unknowns_; ++k) {
      if (!std::isfinite(u[k])) return false;
    }
    for (int j = 0; j < n_stiff_; ++j) guess_[j] = z[stiff_[j]];
    return true;
  }

  /// The states in the full vector z.
  State from_z(const T (&z)[kExtent<kZ>]) const noexcept {
    State x = State::Zero();
    for (int s = 0; s < n_states_; ++s) x[s] = z[z_of_state_[s]];
    return x;
  }

  /// ∂(net inflow, net torque)/∂z at z, dense [kExtent<kZ>][kExtent<kZ>] (rows: node flows, shaft torques).
  void full_jacobian(const T (&z)[kExtent<kZ>], T (&J)[kExtent<kZ>][kExtent<kZ>]) const noexcept {
    for (int r = 0; r < kZ; ++r) {
      for (int c = 0; c < kZ; ++c) J[r][c] = T(0);
    }
    if (c_ == nullptr) return;
    for (int e = 0; e < c_->n_elements; ++e) {
      const Element& el = c_->elements[e];
      const int sz = kNodes + el.shaft;
      const T w = el.shaft >= 0 ? z[sz] : T(0);
      if (has_ports(el.kind)) {
        const Flow<T> f = element_flow(el.kind, coef_[e], z[el.a], z[el.b], w);
        J[el.a][el.a] -= f.dpa;
        J[el.a][el.b] -= f.dpb;
        J[el.b][el.a] += f.dpa;
        J[el.b][el.b] += f.dpb;
        if (el.shaft >= 0) {
          J[el.a][sz] -= f.dw;
          J[el.b][sz] += f.dw;
        }
      }
      if (has_shaft(el.kind)) {
        T da, db, dw;
        const T pa = has_ports(el.kind) ? z[el.a] : T(0);
        const T pb = has_ports(el.kind) ? z[el.b] : T(0);
        (void)element_torque(el.kind, coef_[e], pa, pb, w, da, db, dw);
        if (has_ports(el.kind)) {
          J[sz][el.a] += da;
          J[sz][el.b] += db;
        }
        J[sz][sz] += dw;
      }
    }
  }

  /// Net inflow into each unknown node [m³/s] and net torque on each free shaft [N·m] at z,
  /// in unknown order, each row accumulated in element order.
  void unknowns_net(const T (&z)[kExtent<kZ>], T (&g)[kExtent<kU>]) const noexcept {
    for (int r = 0; r < n_unknowns_; ++r) g[r] = T(0);
    if (c_ == nullptr) return;
    for (int e = 0; e < c_->n_elements; ++e) {
      const Element& el = c_->elements[e];
      const T w = el.shaft >= 0 ? z[kNodes + el.shaft] : T(0);
      if (has_ports(el.kind)) {
        const T q = element_flow(el.kind, coef_[e], z[el.a], z[el.b], w).q;
        if (unknown_of_z_[el.a] >= 0) g[unknown_of_z_[el.a]] -= q;
        if (unknown_of_z_[el.b] >= 0) g[unknown_of_z_[el.b]] += q;
      }
      if (has_shaft(el.kind) && unknown_of_z_[kNodes + el.shaft] >= 0) {
        T da, db, dw;
        const T pa = has_ports(el.kind) ? z[el.a] : T(0);
        const T pb = has_ports(el.kind) ? z[el.b] : T(0);
        g[unknown_of_z_[kNodes + el.shaft]] += element_torque(el.kind, coef_[e], pa, pb, w, da, db, dw);
      }
    }
  }

  /// full_jacobian's rows and columns of the unknowns only, in unknown order (volume
  /// nodes, then free shafts): J[r][c] = ∂(net of unknown r)/∂(unknown c) at z. The same
  /// values bit for bit (each entry accumulates in the same element order).
  void unknowns_jacobian(const T (&z)[kExtent<kZ>], T (&J)[kExtent<kU>][kExtent<kU>]) const noexcept {
    for (int r = 0; r < n_unknowns_; ++r) {
      for (int c = 0; c < n_unknowns_; ++c) J[r][c] = T(0);
    }
    if (c_ == nullptr) return;
    for (int e = 0; e < c_->n_elements; ++e) {
      const Element& el = c_->elements[e];
      const int ua = el_unknown_[e][0], ub = el_unknown_[e][1], us = el_unknown_[e][2];
      const T w = el.shaft >= 0 ? z[kNodes + el.shaft] : T(0);
      // Flow rows a and b (only where an unknown): an element between fixed ends adds nothing.
      if (has_ports(el.kind) && (ua >= 0 || ub >= 0)) {
        const Flow<T> f = element_flow(el.kind, coef_[e], z[el.a], z[el.b], w);
        if (ua >= 0) {
          J[ua][ua] -= f.dpa;
          if (ub >= 0) J[ua][ub] -= f.dpb;
        }
        if (ub >= 0) {
          if (ua >= 0) J[ub][ua] += f.dpa;
          J[ub][ub] += f.dpb;
        }
        if (el.shaft >= 0 && us >= 0) {
          if (ua >= 0) J[ua][us] -= f.dw;
          if (ub >= 0) J[ub][us] += f.dw;
        }
      }
      if (has_shaft(el.kind) && us >= 0) {
        T da, db, dw;
        const T pa = has_ports(el.kind) ? z[el.a] : T(0);
        const T pb = has_ports(el.kind) ? z[el.b] : T(0);
        (void)element_torque(el.kind, coef_[e], pa, pb, w, da, db, dw);
        if (has_ports(el.kind)) {
          if (ua >= 0) J[us][ua] += da;
          if (ub >= 0) J[us][ub] += db;
        }
        J[us][us] += dw;
      }
    }
  }

  /// unknowns_jacobian bounded entrywise over the box lo ≤ z ≤ hi (full vectors; a fixed
  /// entry's bounds are its value): each element's conductance over its ports' pressure
  /// range (laws.hpp conductance_range); the machines' displacement and every torque slope
  /// are constants of the laws.
  void unknowns_jacobian_range(const T (&lo)[kExtent<kZ>], const T (&hi)[kExtent<kZ>], T (&J_lo)[kExtent<kU>][kExtent<kU>],
                               T (&J_hi)[kExtent<kU>][kExtent<kU>]) const noexcept {
    for (int r = 0; r < n_unknowns_; ++r) {
      for (int c = 0; c < n_unknowns_; ++c) J_lo[r][c] = J_hi[r][c] = T(0);
    }
    if (c_ == nullptr) return;
    for (int e = 0; e < c_->n_elements; ++e) {
      const Element& el = c_->elements[e];
      const int ua = el_unknown_[e][0], ub = el_unknown_[e][1], us = el_unknown_[e][2];
      const T w = el.shaft >= 0 ? lo[kNodes + el.shaft] : T(0);
      if (has_ports(el.kind) && (ua >= 0 || ub >= 0)) {
        T g_lo, g_hi;
        conductance_range(el.kind, coef_[e], lo[el.a] - hi[el.b], hi[el.a] - lo[el.b], g_lo, g_hi);
        const T dw = element_flow(el.kind, coef_[e], lo[el.a], lo[el.b], w).dw;
        if (ua >= 0) {
          J_lo[ua][ua] -= g_hi;
          J_hi[ua][ua] -= g_lo;
          if (ub >= 0) {
            J_lo[ua][ub] += g_lo;
            J_hi[ua][ub] += g_hi;
          }
        }
        if (ub >= 0) {
          if (ua >= 0) {
            J_lo[ub][ua] += g_lo;
            J_hi[ub][ua] += g_hi;
          }
          J_lo[ub][ub] -= g_hi;
          J_hi[ub][ub] -= g_lo;
        }
        if (el.shaft >= 0 && us >= 0) {
          if (ua >= 0) {
            J_lo[ua][us] -= dw;
            J_hi[ua][us] -= dw;
          }
          if (ub >= 0) {
            J_lo[ub][us] += dw;
            J_hi[ub][us] += dw;
          }
        }
      }
      if (has_shaft(el.kind) && us >= 0) {
        T da, db, dw;
        const T pa = has_ports(el.kind) ? lo[el.a] : T(0);
        const T pb = has_ports(el.kind) ? lo[el.b] : T(0);
        (void)element_torque(el.kind, coef_[e], pa, pb, w, da, db, dw);
        if (has_ports(el.kind)) {
          if (ua >= 0) {
            J_lo[us][ua] += da;
            J_hi[us][ua] += da;
          }
          if (ub >= 0) {
            J_lo[us][ub] += db;
            J_hi[us][ub] += db;
          }
        }
        J_lo[us][us] += dw;
        J_hi[us][us] += dw;
      }
    }
  }

  /// Stiffness certificate over the box lo ≤ z ≤ hi (full vectors, fixed entries at their
  /// values; stiffness_certificate.hpp): true when at every z in it the quasi-steady solve
  /// contracts by q < 0.5 and the reduced Jacobian's spectral radius is at most rho_max
  /// [1/s] (+∞: the contraction only), each with kCertificateMargin to spare. O(elements +
  /// unknowns³), two square roots per orifice.
  bool certify_box(const T (&lo)[kExtent<kZ>], const T (&hi)[kExtent<kZ>], T rho_max) const noexcept {
    if (!valid()) return false;
    T G_lo[kExtent<kU>][kExtent<kU>], G_hi[kExtent<kU>][kExtent<kU>];
    unknowns_jacobian_range(lo, hi, G_lo, G_hi);
    T inv_mass[kExtent<kStates>] = {};
    states_inv_mass(inv_mass);
    return certify_reduced(G_lo, G_hi, stiff_u_, n_stiff_, state_u_, n_states_, inv_mass, rho_max);
  }

 private:
  /// The states' K [Pa/m³] or 1/J [1/(kg·m²)], in state order: the rows' scale of the
  /// reduced Jacobian (reduced_jacobian, certify_box).
  void states_inv_mass(T (&m)[kExtent<kStates>]) const noexcept {
    for (int r = 0; r < n_states_; ++r) m[r] = inv_mass_[z_of_state_[r]];
  }

  bool is_stiff(int i) const noexcept { return c_ != nullptr && ((c_->stiff_mask >> i) & 1u) != 0; }

  template <std::size_t N>
  static bool all_finite(const T (&v)[N]) noexcept {
    T s = T(0);
    for (const T& e : v) s += e * T(0);  // ±0 for finite values, NaN otherwise
    return s == T(0);
  }

  T value(Ref r, T dflt) const noexcept {
    switch (r.kind) {
      case RefKind::kParam:
        return p_.v[r.index];
      case RefKind::kInput:
        return u_.v[r.index];
      default:
        return dflt;
    }
  }

  /// k of an orifice or poppet: the given k, or Cd·A·√(2/ρ).
  T flow_coefficient(const Element& el) const noexcept {
    if (el.r[kK].kind != RefKind::kNone) return value(el.r[kK], T(0));
    return value(el.r[kCd], T(0)) * value(el.r[kArea], T(0)) * std::sqrt(T(2) / value(el.r[kRho], T(1)));
  }

  /// Resolves every number from the parameters and inputs (set_inputs' work).
  void resolve() noexcept {
    const Description& c = *c_;
    bool ok = true;
    p_env_ = value(c.pressure_max, T(0));
    w_env_ = value(c.speed_max, T(0));
    ok = ok && p_env_ > T(0) && w_env_ > T(0);
    for (int k = 0; k < kZ; ++k) {
      fixed_z_[k] = T(0);
      inv_mass_[k] = T(0);
    }
    for (int i = 0; i < c.n_nodes; ++i) {
      const Node& n = c.nodes[i];
      if (n.kind == NodeKind::kBoundary) {
        fixed_z_[i] = value(n.pressure, T(0));
      } else {
        const T K = n.K.kind != RefKind::kNone ? value(n.K, T(0)) : value(n.beta, T(0)) / value(n.volume, T(0));
        inv_mass_[i] = K;
        ok = ok && K > T(0) && K < std::numeric_limits<T>::infinity();
      }
    }
    for (int s = 0; s < c.n_shafts; ++s) {
      const Shaft& sh = c.shafts[s];
      if (sh.driven) {
        fixed_z_[kNodes + s] = value(sh.speed, T(0));
      } else {
        const T J = value(sh.J, T(0));
        ok = ok && J > T(0);
        inv_mass_[kNodes + s] = T(1) / J;
      }
    }
    for (int e = 0; e < c.n_elements; ++e) ok = resolve_element(c.elements[e], coef_[e]) && ok;
    values_ok_ = ok && all_finite(fixed_z_) && all_finite(inv_mass_);
    rest();
    bound();
  }

  bool resolve_element(const Element& el, Coeffs<T>& k) noexcept {
    for (T& v : k.c) v = T(0);
    T* c = k.c;
    switch (el.kind) {
      case ElementKind::kOrifice: {
        const T s = value(el.r[kOpening], T(1));
        const T open = el.opening_sign < 0 ? -s : s;
        c[0] = flow_coefficient(el) * (open > T(0) ? open : T(0));
        c[1] = value(el.r[kDpT], T(kDefaultDpT));
        return std::isfinite(c[0]) && c[0] >= T(0) && c[1] > T(0);
      }
      case ElementKind::kPoppet: {
        c[0] = flow_coefficient(el);
        c[1] = value(el.r[kDpT], T(kDefaultDpT));
        c[2] = value(el.r[kCrack], T(0));
        c[4] = value(el.r[kFull], T(0));
        c[3] = T(1) / (c[4] - c[2]);
        return std::isfinite(c[0]) && c[0] >= T(0) && c[1] > T(0) && c[4] > c[2] && std::isfinite(c[3]);
      }
      case ElementKind::kLaminar: {
        const T R = value(el.r[kR], T(0));
        c[0] = T(1) / R;
        return R > T(0);
      }
      case ElementKind::kFlowSource:
        c[0] = value(el.r[kQ], T(0));
        return true;
      case ElementKind::kMachine:
        c[0] = value(el.r[kFraction], T(1)) * value(el.r[kD], T(0));
        return true;
      case ElementKind::kCompPump: {
        PumpCurveParams<T> pp;
        pp.Q0 = value(el.r[kQ0], T(0));
        pp.R = value(el.r[kRleak], T(0));
        pp.Pc = value(el.r[kPc], T(0));
        pp.Pk = value(el.r[kPk], T(0));
        pp.Pmax = value(el.r[kPmax], T(0));
        PumpCurve<T> curve;
        if (!curve.make(pp)) return false;
        c[0] = pp.Q0;
        c[1] = -T(1) / pp.R;
        c[2] = pp.Pc;
        c[3] = pp.Pk;
        c[4] = curve.q_cutin();
        c[5] = curve.parabola();
        c[6] = curve.q_knee();
        c[7] = -curve.q_knee() / (pp.Pmax - pp.Pk);
        return true;
      }
      case ElementKind::kTorque:
        c[0] = value(el.r[kTau], T(0));
        return true;
      case ElementKind::kFriction:
        c[0] = value(el.r[kC], T(0));
        return c[0] >= T(0);
    }
    return false;
  }

  /// rest_z_: boundaries and driven speeds, free shafts at 0, volumes at the pressure of
  /// the first boundary reached breadth-first through conductive elements.
  void rest() noexcept {
    const Description& c = *c_;
    bool seen[kExtent<kNodes>];
    std::uint8_t queue[kExtent<kNodes>];
    int head = 0, tail = 0;
    for (int k = 0; k < kZ; ++k) rest_z_[k] = fixed_z_[k];
    for (int i = 0; i < c.n_nodes; ++i) {
      seen[i] = c.nodes[i].kind == NodeKind::kBoundary;
      if (seen[i]) queue[tail++] = static_cast<std::uint8_t>(i);
    }
    while (head < tail) {
      const int i = queue[head++];
      for (int k = inc_start_[i]; k < inc_start_[i + 1]; ++k) {
        const Element& el = c.elements[inc_[k]];
        if (el.kind != ElementKind::kOrifice && el.kind != ElementKind::kLaminar && el.kind != ElementKind::kPoppet) continue;
        const int o = el.a == i ? el.b : el.a;
        if (seen[o]) continue;
        seen[o] = true;
        rest_z_[o] = rest_z_[i];
        queue[tail++] = static_cast<std::uint8_t>(o);
      }
    }
    for (int j = 0; j < n_stiff_; ++j) guess_[j] = rest_z_[stiff_[j]];
  }

  /// q_bound_: contraction_bound() for the current values.
  void bound() noexcept {
    q_bound_ = T(0);
    for (int j = 0; j < n_stiff_; ++j) {
      T g_min, g_fix, s_max;
      conductance_bounds(stiff_[j], c_->stiff_mask, g_min, g_fix, s_max);
      const T q = g_fix > T(0) ? s_max / (s_max + g_fix) : std::numeric_limits<T>::infinity();
      q_bound_ = std::fmax(q_bound_, q);
    }
  }

  /// z from the fixed values and the states (stiff nodes left at their last values).
  void fill(const State& x, T (&z)[kExtent<kZ>]) const noexcept {
    for (int k = 0; k < kZ; ++k) z[k] = fixed_z_[k];
    for (int s = 0; s < n_states_; ++s) z[z_of_state_[s]] = x[s];
  }

  /// Net inflow into node i [m³/s] at z, and its derivative by z[i] in slope (≤ 0).
  T node_balance(int i, const T (&z)[kExtent<kZ>], T& slope) const noexcept {
    T F = T(0), dF = T(0);
    for (int k = inc_start_[i]; k < inc_start_[i + 1]; ++k) {
      const int e = inc_[k];
      const Element& el = c_->elements[e];
      const T w = el.shaft >= 0 ? z[kNodes + el.shaft] : T(0);
      const Flow<T> f = element_flow(el.kind, coef_[e], z[el.a], z[el.b], w);
      if (el.a == i) {
        F -= f.q;
        dF -= f.dpa;
      } else {
        F += f.q;
        dF += f.dpb;
      }
    }
    slope = dF;
    return F;
  }

  /// Solves node i's balance for z[i], the other entries held: in closed form when its
  /// elements are one orifice and flows linear in z[i] (quasi_steady.hpp
  /// solve_node_orifice, the terms summed in incidence order as the compiled kernels sum
  /// them), else and wherever that does not apply by the safeguarded Newton.
  bool solve_node(int i, T (&z)[kExtent<kZ>]) const noexcept {
    int orifice = -1;
    bool linear = true;
    T lin = T(0), B = T(0);
    for (int k = inc_start_[i]; k < inc_start_[i + 1] && linear; ++k) {
      const int e = inc_[k];
      const Element& el = c_->elements[e];
      const T c0 = coef_[e].c[0];
      switch (el.kind) {
        case ElementKind::kOrifice:
          linear = orifice < 0;
          orifice = e;
          break;
        case ElementKind::kLaminar:
          lin += c0 * z[el.a == i ? el.b : el.a];
          B += c0;
          break;
        case ElementKind::kMachine:
          if (el.a == i) {
            lin -= c0 * z[kNodes + el.shaft];
          } else {
            lin += c0 * z[kNodes + el.shaft];
          }
          break;
        case ElementKind::kFlowSource:
          if (el.a == i) {
            lin -= c0;
          } else {
            lin += c0;
          }
          break;
        default:
          linear = false;
      }
    }
    if (linear && orifice >= 0) {
      const Element& o = c_->elements[orifice];
      T root;
      if (solve_node_orifice(z[i], z[o.a == i ? o.b : o.a], coef_[orifice].c[0], coef_[orifice].c[1], lin, B, root)) {
        return true;
      }
    }
    return solve_node_newton(z[i], p_env_, [&](T p, T& dF) {
      z[i] = p;
      return node_balance(i, z, dF);
    });
  }

  /// The quasi-steady solve: Gauss–Seidel sweeps over the stiff nodes from the last
  /// solution (quasi_steady.hpp), kept as the next start when it converged.
  bool solve_stiff(T (&z)[kExtent<kZ>]) const noexcept {
    if (n_stiff_ == 0) return true;
    for (int j = 0; j < n_stiff_; ++j) z[stiff_[j]] = guess_[j];
    const bool conv = gauss_seidel(p_env_, stiff_coupled_, [&](Sweep<T>& w) {
      for (int j = 0; j < n_stiff_; ++j) {
        const int i = stiff_[j];
        w.node(z[i], [&] { return solve_node(i, z); });
      }
    });
    if (conv) {
      for (int j = 0; j < n_stiff_; ++j) guess_[j] = z[stiff_[j]];
    }
    return conv;
  }

  /// The states' rates [Pa/s, rad/s²]: unknowns_net()'s rows of the states only, each summed
  /// in element order (so the same bits), without the stiff nodes'.
  State rates(const T (&z)[kExtent<kZ>]) const noexcept {
    State d = State::Zero();
    for (int s = 0; s < n_states_; ++s) {
      const int zs = z_of_state_[s];
      T g = T(0);
      if (zs < kNodes) {
        for (int k = inc_start_[zs]; k < inc_start_[zs + 1]; ++k) {
          const int e = inc_[k];
          const Element& el = c_->elements[e];
          const T w = el.shaft >= 0 ? z[kNodes + el.shaft] : T(0);
          const T q = element_flow(el.kind, coef_[e], z[el.a], z[el.b], w).q;
          if (el.a == zs) {
            g -= q;
          } else {
            g += q;
          }
        }
      } else {
        for (int k = shaft_start_[zs - kNodes]; k < shaft_start_[zs - kNodes + 1]; ++k) {
          const int e = shaft_inc_[k];
          const Element& el = c_->elements[e];
          T da, db, dw;
          const T pa = has_ports(el.kind) ? z[el.a] : T(0);
          const T pb = has_ports(el.kind) ? z[el.b] : T(0);
          g += element_torque(el.kind, coef_[e], pa, pb, z[zs], da, db, dw);
        }
      }
      d[s] = inv_mass_[zs] * g;
    }
    return d;
  }

  Output outputs_at(const T (&z)[kExtent<kZ>]) const noexcept {
    Output y = Output::Zero();
    if (c_ == nullptr) return y;
    for (int ch = 0; ch < c_->n_channels; ++ch) {
      const Channel& h = c_->channels[ch];
      if (h.kind == ChannelKind::kPressure) {
        y[ch] = z[h.index];
      } else if (h.kind == ChannelKind::kSpeed) {
        y[ch] = z[kNodes + h.index];
      } else {
        const Element& el = c_->elements[h.index];
        const T w = el.shaft >= 0 ? z[kNodes + el.shaft] : T(0);
        y[ch] = element_flow(el.kind, coef_[h.index], z[el.a], z[el.b], w).q;
      }
    }
    return y;
  }

  /// Reduced Jacobian jr = M⁻¹(G_xx − G_xa·G_aa⁻¹·G_ax) at z (a: stiff nodes) and the local
  /// contraction factor q of the stiff block. G_aa is strictly diagonally dominant
  /// wherever the solve contracts, so it is eliminated without pivoting.
  /// Out of line on firmware: inlined into slowest_rate it would add its kU × kU scratch
  /// to the eigenvalue problem's frame (the C API's create stack).
  HSTMON_LEAN_NOINLINE void reduced_jacobian(const T (&z)[kExtent<kZ>], T (&jr)[kExtent<kStates>][kExtent<kStates>],
                                             T& q) const noexcept {
    // Only the unknowns' rows and columns (kU × kU, not kZ × kZ), and the elimination in
    // place on the stiff rows (G_aa, G_ax), which nothing reads afterwards: firmware stack.
    T G[kExtent<kU>][kExtent<kU>];
    unknowns_jacobian(z, G);
    T inv_mass[kExtent<kStates>] = {};
    states_inv_mass(inv_mass);
    // A capacity with no room for a stiff node says so at compile time (GCC would otherwise
    // warn that the stiff block, never read then, may be uninitialised).
    const int n_stiff = kU > kStates ? n_stiff_ : 0;
    schur_reduce(G, stiff_u_, n_stiff, state_u_, n_states_, inv_mass, jr, q);
  }

  const Description* c_ = nullptr;
  CircuitError error_ = CircuitError::kUnbound;
  Params p_{};
  Inputs u_{};
  int n_states_ = 0, n_stiff_ = 0, n_unknowns_ = 0;
  bool stiff_coupled_ = false;
  bool values_ok_ = false;
  std::int8_t state_of_z_[kExtent<kZ>]{};
  std::int8_t unknown_of_z_[kExtent<kZ>]{};  ///< index among the unknowns, or −1 (boundary, driven shaft)
  std::uint8_t stiff_u_[kExtent<kU>]{};       ///< unknown index of the j-th stiff node
  std::int8_t el_unknown_[kExtent<kElements>][3]{};  ///< unknown index of port a, port b, shaft (−1 fixed)
  std::uint8_t shaft_start_[kExtent<Cap::kShafts + 1>]{};  ///< shaft s's torque elements: shaft_inc_[start[s], start[s+1])
  std::uint8_t shaft_inc_[kExtent<kElements>]{};
  std::uint8_t state_u_[kExtent<kStates>]{};  ///< unknown index of state s
  std::uint8_t z_of_state_[kExtent<kStates>]{};
  std::uint8_t stiff_[kExtent<kNodes>]{};
  std::uint8_t unknown_z_[kExtent<kU>]{};
  std::uint16_t inc_start_[kExtent<kNodes + 1>]{};
  std::uint8_t inc_[kExtent<2 * kElements>]{};
  Coeffs<T> coef_[kExtent<kElements>]{};
  T inv_mass_[kExtent<kZ>]{};  ///< K [Pa/m³] per volume node, 1/J [1/(kg·m²)] per free shaft, else 0
  T fixed_z_[kExtent<kZ>]{};   ///< boundary pressures [Pa], driven speeds [rad/s], else 0
  T rest_z_[kExtent<kZ>]{};    ///< the rest state as a full vector
  T p_env_{}, w_env_{};
  T q_bound_{};
  mutable T guess_[kExtent<kNodes>]{};  ///< last quasi-steady pressures (warm start) [Pa]
};

}  // namespace hstmon::circuit
