#pragma once
/// @file laws.hpp
/// The flow and torque law of each element kind, with its slopes, from coefficients
/// resolved once per input change (CircuitModel::set_inputs). Every flow element is
/// monotone: Q(pa, pb) never falls as pa rises or as pb falls. That is what makes the
/// quasi-steady solve of stiff nodes a contraction (docs/circuits.md, "Why the solve
/// contracts"); the conductance bounds below are its numbers.

#include <cmath>
#include <limits>

#include "hstmon/circuit/circuit.hpp"
#include "hstmon/circuit/inlining.hpp"
#include "hstmon/signed_root.hpp"

namespace hstmon::circuit {

/// Number of resolved coefficients per element.
constexpr int kCoeffs = 8;

/// Resolved coefficients, by kind (SI units):
///  orifice:   c[0] k·opening [m³/(s·√Pa)], c[1] ΔP_t [Pa]
///  poppet:    c[0] k [m³/(s·√Pa)], c[1] ΔP_t [Pa], c[2] crack [Pa], c[3] 1/(full − crack) [1/Pa], c[4] full [Pa]
///  laminar:   c[0] 1/R [m³/(s·Pa)]
///  source:    c[0] Q [m³/s]
///  machine:   c[0] ε·D [m³/rad]
///  comp pump: c[0] Q0 [m³/s], c[1] s1 = −1/R, c[2] Pc [Pa], c[3] Pk [Pa], c[4] Q1 [m³/s],
///             c[5] curvature [m³/(s·Pa²)], c[6] Q2 [m³/s], c[7] s3 [m³/(s·Pa)]
///  torque:    c[0] τ [N·m];  friction: c[0] c [N·m·s/rad]
template <typename T>
struct Coeffs {
  T c[kCoeffs]{};
};

/// An element's flow a→b [m³/s] and its partial derivatives.
template <typename T>
struct Flow {
  T q{};    ///< flow from port a to port b [m³/s]
  T dpa{};  ///< ∂Q/∂pa [m³/(s·Pa)], ≥ 0
  T dpb{};  ///< ∂Q/∂pb [m³/(s·Pa)], ≤ 0
  T dw{};   ///< ∂Q/∂ω [m³/rad] (machines)
};

/// True for kinds that exchange flow between their two ports.
constexpr bool has_ports(ElementKind k) noexcept { return k != ElementKind::kTorque && k != ElementKind::kFriction; }

/// True for kinds that act on a shaft.
constexpr bool has_shaft(ElementKind k) noexcept {
  return k == ElementKind::kMachine || k == ElementKind::kTorque || k == ElementKind::kFriction;
}

// Each law writes its flow and slopes into f, which the caller has value-initialised (a
// law leaves the slopes it does not have at 0): one Flow object for a switch over kinds.

/// Orifice: Q = c0·sq(pa − pb) [m³/s], sq the regularised signed root.
template <typename T>
HSTMON_CIRCUIT_LAW void orifice_flow(const Coeffs<T>& k, T pa, T pb, Flow<T>& f) noexcept {
  T s;
  f.q = k.c[0] * signed_root(pa - pb, k.c[1], s);
  f.dpa = k.c[0] * s;
  f.dpb = -f.dpa;
}

/// Poppet (relief or check valve): the orifice law through an opening that rises
/// linearly from the cracking to the full-open pressure difference [m³/s].
template <typename T>
HSTMON_CIRCUIT_LAW void poppet_flow(const Coeffs<T>& k, T pa, T pb, Flow<T>& f) noexcept {
  const T* c = k.c;
  const T dp = pa - pb;
  if (dp > c[2]) {
    const T x_raw = (dp - c[2]) * c[3];
    const bool full = x_raw >= T(1);
    const T x = full ? T(1) : x_raw;
    T s;
    const T r = signed_root(dp, c[1], s);
    f.q = c[0] * x * r;
    f.dpa = c[0] * (x * s + (full ? T(0) : c[3] * r));
    f.dpb = -f.dpa;
  }
}

/// Laminar leakage: Q = (pa − pb)/R [m³/s].
template <typename T>
HSTMON_CIRCUIT_LAW void laminar_flow(const Coeffs<T>& k, T pa, T pb, Flow<T>& f) noexcept {
  f.q = k.c[0] * (pa - pb);
  f.dpa = k.c[0];
  f.dpb = -k.c[0];
}

/// Flow source: Q = q whatever the pressures [m³/s].
template <typename T>
HSTMON_CIRCUIT_LAW void source_flow(const Coeffs<T>& k, Flow<T>& f) noexcept {
  f.q = k.c[0];
}

/// Pump or motor: Q = ε·D·ω [m³/s].
template <typename T>
HSTMON_CIRCUIT_LAW void machine_flow(const Coeffs<T>& k, T w, Flow<T>& f) noexcept {
  f.q = k.c[0] * w;
  f.dw = k.c[0];
}

/// Pressure-compensated pump: delivery from a (suction) to b at the pressure rise
/// pb − pa, pump_curve.hpp's three-region law [m³/s].
template <typename T>
HSTMON_CIRCUIT_LAW void comp_pump_flow(const Coeffs<T>& k, T pa, T pb, Flow<T>& f) noexcept {
  const T* c = k.c;
  const T P = pb - pa;
  T q, s;
  if (P <= c[2]) {
    q = c[0] + c[1] * P;
    s = c[1];
  } else if (P <= c[3]) {
    const T e = P - c[2];
    q = c[4] + c[1] * e - c[5] * e * e;
    s = c[1] - T(2) * c[5] * e;
  } else {
    q = c[6] + c[7] * (P - c[3]);
    s = c[7];
  }
  f.q = q;
  f.dpb = s;
  f.dpa = -s;
}

/// Flow of one element at port pressures pa, pb [Pa] and shaft speed w [rad/s]: the
/// kind's law above (the compiled models call those directly).
template <typename T>
inline Flow<T> element_flow(ElementKind kind, const Coeffs<T>& k, T pa, T pb, T w) noexcept {
  Flow<T> f;
  switch (kind) {
    case ElementKind::kOrifice:
      orifice_flow(k, pa, pb, f);
      break;
    case ElementKind::kPoppet:
      poppet_flow(k, pa, pb, f);
      break;
    case ElementKind::kLaminar:
      laminar_flow(k, pa, pb, f);
      break;
    case ElementKind::kFlowSource:
      source_flow(k, f);
      break;
    case ElementKind::kMachine:
      machine_flow(k, w, f);
      break;
    case ElementKind::kCompPump:
      comp_pump_flow(k, pa, pb, f);
      break;
    case ElementKind::kTorque:
    case ElementKind::kFriction:
      break;
  }
  return f;
}

/// Torque of an element on its shaft [N·m] at port pressures pa, pb [Pa] and speed w
/// [rad/s]; dpa, dpb [N·m/Pa] and dw [N·m·s/rad] receive its slopes. 0 for kinds without
/// a shaft.
template <typename T>
inline T element_torque(ElementKind kind, const Coeffs<T>& k, T pa, T pb, T w, T& dpa, T& dpb, T& dw) noexcept {
  dpa = dpb = dw = T(0);
  switch (kind) {
    case ElementKind::kMachine:
      dpa = k.c[0];
      dpb = -k.c[0];
      return k.c[0] * (pa - pb);
    case ElementKind::kTorque:
      return -k.c[0];
    case ElementKind::kFriction:
      dw = -k.c[0];
      return -k.c[0] * w;
    default:
      return T(0);
  }
}

/// Largest conductance |∂Q/∂p| an element can have at either port [m³/(s·Pa)], over all
/// pressures: the regularised root's slope peaks at 5/(4√ΔP_t) at zero.
template <typename T>
inline T max_conductance(ElementKind kind, const Coeffs<T>& k) noexcept {
  const T* c = k.c;
  switch (kind) {
    case ElementKind::kOrifice:
      return c[0] * T(1.25) / std::sqrt(c[1]);
    case ElementKind::kPoppet:
      // x·sq'(Δp) + x'·sq(Δp) with x ≤ 1 and sq(Δp) ≤ √full while x is still rising.
      return c[0] * (T(1.25) / std::sqrt(c[1]) + c[3] * std::sqrt(std::fabs(c[4])));
    case ElementKind::kLaminar:
      return std::fabs(c[0]);
    case ElementKind::kCompPump: {
      const T s2 = c[1] - T(2) * c[5] * (c[3] - c[2]);
      return std::fmax(std::fmax(-c[1], -s2), -c[7]);
    }
    default:
      return T(0);
  }
}

/// Range of an element's conductance g = ∂Q/∂pa = −∂Q/∂pb [m³/(s·Pa)] while its pressure
/// difference pa − pb stays within [dp_lo, dp_hi] [Pa] (the stiffness certificate's box,
/// stiffness_certificate.hpp): exact for orifices (the regularised slope falls with |Δp|),
/// laminar leaks and the compensated pump's three regions; for a poppet 0 while it stays
/// shut, else from 0 to max_conductance. Machines and sources: 0 (their flow does not
/// depend on pressure; ∂Q/∂ω is their constant c[0]).
template <typename T>
inline void conductance_range(ElementKind kind, const Coeffs<T>& k, T dp_lo, T dp_hi, T& g_lo, T& g_hi) noexcept {
  const T* c = k.c;
  g_lo = g_hi = T(0);
  switch (kind) {
    case ElementKind::kOrifice: {
      const T far = std::fmax(std::fabs(dp_lo), std::fabs(dp_hi));
      const T near = (dp_lo <= T(0) && dp_hi >= T(0)) ? T(0) : std::fmin(std::fabs(dp_lo), std::fabs(dp_hi));
      g_lo = c[0] * signed_root_slope(far, c[1]);
      g_hi = c[0] * signed_root_slope(near, c[1]);
      break;
    }
    case ElementKind::kPoppet:
      if (dp_hi > c[2]) g_hi = max_conductance(kind, k);
      break;
    case ElementKind::kLaminar:
      g_lo = g_hi = std::fabs(c[0]);
      break;
    case ElementKind::kCompPump: {
      // g = −s(P) at the pressure rise P = pb − pa ∈ [−dp_hi, −dp_lo]: constant in regions 1
      // and 3, linear in region 2, so its extremes lie at the ends of each region met.
      const T P_lo = -dp_hi, P_hi = -dp_lo;
      T lo = std::numeric_limits<T>::infinity(), hi = -lo;
      const auto take = [&](T g) {
        lo = std::fmin(lo, g);
        hi = std::fmax(hi, g);
      };
      if (P_lo <= c[2]) take(-c[1]);
      if (P_hi > c[2] && P_lo <= c[3]) {
        take(-(c[1] - T(2) * c[5] * (std::fmax(P_lo, c[2]) - c[2])));
        take(-(c[1] - T(2) * c[5] * (std::fmin(P_hi, c[3]) - c[2])));
      }
      if (P_hi > c[3]) take(-c[7]);
      g_lo = lo;
      g_hi = hi;
      break;
    }
    default:
      break;
  }
}

/// Smallest conductance an element keeps at either port while |pa − pb| ≤ p_env [Pa]
/// (the circuit's envelope) [m³/(s·Pa)]: what a node can count on whatever the state.
/// Poppets can close and machines and sources do not depend on pressure: 0.
template <typename T>
inline T min_conductance(ElementKind kind, const Coeffs<T>& k, T p_env) noexcept {
  const T* c = k.c;
  switch (kind) {
    case ElementKind::kOrifice:
      // The regularised slope falls monotonically with |Δp|: its least is at p_env.
      return c[0] * signed_root_slope(p_env, c[1]);
    case ElementKind::kLaminar:
      return std::fabs(c[0]);
    case ElementKind::kCompPump:
      return -c[1];  // the curve is concave: region 1's leakage slope is its least steep
    default:
      return T(0);
  }
}

}  // namespace hstmon::circuit
