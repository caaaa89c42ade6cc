#pragma once
/// @file equations.hpp
/// Analytical redundancy relations of the thesis rig (bond-graph ARRs): the model's
/// balance equations evaluated on the measured signals alone — the flow balance at each
/// pressure node (Pmi, Pmo, Ppp) and the torque balance on the shaft (ωm). An effect the
/// model lacks unbalances the equation it enters and leaves the others at noise, so the
/// imbalances say *where* the gap is, whether or not a library effect names it.
/// Derivatives come from a local linear fit over a short window (the smoothing), and the
/// sensor noise is propagated through each equation to give its own noise level.
#include <array>
#include <string>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_gap/effects.hpp"

namespace hstmon::gap {

/// Balance equations, in this order: flow:p_mi, flow:p_mo, flow:p_pp, torque:w_m.
inline constexpr int kEquations = 4;
enum EquationId : int { kEqFlowMi = 0, kEqFlowMo = 1, kEqFlowPp = 2, kEqTorque = 3 };
/// "flow:p_mi", "flow:p_mo", "flow:p_pp", "torque:w_m".
const std::array<const char*, kEquations>& equation_names();
/// "m^3/s" for the flow balances, "N*m" for the torque balance.
const std::array<const char*, kEquations>& equation_units();

/// One log's smoothed signals at the rows where the ARRs are evaluated (the window lies
/// inside one input setting and leaves out the first row), and the imbalances there.
///
/// Imbalance = what the model says flows into the node (or drives the shaft) minus what
/// flows out (or brakes it), from the measured signals; positive: a loss the model lacks.
///   flow:p_mi   kf·√(Psupl − Pmi) − Dm·ωm − Pmi/Rlkg − (Pmi − Pmo)/Ripl
///   flow:p_mo   Dm·ωm + (Pmi − Pmo)/Ripl − Pmo/Rlkg − kf·√(Pmo − Ps)
///   flow:p_pp   Dp·ωm − kp·√(Ppp − Pbp) − (dPpp/dt)/K
///   torque:w_m  Dm·(Pmi − Pmo) − (Rf + Rbl)·ωm − Dp·(Ppp − Pbp) − J·dωm/dt
/// (√ is lib's regularised signed_root, the model's orifice law.)
struct ArrData {
  std::vector<std::size_t> rows;                  ///< log rows (window centres)
  std::vector<std::array<double, kChannels>> y;   ///< smoothed Pmi, Pmo, Ppp [Pa], ωm [rad/s]
  std::vector<double> dPpp, dw;                   ///< smoothed derivatives [Pa/s], [rad/s²]
  std::vector<double> Psupl, Ps, Pbp, kp, t_since_start;
  std::array<bool, kEquations> available{};       ///< the equation's channels are measured
  std::array<std::vector<double>, kEquations> r;      ///< imbalance (SI)
  std::array<std::vector<double>, kEquations> sigma;  ///< its propagated noise (SI)
  int half_window = 0;                            ///< smoothing half-width [samples]
};

/// Evaluates the ARRs on a log (t, inputs u, measurements y with per-channel noise).
ArrData evaluate_arrs(const ThesisParams<double>& p, const InputSeries& u,
                      const std::vector<std::array<double, kChannels>>& y, const std::array<bool, kChannels>& present,
                      const std::array<double, kChannels>& noise);

/// Statistics of one equation's imbalance on one log.
struct EquationStats {
  std::string equation, unit;
  bool available = false;
  double mean = 0, rms = 0;      ///< SI
  double noise = 0;              ///< RMS of the propagated noise (SI)
  double rms_w = 0;              ///< RMS of imbalance / propagated noise
  struct Part {
    std::string label;
    double mean = 0, rms_w = 0;
  };
  std::vector<Part> by_load;     ///< the operating-point dependence, per load regime
  std::string dependence;        ///< one line: how the mean imbalance moves with the load
};

/// One equation's mean, RMS, noise (RMS of sigma) and RMS of r/sigma over its rows
/// (r, sigma: imbalance and its propagated noise, SI, same length > 0) into s.
void imbalance_stats(const std::vector<double>& r, const std::vector<double>& sigma, EquationStats& s);

/// Per-equation statistics, in equation order.
std::vector<EquationStats> equation_stats(const ArrData& a);

/// Index of the located equation: the largest RMS over noise, if above 3; else -1.
int located_equation(const std::vector<EquationStats>& s);

}  // namespace hstmon::gap
