#pragma once
/// @file load_bins.hpp
/// Rows of a log grouped by load regime (the PRV setting kp): one group per distinct
/// setting when there are at most six, else tertiles. Shared by the channel and the
/// equation decompositions so both speak of the same regimes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace hstmon::gap::detail {

struct LoadBin {
  std::string label;
  std::vector<char> mask;  ///< per row of kp
};

inline std::vector<LoadBin> load_bins(const std::vector<double>& kp) {
  const std::size_t n = kp.size();
  std::vector<double> kps;
  for (double v : kp) {
    if (std::none_of(kps.begin(), kps.end(), [&](double q) { return std::fabs(q - v) <= 1e-3 * std::fabs(v); }))
      kps.push_back(v);
    if (kps.size() > 6) break;
  }
  std::vector<std::pair<double, double>> bins;  // [lo, hi]
  const bool distinct = kps.size() <= 6;
  if (distinct) {
    std::sort(kps.begin(), kps.end());
    for (double v : kps) bins.emplace_back(v * (1 - 1e-3), v * (1 + 1e-3));
  } else {
    std::vector<double> s = kp;
    std::sort(s.begin(), s.end());
    const double q1 = s[s.size() / 3], q2 = s[2 * s.size() / 3];
    bins = {{s.front(), q1}, {std::nextafter(q1, 1e300), q2}, {std::nextafter(q2, 1e300), s.back()}};
  }
  std::vector<LoadBin> out;
  for (std::size_t b = 0; b < bins.size(); ++b) {
    LoadBin lb;
    lb.mask.resize(n);
    for (std::size_t k = 0; k < n; ++k) lb.mask[k] = kp[k] >= bins[b].first && kp[k] <= bins[b].second;
    char buf[96];
    if (distinct) {
      const bool many = bins.size() > 1;
      std::snprintf(buf, sizeof buf, "kp=%.4g%s", 0.5 * (bins[b].first + bins[b].second),
                    b == 0 && many ? " (heaviest load)" : (b + 1 == bins.size() && many ? " (lightest load)" : ""));
    } else {
      std::snprintf(buf, sizeof buf, "kp in [%.4g, %.4g]", bins[b].first, bins[b].second);
    }
    lb.label = buf;
    out.push_back(std::move(lb));
  }
  return out;
}

}  // namespace hstmon::gap::detail
