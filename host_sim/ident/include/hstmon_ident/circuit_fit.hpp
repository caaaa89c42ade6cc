#pragma once
/// @file circuit_fit.hpp
/// `hstmon identify --circuit`: named parameters of any circuit fitted to the steady
/// operating points of its logs, by Levenberg–Marquardt (least_squares.hpp) on the
/// engine's steady states — the thesis's nonlinear regression (Table 2.2) for a circuit
/// from a file.
///
/// Operating points (circuit_points.cpp): stretches of a log over which every logged input
/// holds (within 0.5 % of its value or 8 of its own noise σ, from successive differences:
/// a measured speed scatters) and the outputs are steady, less their first 5 slowest time
/// constants of the circuit at that point (the transient), at least `min_duration` long.
/// A held stretch whose outputs step (an event the log does not record: 0.05 s block
/// means, a split beyond 8 standard errors and 3 of the sensor's σ) is split there, each side
/// settling again, with a note; a piece whose outputs still trend by more than 3 σ over it
/// (a start from rest still settling) is left out, with a note.
/// Per point and measured channel the residual is (mean reading − model)/σ (measured − model), σ the sensor's
/// noise (1 % of the span without one). Parameters are fitted as ln(p/p₀), so they stay
/// positive and their steps are relative; standard errors come from the linearised
/// covariance at the optimum.
///
/// Setting per window (`setting_per_window`): for logs that do not record the input that
/// sets the load, each operating point gets its own value of that input ("window input"),
/// fitted together with the named parameters. A point is then a stretch where the logged
/// inputs hold, split where the outputs step (a new setting, said without a note). The
/// window inputs are fitted as ln(u/u₀) (u₀ the logged mean, else the nominal value; an
/// input whose u₀ is not positive in its own unit, u − u₀), from the same residuals; each moves only
/// its own point's residuals, so the Jacobian is built per block: one steady state per
/// point and window-input column (cost and memory linear in the points, not quadratic).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"

