#pragma once
/// @file thesis_fit.hpp
/// Steady-state nonlinear regression of the thesis model (seed 000 §2.3.1).
///
/// Unknowns: kf, Rw = Rf + Rbl, one kp per PRV setting, and (only if the data can tell)
/// Rlkg and Ripl. Known: Dm, Dp (manual), Psupl, Ps, Pbp (logged or Table 2.2). J and K do
/// not enter a steady state.
///
/// Why Rf + Rbl is one parameter: both are viscous shaft losses multiplying ωm in eq. 2.8,
/// (Rf + Rbl)·ωm, and appear nowhere else, so any split with the same sum gives identical
/// outputs — only the sum is identifiable (the thesis lumps Rbl1 + Rbl2 the same way). The
/// written parameters split the fitted sum in the prior's Rf : Rbl ratio.
///
/// Residuals (output error): for each operating point w and measured channel c,
///   r = √n_w · (ŷ_c(θ; u_w, kp_s(w)) − ȳ_w,c) / σ_c,
/// ŷ the model's steady state (ThesisCircuitModel::steady_state), ȳ the window mean of n_w
/// samples, σ_c the channel's noise. Output error rather than equation error because the
/// noise is on the measurements: equation residuals (eqs. 2.5–2.8 evaluated at noisy
/// pressures) put the noise inside the square roots and the products — an errors-in-
/// variables problem whose least-squares estimates are biased and whose J-based intervals
/// are wrong. Weighting by σ_c makes pressures (Pa) and speed (rad/s) commensurate; the
/// √n_w factor makes the window-mean fit identical to a fit of every sample.
/// Parameters are fitted as logarithms (positivity; relative standard errors).
///
/// Statistics: covariance s²·(JᵀJ)⁻¹ with J the Jacobian of r in log-parameters and
/// s² = (Σr² + Σ_w,c SS_within/σ_c²)/(N − p), N the number of scalar samples: the residual
/// variance of the equivalent per-sample fit. Intervals: exp(ln θ̂ ± t(0.975, N − p)·SE).
/// A parameter is not identifiable when its column of J is rank deficient or its interval
/// spans more than a factor e each way (t·SE(ln θ) > max_log_halfwidth). Leakage
/// resistances found not identifiable stay at their prior and are reported so; a core
/// parameter (kf, Rw, any kp) not identifiable is an error (singular design).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_ident/least_squares.hpp"
#include "hstmon_ident/operating_points.hpp"
#include "hstmon_ident/validation.hpp"

namespace hstmon::ident {

/// Model steady-state outputs (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) for parameters p and inputs u.
/// Returns false if p or u are invalid or admit no steady state (kp = 0).
bool thesis_steady_outputs(const ThesisParams<double>& p, const ThesisInputs<double>& u, std::array<double, 4>& y);

/// Noise σ per channel of the thesis DAS (thesis_das_sensors(): white noise and 12-bit /
/// 1 rpm quantisation, σ² = σ_n² + q²/12) [Pa, Pa, Pa, rad/s]; the fallback when a log has
/// too few repeated samples to estimate it.
std::array<double, 4> thesis_das_noise();

/// Settings of fit_thesis_steady.
struct ThesisFitOptions {
  /// Known Dm, Dp; start values of kf, Rf + Rbl; leakage values used when not identifiable.
  ThesisParams<double> prior{};
  /// σ per channel [Pa, Pa, Pa, rad/s]; ≤ 0 or NaN: pooled within-window scatter if the
  /// windows give ≥ 3 degrees of freedom, else thesis_das_noise().
  std::array<double, 4> noise{};
  std::size_t min_settings = 3;     ///< fewest PRV settings (operating points) accepted
  double confidence = 0.95;         ///< level of the intervals
  double max_log_halfwidth = 1.0;   ///< identifiability limit on t·SE(ln θ) [-]
  bool try_leakage = true;          ///< test Rlkg, Ripl for identifiability and fit them if they are
};

/// Identifiability verdict of a parameter.
enum class ParamStatus {
  kEstimated,         ///< fitted; interval meaningful
  kNotIdentifiable,   ///< the data cannot determine it; held at its prior
};

/// One parameter of the fit.
struct ParameterEstimate {
  std::string name;        ///< "kf", "Rf+Rbl", "kp[1]" …, "Rlkg", "Ripl"
  std::string unit;        ///< SI unit
  double value = 0.0;      ///< estimate (or prior if not identifiable) [unit]
  double prior = 0.0;      ///< start / prior value [unit]
  double se = 0.0;         ///< standard error, delta method value·SE(ln θ) [unit]; ∞ if not identifiable
  double se_log = 0.0;     ///< standard error of ln θ [-]
  double ci_lo = 0.0;      ///< lower end of the interval exp(ln θ̂ − t·SE) [unit]
  double ci_hi = 0.0;      ///< upper end [unit]
  /// ‖∂r/∂ln θ‖·ln 2: how far (in noise σ, summed over all data) doubling θ moves the fit [-].
  double sensitivity = 0.0;
  ParamStatus status = ParamStatus::kEstimated;  ///< verdict
  std::string note;        ///< why not identifiable, in words
};

/// Result of fit_thesis_steady.
struct ThesisFitResult {
  std::optional<std::string> error;           ///< set on failure (no numbers are then valid)
  std::vector<ParameterEstimate> params;      ///< kf, Rf+Rbl, kp[1…S], Rlkg, Ripl
  std::vector<std::string> fitted;            ///< names of the fitted parameters (correlation order)
  DenseMatrix correlation;                    ///< correlation of the fitted ln-parameters
  double condition = 0.0;                     ///< condition number of the column-scaled J [-]
  std::size_t rank = 0;                       ///< numerical rank of J
  double s2 = 0.0;                            ///< residual variance factor (≈ 1 when σ is right) [-]
  double dof = 0.0;                           ///< N − p
  std::size_t samples = 0;                    ///< N, scalar samples behind the fit
  double t_value = 0.0;                       ///< Student-t quantile used for the intervals
  std::array<double, 4> noise{};              ///< σ used per channel [Pa, Pa, Pa, rad/s]
  std::array<std::string, 4> noise_source{};  ///< "option", "within-window scatter", "DAS default"
  std::string lm_status;                      ///< LM stop reason
  int evaluations = 0;                        ///< residual evaluations
  ThesisParams<double> fitted_params{};       ///< prior with the estimates written in (Rf, Rbl split)
  std::vector<double> kp;                     ///< kp per setting [m³/(s·√Pa)]
  std::vector<std::string> settings;          ///< setting labels (as given)
  std::vector<OperatingPoint> points;         ///< the data
  std::vector<std::array<double, 4>> predicted;  ///< model outputs per point at the estimate
  std::vector<ValidationRow> validation;      ///< Table 2.3 form
  std::vector<std::string> notes;             ///< remarks (assumed-steady points, …)
  /// True on success.
  bool ok() const noexcept { return !error.has_value(); }
};

/// Fits the thesis model to steady operating points (see file comment).
/// @param points    operating points; point.setting < settings.size()
/// @param settings  labels of the PRV settings
ThesisFitResult fit_thesis_steady(const std::vector<OperatingPoint>& points, const std::vector<std::string>& settings,
                                  const ThesisFitOptions& options = {});

}  // namespace hstmon::ident
