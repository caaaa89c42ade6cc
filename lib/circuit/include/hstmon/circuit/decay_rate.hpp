#pragma once
/// @file decay_rate.hpp
/// The slowest decay rate of linear dynamics dx/dt = J·x, min over J's eigenvalues λ of
/// −Re λ, read off J's real Schur form. Eigen's EigenSolver computes the same eigenvalues
/// from the same form (bit for bit: the 2×2 blocks' real parts are taken as it takes them)
/// but carries copies of the form and the eigenvalue vector besides: on a controller its
/// frame alone was 728 B of the monitor's stack after an input change.

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace hstmon::circuit {

/// min −Re λ over the eigenvalues of the square matrix J [1/s when J is in 1/s]; 0 when
/// some mode does not decay (Re λ ≥ 0), the Schur reduction fails or an eigenvalue is not
/// finite.
template <class Matrix>
typename Matrix::Scalar slowest_decay_rate(const Matrix& J) noexcept {
  using T = typename Matrix::Scalar;
  const Eigen::RealSchur<Matrix> schur(J, /*computeU=*/false);
  if (schur.info() != Eigen::Success) return T(0);
  const Matrix& S = schur.matrixT();
  const Eigen::Index n = S.cols();
  T rate = std::numeric_limits<T>::infinity();
  for (Eigen::Index i = 0; i < n;) {
    if (i == n - 1 || S(i + 1, i) == T(0)) {  // a real eigenvalue
      if (!std::isfinite(S(i, i))) return T(0);
      rate = std::min(rate, -S(i, i));
      ++i;
      continue;
    }
    // A complex pair: Re λ = S(i+1,i+1) + p as EigenSolver forms it; Im λ = ±z, scaled
    // against overflow, is checked finite as EigenSolver checks it.
    const T p = T(0.5) * (S(i, i) - S(i + 1, i + 1));
    const T t0 = S(i + 1, i), t1 = S(i, i + 1);
    const T scale = std::max(std::abs(p), std::max(std::abs(t0), std::abs(t1)));
    const T z = scale * std::sqrt(std::abs((p / scale) * (p / scale) + (t0 / scale) * (t1 / scale)));
    const T re = S(i + 1, i + 1) + p;
    if (!std::isfinite(re) || !std::isfinite(z)) return T(0);
    rate = std::min(rate, -re);
    i += 2;
  }
  return rate > T(0) && std::isfinite(rate) ? rate : T(0);
}

}  // namespace hstmon::circuit
