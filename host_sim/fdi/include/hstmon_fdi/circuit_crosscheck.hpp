#pragma once
/// @file circuit_crosscheck.hpp
/// Cross-check of a circuit's temporal causal graph (circuit_tcg.hpp) against the nonlinear
/// engine: every circuit parameter and input on the graph is stepped up and down at several
/// operating points; the sign of each sensor channel's steady-state change (engine steady
/// solve), and of its first non-zero time derivative at 0+ (Δf at the steady state, then
/// Jacobian powers, through ∂y/∂x for flow channels), are compared with the qualitative TCG, the weighted TCG and the
/// linearised graph's steady state. The circuit counterpart of crosscheck.hpp (which also
/// reads the thesis's stiff reference; this one does not).

#include <string>
#include <utility>
#include <vector>

#include "hstmon/fault_signature.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::fdi {

/// One operating point: the nominal values with some inputs or parameters scaled.
struct CircuitCase {
  std::string name;                                  ///< "nominal", "kp x 1.6"
  std::vector<std::pair<std::string, double>> scale; ///< (input or parameter name, factor [-])
};

/// nominal, and the first input with a non-zero nominal value × 0.8 and × 1.2.
std::vector<CircuitCase> default_circuit_cases(const circuit_tools::LoadedCircuit& c);

/// Options of the circuit cross-check.
struct CircuitCrosscheckOptions {
  std::vector<CircuitCase> cases;  ///< empty: default_circuit_cases
  double step = 0.1;               ///< relative fault step [-]
  std::vector<std::pair<std::string, double>> steps;  ///< per-fault steps overriding `step` [-]
  /// The rows checked, by name with their sign ("kp-"); empty: both signs of every fault on
  /// the graph. A row's readings do not depend on which others are checked.
  std::vector<std::string> faults;
  int max_order = 6;               ///< highest derivative examined [-]
  /// Steady change relative to the channel's value read as zero [-]: the thesis rig's
  /// smallest real effect (Ripl ±10 % on Pmi) is ~1e-12; K and J move nothing (< 1e-15 after
  /// the Newton polish of the steady solve).
  double ss_zero_rel = 1e-14;
};

/// Readings and predictions for one channel.
struct CircuitChannelCheck {
  QualSign ss = kQualZero;            ///< nonlinear steady-state change
  double ss_rel = 0.0;                ///< that change relative to the nominal value [-]
  QualSign slope0 = kQualZero;        ///< nonlinear first non-zero derivative at 0+
  int order0 = -1;                    ///< its order (0: a jump, a flow sensor on the faulty element; −1: none up to max_order)
  QualSign tcg_slope = kQualZero;     ///< qualitative TCG slope (kQualAny: opposite paths)
  int tcg_order = -1;                 ///< qualitative TCG order
  QualSign tcg_weighted = kQualZero;  ///< TCG with operating-point gains: slope
  QualSign lin = kQualZero;           ///< linearised graph's steady state
};

/// One fault at one operating point.
struct CircuitCrosscheckRow {
  std::string case_name;
  std::string fault;                          ///< "kp-"
  double step = 0.0;                          ///< relative step applied [-]
  std::vector<CircuitChannelCheck> channel;   ///< sensor channel order
};

/// The cross-check of one circuit.
struct CircuitCrosscheck {
  std::vector<std::string> channels;       ///< sensor names
  std::vector<CircuitCrosscheckRow> rows;
  std::vector<std::string> notes;          ///< faults skipped and why, parameters and inputs not on the graph
};

/// Runs the cross-check.
/// @throws std::invalid_argument for an unknown name in a case, std::runtime_error if an
///         operating point has no steady state
CircuitCrosscheck run_circuit_crosscheck(const circuit_tools::LoadedCircuit& c, const CircuitCrosscheckOptions& opt);

/// Agreement counts over every fault × channel × case reading.
struct CircuitAgreement {
  int readings = 0;   ///< fault × channel × case
  int magnitude = 0;  ///< qualitative TCG slope (the thesis's magnitude) = nonlinear steady sign
  int linear = 0;     ///< linearised graph's steady sign = nonlinear steady sign
  int slope = 0;      ///< qualitative TCG slope agrees with the 0+ slope (? agrees)
  int order = 0;      ///< qualitative TCG order = 0+ order
  int weighted = 0;   ///< weighted TCG slope = 0+ slope
};

/// Counts the agreements of a cross-check.
CircuitAgreement circuit_agreement(const CircuitCrosscheck& x);

}  // namespace hstmon::fdi
