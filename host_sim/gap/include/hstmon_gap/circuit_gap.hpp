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
///  - offset(<channel>): a transducer zero offset.
/// Each candidate has one magnitude, fitted on the fit log's steady operating points
/// (circuit_fit.hpp: held inputs less the settle time) by a scan of its logarithm and a
/// golden-section refinement (an offset: the mean residual); the check log's operating
/// points then say how much of the gap it removes. The verdict names an effect only when
/// it removes at least half of the check log's residual and clearly more than the
/// runner-up; otherwise it says that no single candidate explains the gap.

#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"

namespace hstmon::gap {

/// A candidate effect of a circuit.
struct CircuitEffect {
  enum class Kind { kLeak, kFriction, kTorqueLoss, kOffset };
  Kind kind = Kind::kLeak;
  int index = 0;        ///< node, shaft or channel index
  std::string name;     ///< "leak(Pmi)", "friction(motor)", …
  double reference = 1; ///< magnitude scale: conductance [m³/(s·Pa)], damping [N·m·s/rad], torque [N·m]
};

/// One candidate's result.
struct CircuitEffectResult {
  CircuitEffect effect;
  double magnitude = 0.0;   ///< fitted: conductance, damping, torque [SI] or offset [channel SI]
  double rms_fit = 0.0;     ///< residual RMS on the fit log with the effect [σ]
  double rms_check = 0.0;   ///< on the check log [σ]
  bool ok = false;          ///< the fit and the check evaluated
};

/// Result of circuit_gap().
struct CircuitGapResult {
  std::size_t fit_points = 0, check_points = 0;
  double rms_fit = 0.0, rms_check = 0.0;    ///< without any effect [σ]
  std::vector<std::string> channels;        ///< channel names
  std::vector<double> mean_fit;             ///< mean residual per channel on the fit log [σ] (where the gap lies)
  std::vector<CircuitEffectResult> ranked;  ///< best check RMS first
  std::string verdict;                      ///< the named effect, "none" (no gap) or "unexplained"
  std::vector<std::string> notes;
  std::optional<std::string> error;
};

/// The candidates of circuit c (see the file comment).
std::vector<CircuitEffect> circuit_effects(const circuit_tools::LoadedCircuit& c);

/// c with effect e of magnitude m added (an offset leaves the circuit unchanged).
circuit_tools::LoadedCircuit with_effect(const circuit_tools::LoadedCircuit& c, const CircuitEffect& e, double m);

/// Fits every candidate on `fit`, judges it on `check`.
CircuitGapResult circuit_gap(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& fit,
                             const circuit_tools::CircuitLog& check);

}  // namespace hstmon::gap
