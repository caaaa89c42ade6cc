#pragma once
/// @file crosscheck.hpp
/// Cross-check of the temporal causal graph's predictions against the nonlinear model:
/// each catalogue parameter is stepped up and down at several operating points, and the
/// sign of the steady-state change (ThesisCircuitModel::steady_state), of the first
/// non-zero derivative at 0+ (full model, Taylor terms from thesis_derivative and its
/// Jacobian), and of the early deviation read from the stiff reference simulator are
/// compared with the qualitative TCG, the weighted TCG and the linearised steady states.

#include <array>
#include <string>
#include <vector>

#include "hstmon/fault_signature.hpp"
#include "hstmon_fdi/thesis_forward.hpp"
#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

/// One operating point of the cross-check: Table 2.2 with kp scaled.
struct OperatingCase {
  std::string name;  ///< "light", "nominal", "heavy"
  double kp_factor;  ///< kp / 4.41e-8 [-]
};

/// light (kp × 1.6), nominal, heavy (kp × 0.65).
std::vector<OperatingCase> default_operating_cases();

/// Options of the cross-check.
struct CrosscheckOptions {
  std::vector<OperatingCase> cases = default_operating_cases();
  double t_early = 1e-3;       ///< time after the fault at which the reference deviation is read [s]
  int max_order = 6;           ///< highest derivative examined [-]
  double ss_zero_rel = 1e-12;  ///< relative steady-state change read as zero [-]
};

/// The readings and predictions for one channel.
struct ChannelCheck {
  QualSign ss;            ///< nonlinear steady-state change
  double ss_rel;          ///< that change relative to the nominal value [-]
  QualSign slope0;        ///< nonlinear: sign of the first non-zero derivative at 0+
  int order0;             ///< nonlinear: its order (−1: none up to max_order)
  QualSign early;         ///< stiff reference: sign of the deviation at t_early (kQualAny: below its resolution)
  QualSign tcg_slope;     ///< qualitative TCG: slope (kQualAny: opposite paths)
  int tcg_order;          ///< qualitative TCG: order (−1: no path)
  QualSign tcg_weighted;  ///< TCG with operating-point gains: slope
  QualSign lin_secant;    ///< steady-state sign of the Fig. 2.14 graph (secant resistances)
  QualSign lin_tangent;   ///< steady-state sign of the graph with tangent valve gains
};

/// One fault at one operating point.
struct CrosscheckRow {
  std::string case_name;
  std::string fault;                    ///< "kp-"
  double step;                          ///< relative step applied [-]
  std::array<ChannelCheck, 4> channel;  ///< ThesisChannel order
};

/// Runs the cross-check for every catalogue parameter, both directions, every case.
/// @throws std::runtime_error if a steady state or a reference run fails
std::vector<CrosscheckRow> run_crosscheck(const CrosscheckOptions& opt = CrosscheckOptions{});

}  // namespace hstmon::fdi
