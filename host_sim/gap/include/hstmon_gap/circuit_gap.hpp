#pragma once
/// @file circuit_gap.hpp
/// `hstmon gap --circuit`: where a circuit's model and its machine disagree, which
/// unmodelled effect explains it, and how far the gap shrinks once that effect is added —
/// judged on a withheld log. The thesis rig's gap tool (gap.hpp) has a library of effects
/// written for that rig; this one derives its candidates from any circuit file:
///  - leak(<node>): a laminar leakage from a volume node to the lowest-pressure boundary;
///  - friction(<shaft>): extra viscous friction on a free shaft;
///  - torque_loss(<shaft>): a constant torque loss on a free shaft (Coulomb-like at a
///    steady speed of one sign);
///  - offset(<channel>): a transducer zero offset;
///  - parameter(<name>): a parameter of the file off beyond its stated uncertainty (then
///    `hstmon identify --circuit` says by how much); left out where a leak or friction
///    candidate is the same law between the same nodes.
/// Each candidate has one magnitude, fitted on the fit log's steady operating points
/// (circuit_fit.hpp: held inputs less the settle time) by a scan of its logarithm and a
/// golden-section refinement (an offset: the mean residual); the check log's operating
/// points then say how much of the gap it removes. There is no gap when, on both logs, the
/// steady residual lies within the noise and the parameters' stated uncertainty
/// (circuit_judge.hpp); too few steady settings give `insufficient_data`. The verdict names
/// an effect only when it removes at least half of the check log's residual and clearly
/// more than the runner-up; two close candidates are named "ambiguous" only when the best
/// leaves the check log within noise and uncertainty, else no single candidate explains it.
///
/// Besides the candidates, and whatever the verdict: the circuit's balance equations on the
/// measured signals (circuit_equations.hpp; imbalance = the model's net inflow or torque −
/// accumulation, a loss the model lacks > 0), the located one (largest RMS/noise above 3,
/// fit log, else check log), and the located equation's missing term found by STLSQ on
/// candidate terms built from the circuit (circuit_discover.hpp).

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_gap/circuit_discover.hpp"
#include "hstmon_gap/equations.hpp"

namespace hstmon::gap {

/// A candidate effect of a circuit.
struct CircuitEffect {
  enum class Kind { kLeak, kFriction, kTorqueLoss, kOffset, kParam };
  Kind kind = Kind::kLeak;
  int index = 0;        ///< node, shaft, channel or parameter index
  std::string name;     ///< "leak(Pmi)", "friction(motor)", …
  double reference = 1; ///< magnitude scale: conductance [m³/(s·Pa)], damping [N·m·s/rad], torque [N·m]; a parameter's ε
};

/// One candidate's result.
struct CircuitEffectResult {
  CircuitEffect effect;
  double magnitude = 0.0;   ///< fitted: conductance, damping, torque [SI], offset [channel SI] or a parameter's relative change [-]
  double rms_fit = 0.0;     ///< residual RMS on the fit log with the effect [σ]
  double rms_check = 0.0;   ///< on the check log [σ]
  double z_check = 0.0;     ///< what remains on the check log beyond noise and parameter uncertainty [σ]
  bool ok = false;          ///< the fit and the check evaluated
};

/// Result of circuit_gap().
struct CircuitGapResult {
  std::size_t fit_points = 0, check_points = 0;
  double rms_fit = 0.0, rms_check = 0.0;    ///< without any effect [σ]
  std::vector<std::string> channels;        ///< channel names
  std::vector<double> mean_fit;             ///< mean residual per channel on the fit log [σ] (where the gap lies)
  std::vector<double> noise_fit, noise_check;  ///< σ per channel each log is weighed in [SI] (circuit_judge.hpp)
  double z_fit = 0.0, z_check = 0.0;        ///< gap beyond noise and parameter uncertainty [σ]; none when both ≤ 2
  std::string evidence_missing;             ///< what the logs lack (verdict insufficient_data), else empty
  std::vector<CircuitEffectResult> ranked;  ///< best check RMS first
  std::string verdict;                      ///< the named effect, "none", "insufficient_data", "ambiguous: A or B" or "unexplained"
  std::vector<std::string> notes;
  std::optional<std::string> error;
  /// Where, by balance equation: per equation of the circuit (circuit_equations() order)
  /// its statistics on each log (SI; rms_w = RMS of imbalance/propagated noise).
  std::vector<EquationStats> equations_fit, equations_check;
  /// Per equation: what a log lacks for it ("p_mi (not in the log)", "pressure of Pmo (no
  /// sensor)"; the fit log's, else the check log's), "" when available on both.
  std::vector<std::string> equations_missing;
  std::string located_equation;               ///< the located equation's name (fit log, else check log), or ""
  std::optional<CircuitDiscovery> discovery;  ///< the located equation's missing term, if one shrinks the check log
};

/// The candidates of circuit c (see the file comment).
std::vector<CircuitEffect> circuit_effects(const circuit_tools::LoadedCircuit& c);

/// The unit of effect e's magnitude: "m3/(s*Pa)", "N*m*s/rad", "N*m", the channel's SI
/// unit for an offset, "-" for a parameter's relative change.
const char* effect_unit(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e);

/// c with effect e of magnitude m added (an offset leaves the circuit unchanged).
circuit_tools::LoadedCircuit with_effect(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m);

/// Options of circuit_gap().
struct CircuitGapOptions {
  /// The candidates tried: each a candidate's name ("leak(p_b)") or a kind (leak, friction,
  /// torque_loss, offset, parameter); empty = all of them.
  std::vector<std::string> effects;
  /// Each candidate fitted together with the circuit's uncertain parameters, each move
  /// charged against its stated uncertainty (the allowance's δ*, param_allowance.hpp); the
  /// check log is then judged at the fit log's parameter values (`--refit-nominal`).
  bool refit_nominal = false;
};

/// The candidates of c that `effects` names (CircuitGapOptions::effects), in c's order.
/// @param error  out: for a name that matches no candidate, a sentence naming it and listing
///               c's candidates and kinds (nothing is chosen then); else empty
std::vector<CircuitEffect> chosen_effects(const circuit_tools::LoadedCircuit& c, const std::vector<std::string>& effects,
                                          std::string& error);

/// Fits every candidate (or those `o` names) on `fit`, judges it on `check`. A name in
/// `o.effects` that matches no candidate sets `error`.
CircuitGapResult circuit_gap(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& fit,
                             const circuit_tools::CircuitLog& check, const CircuitGapOptions& o = {});

}  // namespace hstmon::gap
