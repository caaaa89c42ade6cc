#pragma once
/// @file discover.hpp
/// Beyond the library: the located balance equation's imbalance regressed on a
/// physics-structured set of candidate terms (constant, ωm, tanh(ωm/ω0), node pressure,
/// pressure differences, orifice flows, pressure × speed, derivatives, time since start)
/// by sequentially thresholded least squares (STLSQ), fitted on the fit log and the
/// sparsest model that does (nearly) as well as the best chosen on the check log.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_gap/equations.hpp"

namespace hstmon::gap {

/// One term of a discovered imbalance model: imbalance ≈ Σ coefficient · form.
struct DiscoveredTerm {
  std::string form;         ///< "p_pp", "tanh(w_m/0.5)", "kp*sqrt(p_pp-Pbp)", …
  std::string unit;         ///< SI unit of the coefficient
  double coefficient = 0;
  double std_error = 0;     ///< with the residuals' autocorrelation (effective sample size)
};

/// A proposed missing term in one balance equation.
struct Discovery {
  std::string equation;               ///< "flow:p_pp"
  std::vector<DiscoveredTerm> terms;  ///< largest contribution first
  double shrink_fit = 0;              ///< share of the equation imbalance above noise removed, fit log (shrink.hpp)
  double shrink_check = 0;            ///< same on the check log (the judge)
  double rms_w_before_check = 0, rms_w_after_check = 0;
  std::string reading;                ///< in words: "a flow loss at the loading-pump node ∝ Ppp: leakage R = …"
  std::vector<ImbalanceTerm> model_terms;  ///< the terms for the simulator (ExtendedModel::terms)
  /// The nominal model with the terms, simulated on the check log (state equations
  /// flow:p_pp and torque:w_m only; simulated false otherwise): the channels' gap.
  bool simulated = false;
  double model_shrink_check = 0;      ///< share of the check log's gap above noise removed, channels pooled (shrink.hpp)
  std::array<double, kChannels> channel_rms_w_after_check{};  ///< per channel, RMS/noise (NaN: absent)
};

/// Proposes the missing term of equation `eq` (EquationId) from fit-log and check-log ARR
/// data; nullopt when the equation is not available or nothing shrinks the check log.
std::optional<Discovery> discover(const ArrData& fit, const ArrData& check, int eq);

}  // namespace hstmon::gap
