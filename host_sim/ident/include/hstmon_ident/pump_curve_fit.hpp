#pragma once
/// @file pump_curve_fit.hpp
/// Fit of pump B's 3-region flow–pressure curve (seed 001 §4.1; hstmon::PumpCurve, C¹ by
/// construction) to (P, Q) data by Levenberg–Marquardt.
///
/// Fitted in ln Q0, ln R, ln Pc, ln(Pk − Pc), ln(Pmax − Pk): every parameter stays positive
/// and 0 < Pc < Pk < Pmax holds by construction. Residuals Q_model(P_i) − Q_i, unweighted
/// (one flow meter). Starts: a line through the lowest-pressure half gives Q0 and R, the
/// zero crossing of the high-pressure end gives Pmax; a small grid of Pc/Pmax and Pk/Pmax
/// ratios is tried and the best fit kept (the region boundaries make the problem
/// multi-modal). Statistics as in least_squares.hpp: s² = SSR/(n − 5), Student-t
/// intervals on the log-parameters. Data must reach into region 3 (P close to Pmax) for
/// Pk and Pmax to be identifiable; the result reports which are not.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hstmon/pump_curve.hpp"
#include "hstmon_ident/least_squares.hpp"

namespace hstmon::ident {

/// One point of the pump characteristic.
struct FlowPressureSample {
  double p = 0.0;  ///< pump pressure [Pa]
  double q = 0.0;  ///< delivered flow [m³/s]
};

/// Result of fit_pump_curve.
struct PumpCurveFit {
  std::optional<std::string> error;         ///< set on bad data or a failed fit
  PumpCurveParams<double> params{};         ///< estimate (Q0 [m³/s], R [Pa·s/m³], Pc, Pk, Pmax [Pa])
  std::array<double, 5> se{};               ///< standard errors in the same units (delta method)
  std::array<double, 5> ci_lo{};            ///< lower interval ends (Q0, R, Pc, Pk, Pmax)
  std::array<double, 5> ci_hi{};            ///< upper interval ends
  std::array<bool, 5> identifiable{};       ///< interval within a factor e of the estimate
  DenseMatrix correlation;                  ///< of the five fitted log-quantities
  double rms = 0.0;                         ///< RMS flow residual [m³/s]
  std::size_t n = 0;                        ///< samples
  double condition = 0.0;                   ///< of the column-scaled Jacobian [-]
  std::string lm_status;                    ///< LM stop reason
  /// True on success.
  bool ok() const noexcept { return !error.has_value(); }
};

/// Names of the five parameters in result order: "Q0", "R", "Pc", "Pk", "Pmax".
const std::array<const char*, 5>& pump_curve_param_names();

/// Fits the curve to the samples (≥ 8, finite, P ≥ 0, spanning at least two regions).
/// @param start  optional start values (else derived from the data as described above)
PumpCurveFit fit_pump_curve(const std::vector<FlowPressureSample>& samples,
                            const std::optional<PumpCurveParams<double>>& start = std::nullopt,
                            double confidence = 0.95);

}  // namespace hstmon::ident
