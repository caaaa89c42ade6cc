/// @file validation.cpp
/// Table 2.3: average and RMS relative error per signal.
#include "hstmon_ident/validation.hpp"

#include <cmath>

namespace hstmon::ident {

std::vector<ValidationRow> validation_table(const std::vector<OperatingPoint>& points,
                                            const std::vector<std::array<double, 4>>& predicted) {
  static const char* const kNames[4] = {"Pmi", "Pmo", "Ppp", "RPM"};
  std::vector<ValidationRow> rows;
  for (std::size_t c = 0; c < 4; ++c) {
    ValidationRow r;
    r.signal = kNames[c];
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t w = 0; w < points.size() && w < predicted.size(); ++w) {
      const double meas = points[w].y[c];
      const double model = predicted[w][c];
      if (!std::isfinite(meas) || !std::isfinite(model) || meas == 0.0) continue;
      const double e = 100.0 * (model - meas) / meas;
      sum += e;
      sum2 += e * e;
      ++r.points;
    }
    if (r.points == 0) continue;
    r.avg_error_pct = sum / static_cast<double>(r.points);
    r.rms_error_pct = std::sqrt(sum2 / static_cast<double>(r.points));
    rows.push_back(r);
  }
  return rows;
}

}  // namespace hstmon::ident
