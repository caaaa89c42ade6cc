#pragma once
/// @file qual.hpp
/// Qualitative sign algebra of the temporal causal graph: values −, 0, +, and ? (ambiguous:
/// two causal paths of opposite sign meet). Uses the firmware's hstmon::QualSign so that
/// predictions drop straight into the generated signature table.

#include "hstmon/fault_signature.hpp"

namespace hstmon::fdi {

/// Sign of an integer as a QualSign (−1, 0, +1).
constexpr QualSign qual_of(int s) noexcept { return s > 0 ? kQualPlus : (s < 0 ? kQualMinus : kQualZero); }

/// Product of a definite sign (±1) and a qualitative value; ? stays ?.
constexpr QualSign qual_mul(int sign, QualSign q) noexcept {
  if (q == kQualAny || q == kQualZero) return q;
  return qual_of(sign * static_cast<int>(q));
}

/// Qualitative sum: 0 is neutral, equal signs stay, opposite signs (or any ?) give ?.
constexpr QualSign qual_add(QualSign a, QualSign b) noexcept {
  if (a == kQualZero) return b;
  if (b == kQualZero) return a;
  if (a == kQualAny || b == kQualAny || a != b) return kQualAny;
  return a;
}

/// One-character symbol: '+', '-', '0', '?'.
constexpr char qual_symbol(QualSign q) noexcept {
  switch (q) {
    case kQualPlus: return '+';
    case kQualMinus: return '-';
    case kQualZero: return '0';
    default: return '?';
  }
}

/// Sign of v, with |v| ≤ zero_tol read as 0 [units of v].
constexpr QualSign qual_from_value(double v, double zero_tol) noexcept {
  return v > zero_tol ? kQualPlus : (v < -zero_tol ? kQualMinus : kQualZero);
}

/// Agreement of a prediction with a reading: ? agrees with anything.
constexpr bool qual_agrees(QualSign predicted, QualSign observed) noexcept {
  return predicted == kQualAny || observed == kQualAny || predicted == observed;
}

}  // namespace hstmon::fdi
