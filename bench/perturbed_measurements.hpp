#pragma once
/// @file perturbed_measurements.hpp
/// Measurements fed to every benchmark variant: the steady-state outputs with a small
/// deterministic perturbation (a few hundred Pa on the pressures, 0.05 rad/s on the speed),
/// all four channels valid. A power-of-two ring, so the index is a mask.

#include <array>
#include <cstddef>
#include <cstdint>

namespace hstmon_bench {

/// Obs: an hstmon::Observer on a four-output model (three pressures [Pa], then a speed [rad/s]).
template <class Obs>
struct PerturbedMeasurements {
  using T = typename Obs::T;
  static constexpr std::size_t kSize = 1024;
  std::array<typename Obs::Measurement, kSize> m{};

  explicit PerturbedMeasurements(const typename Obs::Output& y0) noexcept {
    std::uint32_t lcg = 12345u;
    for (auto& e : m) {
      e.y = y0;
      for (int i = 0; i < 4; ++i) {
        lcg = lcg * 1664525u + 1013904223u;
        const T d = static_cast<T>(static_cast<double>(lcg >> 8) / 16777216.0 - 0.5);  // [-0.5, 0.5)
        e.y[i] += (i == 3 ? T(0.05) : T(400)) * d;
      }
      e.valid = 0x0F;
    }
  }
  const typename Obs::Measurement& operator[](std::uint64_t i) const noexcept {
    return m[static_cast<std::size_t>(i) & (kSize - 1)];
  }
};

}  // namespace hstmon_bench
