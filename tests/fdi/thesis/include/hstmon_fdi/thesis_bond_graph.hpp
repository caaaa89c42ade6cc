#pragma once
/// @file thesis_bond_graph.hpp
/// The thesis's bond graph (Fig. 2.3, nonlinear valves; Fig. 2.14, linearised valves),
/// written by hand: the test oracle that the graph derived from thesis.json is checked
/// against. The figures are not in the seed's text; the structure is reconstructed from
/// equations 2.5–2.8 and the bond numbers of Table 2.4 (docs/fdi.md lists the
/// reconstruction and where it departs).

#include "hstmon_fdi/bond_graph.hpp"

namespace hstmon::fdi {

/// How the valve orifices (DCV inlet R2, DCV outlet R15, PRV R33) are modelled.
enum class ValveModel {
  kNonlinear,   ///< Fig. 2.3: Q = k·sq(ΔP), parameters kfi, kfo, kp; edge gains are the tangent slopes
  kLinearised,  ///< Fig. 2.14: Q = ΔP/R, parameters Rin, Rout, Rpl of eq. 2.11 (secant R = √ΔP/k)
};

/// The thesis HST's bond graph with the given valve model.
BondGraph thesis_bond_graph(ValveModel valves);

}  // namespace hstmon::fdi
