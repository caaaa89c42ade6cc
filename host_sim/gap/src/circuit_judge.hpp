#pragma once
/// @file circuit_judge.hpp
/// What `gap --circuit` weighs a log's steady gap against (docs/gap.md, "Noise",
/// "Parameter uncertainty", "Evidence"): each channel's noise read off the log's operating
/// points (at least the sensor's stated σ), the circuit's parameter uncertainty
/// (circuit_uncertainty: the parameter file's, else 2 % on what moves a steady state), and
/// the least evidence a verdict needs.
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "param_allowance.hpp"

namespace hstmon::gap::detail {

/// A log's operating points with the noise per channel their residuals are weighed in [SI].
struct PointSet {
  std::vector<ident::CircuitOperatingPoint> points;
  std::vector<double> sigma;
};

/// The operating points of log and their channels' noise: noise_floor.hpp's estimate over
/// the points' rows, at least the sensor's stated σ.
PointSet circuit_point_set(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitLog& log);

/// Residuals (mean − model)/σ per point and measured channel for parameter values p.
/// @return false when some point has no steady state
bool point_residuals(const circuit_tools::LoadedCircuit& c, const host::HostCircuitModel::Params& p, const PointSet& s,
                     std::vector<double>& res);

/// The parameters c holds uncertain (index, relative uncertainty ε > 0).
std::vector<std::pair<int, double>> uncertain_params(const circuit_tools::LoadedCircuit& c);

/// The columns parameter_allowance weighs r against: per uncertain parameter (in
/// uncertain_params order), the change of r under +ε of it [noise units]; zeros where the
/// move leaves some point without a steady state.
std::vector<std::vector<double>> allowance_columns(const circuit_tools::LoadedCircuit& c, const PointSet& s,
                                                   const std::vector<double>& r);

/// The allowance of residuals r (point_residuals at c's values) for c's uncertain parameters.
Allowance circuit_allowance(const circuit_tools::LoadedCircuit& c, const PointSet& s, const std::vector<double>& r);

/// c's parameter values moved by δ (Allowance::delta: per uncertain parameter, in units of
/// its ε): p_k·(1 + ε_k·δ_k).
host::HostCircuitModel::Params moved_params(const circuit_tools::LoadedCircuit& c, const std::vector<double>& delta);

/// What the log's points lack for a verdict (evidence.hpp), or "".
std::string circuit_evidence(const std::string& which, const PointSet& s);

}  // namespace hstmon::gap::detail
