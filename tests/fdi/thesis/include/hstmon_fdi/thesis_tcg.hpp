#pragma once
/// @file thesis_tcg.hpp
/// The temporal causal graph of the thesis HST (Fig. 2.15), derived by hand from the bond
/// graph of thesis_bond_graph() in the causality of Table 2.4, with numeric gains at an
/// operating point. Measurement nodes: p_mi ← e4, p_mo ← e18, p_pp ← e31, w_m ← f24.

#include "hstmon_fdi/thesis_bond_graph.hpp"
#include "hstmon_fdi/causal_graph.hpp"
#include "hstmon_fdi/operating_point.hpp"

namespace hstmon::fdi {

/// Names of the measurement nodes in hstmon::ThesisChannel order.
inline constexpr const char* kMeasurementNodes[4] = {"p_mi", "p_mo", "p_pp", "w_m"};

/// Builds the thesis TCG. Rbl1 = Rbl2 = Rbl/2, Rlkg1 = Rlkg2 = Rlkg and
/// Kpmi = Kpmo = Kpp = K at the operating point (the thesis's simplifications).
/// @param valves  Fig. 2.3 (kfi, kfo, kp) or Fig. 2.14 (Rin, Rout, Rpl)
/// @param op      operating point for the numeric gains
CausalGraph thesis_tcg(ValveModel valves, const OperatingPoint& op = operating_point());

}  // namespace hstmon::fdi
