/// @file load_profile.cpp
#include "hstmon_sim/load_profile.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace hstmon::sim {

std::optional<LoadShape> load_shape_from(std::string_view name) {
  if (name == "constant") return LoadShape::kConstant;
  if (name == "steps") return LoadShape::kSteps;
  if (name == "ramp") return LoadShape::kRamp;
  if (name == "sine") return LoadShape::kSine;
  return std::nullopt;
}

const char* to_string(LoadShape s) noexcept {
  switch (s) {
    case LoadShape::kConstant: return "constant";
    case LoadShape::kSteps: return "steps";
    case LoadShape::kRamp: return "ramp";
    case LoadShape::kSine: return "sine";
  }
  return "?";
}

namespace {

// Triangle wave in [0, 1], 0 at x = 0, 1 at x = 1, 0 at x = 2 (x in legs).
double triangle(double x) {
  const double m = std::fmod(x, 2.0);
  return m <= 1.0 ? m : 2.0 - m;
}

}  // namespace

std::vector<std::pair<double, double>> load_setpoints(const LoadProfile& p, double kp0, double duration) {
  if (!(p.period > 0.0 && p.update > 0.0 && kp0 > 0.0 && p.lo <= p.hi && p.lo > 0.0 && p.level > 0.0)) {
    throw std::invalid_argument("load profile: need period, update, kp0, lo, level > 0 and lo <= hi");
  }
  std::vector<std::pair<double, double>> out;
  auto push = [&](double t, double f) {
    if (t >= duration) return;
    if (!out.empty() && out.back().second == f * kp0) return;
    out.emplace_back(t, f * kp0);
  };
  switch (p.shape) {
    case LoadShape::kConstant: push(0.0, p.level); break;
    case LoadShape::kSteps: {
      std::mt19937_64 rng(p.seed);
      std::uniform_real_distribution<double> draw(p.lo, p.hi);
      push(0.0, p.level);
      const double t1 = p.first >= 0.0 ? p.first : p.period;
      for (double t = t1; t < duration; t += p.period) push(t, draw(rng));
      break;
    }
    case LoadShape::kRamp:
    case LoadShape::kSine: {
      const double t1 = p.first >= 0.0 ? p.first : 0.0;
      // The ramp starts at `level` (clamped into [lo, hi]) heading up.
      const double f0 = std::fmin(std::fmax(p.level, p.lo), p.hi);
      const double x0 = p.hi > p.lo ? (f0 - p.lo) / (p.hi - p.lo) : 0.0;
      auto factor = [&](double t) {
        const double s = t - t1;
        if (p.shape == LoadShape::kSine) {
          return 0.5 * (p.lo + p.hi) + 0.5 * (p.hi - p.lo) * std::sin(2.0 * 3.14159265358979323846 * s / p.period);
        }
        return p.lo + (p.hi - p.lo) * triangle(x0 + s / p.period);
      };
      push(0.0, t1 > 0.0 ? (p.shape == LoadShape::kRamp ? f0 : 0.5 * (p.lo + p.hi)) : factor(0.0));
      const auto n = static_cast<long>(std::ceil((duration - t1) / p.update));
      for (long k = t1 > 0.0 ? 0 : 1; k < n; ++k) {
        const double t = t1 + static_cast<double>(k) * p.update;
        push(t, factor(t));
      }
      break;
    }
  }
  return out;
}

}  // namespace hstmon::sim
