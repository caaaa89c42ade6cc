#pragma once
/// @file gaussian.hpp
/// Seeded standard-normal source. std::normal_distribution is implementation-defined
/// (libstdc++ and libc++ give different sequences), so the transform is done here:
/// Box–Muller on 53-bit uniforms from std::mt19937_64, whose output sequence the C++
/// standard fixes. Sequences are identical across standard libraries (up to the last
/// ulp of std::log / std::cos / std::sin).

#include <cstdint>
#include <random>

namespace hstmon::sim {

/// Deterministic N(0, 1) generator.
class GaussianSource {
 public:
  /// @param seed  seed of the underlying std::mt19937_64
  explicit GaussianSource(std::uint64_t seed) : engine_(seed) {}

  /// Next standard-normal variate [-].
  double next();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool have_spare_ = false;
};

}  // namespace hstmon::sim
