/// @file thesis_bond_graph.cpp
#include "hstmon_fdi/thesis_bond_graph.hpp"

namespace hstmon::fdi {

BondGraph thesis_bond_graph(ValveModel valves) {
  const bool lin = valves == ValveModel::kLinearised;
  BondGraph g;
  g.elements = {
      {"Se1", ElementKind::kSe, "Psupl", "supply pressure from the power pack"},
      {"1_in", ElementKind::kOne, "", "DCV inlet orifice: common flow"},
      {"R2", ElementKind::kR, lin ? "Rin" : "kfi", "DCV inlet orifice"},
      {"0_mi", ElementKind::kZero, "", "motor inlet port: common pressure Pmi"},
      {"C4", ElementKind::kC, "Kpmi", "compressibility of the motor inlet volume"},
      {"De5", ElementKind::kDetector, "", "Pmi pressure transducer"},
      {"R6", ElementKind::kR, "Rlkg1", "motor inlet leakage to drain"},
      {"TF7/8", ElementKind::kTF, "Dm", "motor displacement, inlet side"},
      {"1_m1", ElementKind::kOne, "", "motor inlet side shaft torque: common speed"},
      {"R9", ElementKind::kR, "Rbl1", "fluid friction of the inlet flow-control valve"},
      {"1_ipl", ElementKind::kOne, "", "cross-port leakage path: common flow"},
      {"R13", ElementKind::kR, "Ripl", "cross-port leakage of the motor"},
      {"0_mo", ElementKind::kZero, "", "motor outlet port: common pressure Pmo"},
      {"C18", ElementKind::kC, "Kpmo", "compressibility of the motor outlet volume"},
      {"De19", ElementKind::kDetector, "", "Pmo pressure transducer"},
      {"R17", ElementKind::kR, "Rlkg2", "motor outlet leakage to drain"},
      {"1_out", ElementKind::kOne, "", "DCV outlet orifice: common flow"},
      {"R15", ElementKind::kR, lin ? "Rout" : "kfo", "DCV outlet orifice"},
      {"Se14", ElementKind::kSe, "Ps", "tank (return) pressure"},
      {"TF20/21", ElementKind::kTF, "Dm", "motor displacement, outlet side"},
      {"1_m2", ElementKind::kOne, "", "motor outlet side shaft torque: common speed"},
      {"R22", ElementKind::kR, "Rbl2", "fluid friction of the outlet flow-control valve"},
      {"1_shaft", ElementKind::kOne, "", "motor-pump shaft: common speed ωm"},
      {"I24", ElementKind::kI, "J1", "inertia of motor + loading pump"},
      {"R25", ElementKind::kR, "Rf", "shaft friction"},
      {"TF26/29", ElementKind::kTF, "Dp", "loading-pump displacement, outlet side"},
      {"TF27/35", ElementKind::kTF, "Dp", "loading-pump displacement, inlet (booster) side"},
      {"0_pp", ElementKind::kZero, "", "loading-pump outlet: common pressure Ppp"},
      {"C31", ElementKind::kC, "Kpp", "compressibility of the loading-pump outlet volume"},
      {"De30", ElementKind::kDetector, "", "Ppp pressure transducer"},
      {"1_prv", ElementKind::kOne, "", "PRV orifice: common flow"},
      {"R33", ElementKind::kR, lin ? "Rpl" : "kp", "pressure relief valve (pump plenum)"},
      {"0_bp", ElementKind::kZero, "", "booster line: common pressure Pbp"},
      {"Se35", ElementKind::kSe, "Pbp", "booster-pump pressure"},
  };
  g.bonds = {
      {1, "Se1", "1_in"},
      {2, "1_in", "R2"},
      {3, "1_in", "0_mi"},
      {4, "0_mi", "C4"},
      {5, "0_mi", "De5"},
      {6, "0_mi", "R6"},
      {7, "0_mi", "TF7/8"},
      {8, "TF7/8", "1_m1"},
      {9, "1_m1", "R9"},
      {10, "1_m1", "1_shaft"},
      {11, "0_mi", "1_ipl"},
      {12, "1_ipl", "0_mo"},
      {13, "1_ipl", "R13"},
      {14, "1_out", "Se14"},
      {15, "1_out", "R15"},
      {16, "0_mo", "1_out"},
      {17, "0_mo", "R17"},
      {18, "0_mo", "C18"},
      {19, "0_mo", "De19"},
      {20, "TF20/21", "0_mo"},
      {21, "1_m2", "TF20/21"},
      {22, "1_m2", "R22"},
      {23, "1_shaft", "1_m2"},
      {24, "1_shaft", "I24"},
      {25, "1_shaft", "R25"},
      {26, "1_shaft", "TF26/29"},
      {27, "TF27/35", "1_shaft"},
      // Bond 28 is not in Table 2.4: the booster source feeds both the PRV outlet (34)
      // and the pump inlet transformer (35) through the 0-junction 0_bp.
      {28, "Se35", "0_bp"},
      {29, "TF26/29", "0_pp"},
      {30, "0_pp", "De30"},
      {31, "0_pp", "C31"},
      {32, "0_pp", "1_prv"},
      {33, "1_prv", "R33"},
      {34, "1_prv", "0_bp"},
      {35, "0_bp", "TF27/35"},
  };
  return g;
}

}  // namespace hstmon::fdi