namespace hstmon::ident {

/// What makes a stretch of a log an operating point.
struct CircuitPointRules {
  double min_duration = 0.2;      ///< shortest steady stretch after the settle time [s]
  std::size_t min_samples = 1;    ///< fewest rows averaged into a point
  /// Every held stretch is steady from its first row (a DAS log recorded only at steady
  /// state): no settle time, no shortest duration, stretches of one row accepted.
  bool assume_steady = false;
  /// An output step inside a held stretch is a new setting of an input the log does not
  /// record (setting per window): split there without a note.
  bool steps_are_settings = false;
};

/// What to fit and how to find operating points.
struct CircuitFitOptions {
  std::vector<std::string> fit;   ///< names of the parameters to fit (named, not literal)
  double min_duration = 0.2;      ///< shortest steady stretch after the settle time [s]
  std::size_t min_samples = 1;    ///< fewest rows in an operating point
  bool assume_steady = false;     ///< CircuitPointRules::assume_steady
  /// Fewest distinct operating points (held input settings) the fit accepts; fewer is an
  /// error that says how many were found. 0: only the count the parameters need.
  std::size_t min_settings = 0;
  /// Each operating point gets its own value of the window inputs, fitted with `fit`
  /// (see the file comment).
  bool setting_per_window = false;
  /// The window inputs by name; empty: every input that no log has a column for (an
  /// error when the logs have a column for each: then name the one(s) that set the load).
  std::vector<std::string> window_inputs;
};

/// One operating point.
struct CircuitOperatingPoint {
  std::size_t log = 0;                ///< index in the logs given
  double t0 = 0.0, t1 = 0.0;          ///< the averaged stretch [s]
  std::size_t n = 0;                  ///< rows averaged
  std::vector<double> inputs;         ///< the held inputs [SI], by input index
  std::vector<double> mean;           ///< mean reading per channel [SI] (NaN where not logged)
  std::vector<double> before, after;  ///< mean reading − model per channel, in σ, at the start and the fit
  /// Per window input (CircuitFitResult::window_inputs): its start and fitted value [SI]
  /// and the standard error of the fitted value [SI] (∞ where not determined).
  std::vector<double> window_start, window_value, window_se;
};

/// Result of fit_circuit().
struct CircuitFitResult {
  std::vector<CircuitOperatingPoint> points;
  std::vector<std::string> names;        ///< fitted parameters
  std::vector<double> start, value;      ///< their values before and after [SI]
  std::vector<double> rel_se;            ///< standard error relative to the value [-]
  /// Per fitted parameter: the relative uncertainty the monitor's model bound takes after
  /// this fit [-] — the 95 % interval t·SE (at least kLeastUncertainty) where the points pin
  /// the value tighter than it was known, else the uncertainty it had (`pinned` false).
  std::vector<double> uncertainty, prior_uncertainty;
  std::vector<bool> pinned;
  /// Per fitted parameter: the move from the start lies beyond its 95 % interval (the data
  /// show it); false: the start is as consistent with the points as the fitted value.
  std::vector<bool> moved;
  /// Inputs fitted per operating point (CircuitFitOptions::setting_per_window); their
  /// values are in each point's window_value.
  std::vector<std::string> window_inputs;
  /// A parameter asked for that the points cannot determine (see fit_circuit): held at its
  /// start value, not fitted and not in `names`.
  struct Held {
    std::string name;
    double value = 0.0;  ///< the start value it keeps [SI]
    std::string why;     ///< a sentence: what the points show of it
  };
  std::vector<Held> held;
  /// No parameters were named: `names` and `held` are default_fit_parameters().
  bool default_fit = false;
  /// Correlation of the fitted parameters' estimates (ln p), names × names; NaN where a
  /// standard error is not finite. Empty when the fit has no statistics.
  std::vector<std::vector<double>> correlation;
  double rms_before = 0.0, rms_after = 0.0;  ///< RMS of the residuals [σ]
  std::string status;                    ///< the solver's stop reason
  std::vector<std::string> notes;
  std::optional<std::string> error;      ///< set when nothing could be fitted
};

/// The operating points of `logs` for circuit c (see the file comment); `before` and
/// `after` empty.
/// @param notes  out, optional: a sentence per held stretch split where an output stepped
std::vector<CircuitOperatingPoint> circuit_operating_points(const circuit_tools::LoadedCircuit& c,
                                                            const std::vector<circuit_tools::CircuitLog>& logs,
                                                            const CircuitPointRules& rules,
                                                            std::vector<std::string>* notes = nullptr);
/// The same with the default rules but for the shortest duration [s].
std::vector<CircuitOperatingPoint> circuit_operating_points(const circuit_tools::LoadedCircuit& c,
                                                            const std::vector<circuit_tools::CircuitLog>& logs,
                                                            double min_duration,
                                                            std::vector<std::string>* notes = nullptr);

/// How many distinct held input settings `points` cover (each input within the held-input
/// tolerance, 0.5 %, of a setting already counted).
std::size_t distinct_settings(const std::vector<CircuitOperatingPoint>& points);

/// Residuals (mean − model)/σ at every point and measured channel, in point then channel
/// order, for circuit c with parameter values p (c's inputs apart from those the points
/// hold). @return false when some point has no steady state
bool circuit_point_residuals(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel::Params& p,
                             const std::vector<CircuitOperatingPoint>& points, std::vector<double>& res);

/// Fits `o.fit` of circuit c to the operating points of `logs` (each read for c).
/// Before the fit, a parameter the points cannot determine is held at its start value
/// (CircuitFitResult::held): at the start values, with each point's residuals in the noise
/// of its mean (σ/√n: the noise model's s² = 1), its 95 % interval of ln p would span more
/// than a factor e each way
/// (the thesis regression's rule), or its column lies in the others' span (two parameters
/// that act only together, as Rf and Rbl in eq. 2.8). Of those, the one that moves the
/// fit least goes first (a leakage before a friction) and the test is repeated without it.
/// An undetermined direction left in the fit would let the solver wander along it, and the
/// parameter file would get whatever value it stopped at.
CircuitFitResult fit_circuit(const circuit_tools::LoadedCircuit& c, const std::vector<circuit_tools::CircuitLog>& logs,
                             const CircuitFitOptions& o);

/// The parameters `identify` fits when none are named: the losses and openings a data
/// sheet does not give and a healthy log can tell — each named, positive parameter that is
/// a laminar resistance or conductance, a viscous damping, an orifice coefficient or an
/// area. Displacements, volumes, inertias, stiffnesses and pressure settings come from the
/// data sheet. Those the points cannot determine are then held (fit_circuit).
std::vector<std::string> default_fit_parameters(const circuit_tools::LoadedCircuit& c);

/// The least relative uncertainty a fit hands the model bound [-]. A long healthy log can
/// pin a value to 0.01 %, but only at that log's oil temperature and wear: a floor keeps
/// the bound from shrinking to what one log happened to show, while staying far below
/// the 2 % default. A judgement, not a measurement; state a wider one in the parameter
/// file where the oil temperature varies.
inline constexpr double kLeastUncertainty = 0.001;

/// c at the fitted values, with the fitted parameters' `uncertainty` as stated ones: the
/// circuit the parameter file of fitted_values_json() loads to.
circuit_tools::LoadedCircuit fitted_circuit(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r);

/// A parameter file for c (docs/circuits.md's format) with the values of c overridden
/// by the fitted ones, every number in SI, and an "uncertainty" section: the fitted
/// parameters' `uncertainty` (commissioning: the monitor's bound follows what the healthy
/// log pinned) and every uncertainty c's own parameter file stated.
std::string fitted_values_json(const circuit_tools::LoadedCircuit& c, const CircuitFitResult& r);

}  // namespace hstmon::ident
