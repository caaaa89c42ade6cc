#pragma once
/// @file pump_curve.hpp
/// Flow–pressure characteristic of a pressure-compensated pump (seed 001, §4.1, Fig. 4):
///   region 1 (P ≤ Pc):      Q = Q0 − P/R               linear, slope from pump leakage
///   region 2 (Pc < P ≤ Pk): Q = Q1 − (P−Pc)/R − c·(P−Pc)²   parabolic fall (compensator acting)
///   region 3 (P > Pk):      Q = Q2 + S3·(P − Pk)        almost linear fall to Q = 0 at Pmax
/// The printed fits (equations 9–11) do not join up, so the curve is built from five
/// physical numbers and made C¹ at Pc and Pk with Q(Pmax) = 0; docs/equations.md shows
/// the derivation. Beyond Pmax region 3 continues (a stiff, monotone fall).

#include <cmath>

namespace hstmon {

/// The five numbers that define the curve.
template <typename T>
struct PumpCurveParams {
  T Q0 = T(150.0 * 1.33e-6);  ///< ideal flow ωs·Dmp at zero pressure [m³/s]
  T R = T(6e11);              ///< leakage resistance, region-1 slope −1/R [Pa·s/m³]
  T Pc = T(75e5);             ///< compensator cut-in pressure, end of region 1 [Pa]
  T Pk = T(87e5);             ///< knee between the parabolic and the linear fall [Pa]
  T Pmax = T(90e5);           ///< dead-head pressure, Q(Pmax) = 0 [Pa]
};

/// The curve with its derived coefficients. Construct with PumpCurve::make().
template <typename T>
class PumpCurve {
 public:
  /// Builds the curve; returns false (curve unchanged) unless 0 < Pc < Pk < Pmax, R > 0,
  /// Q0 > 0 and the resulting region-2 parabola is concave with Q > 0 at the knee.
  bool make(const PumpCurveParams<T>& p) noexcept {
    if (!(p.Q0 > T(0) && p.R > T(0) && p.Pc > T(0) && p.Pk > p.Pc && p.Pmax > p.Pk)) return false;
    const T s1 = -T(1) / p.R;
    const T q1 = p.Q0 + s1 * p.Pc;
    const T d = p.Pk - p.Pc;
    const T l3 = p.Pmax - p.Pk;
    const T q2 = (q1 + T(0.5) * s1 * d) / (T(1) + T(0.5) * d / l3);
    const T s3 = -q2 / l3;
    const T c = (s1 - s3) / (T(2) * d);
    if (!(q1 > T(0) && q2 > T(0) && c >= T(0))) return false;
    p_ = p;
    s1_ = s1;
    q1_ = q1;
    q2_ = q2;
    s3_ = s3;
    c_ = c;
    return true;
  }

  /// Delivered flow at pump pressure P [Pa] → [m³/s].
  T flow(T P) const noexcept {
    if (P <= p_.Pc) return p_.Q0 + s1_ * P;
    if (P <= p_.Pk) {
      const T e = P - p_.Pc;
      return q1_ + s1_ * e - c_ * e * e;
    }
    return q2_ + s3_ * (P - p_.Pk);
  }

  /// dQ/dP at pressure P [m³/(s·Pa)], ≤ 0 everywhere.
  T slope(T P) const noexcept {
    if (P <= p_.Pc) return s1_;
    if (P <= p_.Pk) return s1_ - T(2) * c_ * (P - p_.Pc);
    return s3_;
  }

  const PumpCurveParams<T>& params() const noexcept { return p_; }
  T q_cutin() const noexcept { return q1_; }  ///< flow at Pc [m³/s]
  T q_knee() const noexcept { return q2_; }   ///< flow at Pk [m³/s]
  T parabola() const noexcept { return c_; }  ///< region-2 curvature c [m³/(s·Pa²)]

 private:
  PumpCurveParams<T> p_{};
  T s1_{}, q1_{}, q2_{}, s3_{}, c_{};
};

}  // namespace hstmon
