#pragma once
/// @file validation.hpp
/// Validation of an identified model in the form of the thesis's Table 2.3: per signal the
/// average and the RMS relative error of the model's steady state against the measured
/// one, over the operating points. Sign as in the thesis: negative when the simulated
/// value is below the experimental one.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "hstmon_ident/operating_points.hpp"

namespace hstmon::ident {

/// One row of the Table 2.3 validation.
struct ValidationRow {
  std::string signal;      ///< "Pmi", "Pmo", "Ppp", "RPM"
  std::size_t points = 0;  ///< operating points compared
  double avg_error_pct = 0.0;  ///< mean of 100·(model − measured)/measured [%] (negative: model below data)
  double rms_error_pct = 0.0;  ///< √mean of the squared relative errors [%]
};

/// Table 2.3 rows (Pmi, Pmo, Ppp, RPM) comparing predicted against measured point means;
/// channels that are not measured, or measured as 0, are left out.
std::vector<ValidationRow> validation_table(const std::vector<OperatingPoint>& points,
                                            const std::vector<std::array<double, 4>>& predicted);

}  // namespace hstmon::ident
