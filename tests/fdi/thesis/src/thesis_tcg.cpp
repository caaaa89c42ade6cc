/// @file thesis_tcg.cpp
/// The TCG of the thesis HST written out relation by relation from the bond graph in the
/// causality of Table 2.4 (C4, C18, C31, I24 integral; R2, R6, R13, R15, R17, R33 set
/// flows from efforts; R9, R22, R25 set efforts from flows). docs/fdi.md tabulates it.
#include "hstmon_fdi/thesis_tcg.hpp"

#include <cmath>
#include <string>

#include "hstmon/signed_root.hpp"

namespace hstmon::fdi {

namespace {

/// Adds nodes and edges with short calls; gains default to 1.
class Builder {
 public:
  explicit Builder(CausalGraph& g) : g_(g) {}

  void effort(int bond, double value, const char* meaning = "") {
    node("e" + std::to_string(bond), NodeKind::kEffort, bond, value, meaning);
  }
  void flow(int bond, double value, const char* meaning = "") {
    node("f" + std::to_string(bond), NodeKind::kFlow, bond, value, meaning);
  }
  void node(const std::string& name, NodeKind kind, int bond, double value, const char* meaning) {
    g_.add_node(Node{name, kind, bond, meaning, value});
  }

  /// Junction or source relation: to = ±from, no parameter.
  void link(const char* to, const char* from, int sign, const char* element, const char* relation) {
    g_.add_edge(Edge{g_.at(from), g_.at(to), sign, EdgeType::kInstant, "", 0, element, relation, 1.0, 0.0});
  }

  /// Element relation carrying a parameter.
  void param(const char* to, const char* from, EdgeType type, const std::string& p, int p_sign, double gain,
             double injection, const char* element, const std::string& relation) {
    g_.add_edge(Edge{g_.at(from), g_.at(to), 1, type, p, p_sign, element, relation, gain, injection});
  }

  /// A valve's flow f from its pressure drop e: linearised (lin), f = e/R with the
  /// parameter `r_name` = r; else the orifice law f = k*sq(e) with the parameter `k_name`
  /// and g its slope at the operating point. q: the valve's steady flow.
  void valve(bool lin, const char* f, const char* e, const char* element, const char* r_name, double r,
             const char* k_name, double g, double q) {
    if (lin) {
      param(f, e, EdgeType::kInstant, r_name, -1, 1.0 / r, -q, element, std::string(f) + " = " + e + "/" + r_name);
    } else {
      param(f, e, EdgeType::kInstant, k_name, 1, g, q, element, std::string(f) + " = " + k_name + "*sq(" + e + ")");
    }
  }

 private:
  CausalGraph& g_;
};

// The operating point's steady flows and the split of the valve friction, which the nodes'
// values and the edges' injections are written with.
struct SteadyValues {
  double Pmi, Pmo, Ppp, w;  ///< states [Pa, Pa, Pa, rad/s]
  double Rbl1, Rbl2;        ///< inlet and outlet valve friction [N·m·s/rad]
  double q_in, q_out;       ///< DCV inlet and outlet flows [m³/s]
  double q_prv, q_ipl;      ///< PRV and cross-port leakage flows [m³/s]
};

SteadyValues steady_values(const OperatingPoint& op) {
  const ThesisParams<double>& p = op.p;
  const ThesisInputs<double>& u = op.u;
  SteadyValues v{};
  v.Pmi = op.x.Pmi;
  v.Pmo = op.x.Pmo;
  v.Ppp = op.x.Ppp;
  v.w = op.x.w_m;
  v.Rbl1 = 0.5 * p.Rbl;  // the thesis identifies only the sum
  v.Rbl2 = 0.5 * p.Rbl;
  v.q_in = p.kf * signed_root(u.Psupl - v.Pmi, p.dp_t_dcv);
  v.q_out = p.kf * signed_root(v.Pmo - u.Ps, p.dp_t_dcv);
  v.q_prv = u.kp * signed_root(v.Ppp - u.Pbp, p.dp_t_prv);
  v.q_ipl = (v.Pmi - v.Pmo) / p.Ripl;
  return v;
}

// At a steady state no net flow enters a volume and no net torque acts on the shaft, so
// a change of K or J injects nothing: they only shape transients (docs/fdi.md).
constexpr double kNet = 0.0;

// One side of the motor, bonds n to n + 3: the port (pressure P), the displacement's
// torque, the side's valve friction Rbl and the side's 1-junction, whose torque is the
// displacement's with the friction added (friction_sign 1) or taken off (-1).
void add_motor_side(Builder& b, int n, const std::string& side, double P, const char* torque, int friction_sign,
                    double Dm, double Rbl, double w) {
  b.effort(n, P);
  b.flow(n, Dm * w, ("motor swept flow, " + side).c_str());
  b.effort(n + 1, Dm * P, torque);
  b.flow(n + 1, w);
  b.effort(n + 2, Rbl * w, (side + " valve friction torque").c_str());
  b.flow(n + 2, w);
  b.effort(n + 3, Dm * P + friction_sign * Rbl * w);
  b.flow(n + 3, w);
}

// Every effort and flow of the bond graph, the sources and the measurements, valued at the operating point.
void add_nodes(Builder& b, const OperatingPoint& op, const SteadyValues& v) {
  const ThesisParams<double>& p = op.p;
  const ThesisInputs<double>& u = op.u;
  const double Pmi = v.Pmi, Pmo = v.Pmo, Ppp = v.Ppp, w = v.w;
  const double Rbl1 = v.Rbl1, Rbl2 = v.Rbl2, q_in = v.q_in, q_out = v.q_out, q_prv = v.q_prv, q_ipl = v.q_ipl;
  b.node("Psupl", NodeKind::kSource, 1, u.Psupl, "supply pressure (Se1)");
  b.node("Ps", NodeKind::kSource, 14, u.Ps, "tank pressure (Se14)");
  b.node("Pbp", NodeKind::kSource, 28, u.Pbp, "booster pressure (Se35)");
  b.effort(1, u.Psupl);
  b.effort(2, u.Psupl - Pmi, "DCV inlet drop");
  b.flow(2, q_in, "DCV inlet flow");
  b.effort(3, Pmi);
  b.flow(3, q_in);
  b.effort(4, Pmi, "Pmi, motor inlet pressure");
  b.flow(4, 0.0, "net flow into the motor inlet volume");
  b.effort(6, Pmi);
  b.flow(6, Pmi / p.Rlkg, "inlet leakage flow");
  add_motor_side(b, 7, "inlet", Pmi, "motor torque from Pmi", -1, p.Dm, Rbl1, w);
  b.effort(11, Pmi);
  b.flow(11, q_ipl);
  b.effort(12, Pmo);
  b.flow(12, q_ipl);
  b.effort(13, Pmi - Pmo, "cross-port pressure difference");
  b.flow(13, q_ipl, "cross-port leakage flow");
  b.effort(14, u.Ps);
  b.effort(15, Pmo - u.Ps, "DCV outlet drop");
  b.flow(15, q_out, "DCV outlet flow");
  b.effort(16, Pmo);
  b.flow(16, q_out);
  b.effort(17, Pmo);
  b.flow(17, Pmo / p.Rlkg, "outlet leakage flow");
  b.effort(18, Pmo, "Pmo, motor outlet pressure");
  b.flow(18, 0.0, "net flow into the motor outlet volume");
  add_motor_side(b, 20, "outlet", Pmo, "motor counter-torque from Pmo", 1, p.Dm, Rbl2, w);
  b.effort(24, 0.0, "net shaft torque");
  b.flow(24, w, "ωm, shaft speed");
  b.effort(25, p.Rf * w, "shaft friction torque");
  b.flow(25, w);
  b.effort(26, p.Dp * Ppp, "pump load torque from Ppp");
  b.flow(26, w);
  b.effort(27, p.Dp * u.Pbp, "pump inlet torque from Pbp");
  b.flow(27, w);
  b.effort(28, u.Pbp);
  b.effort(29, Ppp);
  b.flow(29, p.Dp * w, "pump delivery");
  b.effort(31, Ppp, "Ppp, loading-pump outlet pressure");
  b.flow(31, 0.0, "net flow into the pump outlet volume");
  b.effort(32, Ppp);
  b.flow(32, q_prv);
  b.effort(33, Ppp - u.Pbp, "PRV drop");
  b.flow(33, q_prv, "PRV flow");
  b.effort(34, u.Pbp);
  b.effort(35, u.Pbp);
  b.node("p_mi", NodeKind::kMeasurement, 0, Pmi, "measured Pmi");
  b.node("p_mo", NodeKind::kMeasurement, 0, Pmo, "measured Pmo");
  b.node("p_pp", NodeKind::kMeasurement, 0, Ppp, "measured Ppp");
  b.node("w_m", NodeKind::kMeasurement, 0, w, "measured ωm");
}

// The hydraulic side: sources, the DCV, the motor's inlet and outlet volumes, its ports and the
// cross-port leakage (lin: the valves linearised).
void add_hydraulic_edges(Builder& b, const OperatingPoint& op, const SteadyValues& v, bool lin) {
  const ThesisParams<double>& p = op.p;
  const double Pmi = v.Pmi, Pmo = v.Pmo, w = v.w;
  const double Rbl1 = v.Rbl1, Rbl2 = v.Rbl2, q_in = v.q_in, q_out = v.q_out, q_ipl = v.q_ipl;
  const EdgeType kI = EdgeType::kInstant, kDt = EdgeType::kIntegral;
  // Sources.
  b.link("e1", "Psupl", 1, "Se1", "e1 = Psupl");
  b.link("e14", "Ps", 1, "Se14", "e14 = Ps");
  b.link("e28", "Pbp", 1, "Se35", "e28 = Pbp");
  // DCV inlet.
  b.link("e2", "e1", 1, "1_in", "e2 = e1 - e3");
  b.link("e2", "e3", -1, "1_in", "e2 = e1 - e3");
  b.valve(lin, "f2", "e2", "R2", "Rin", op.Rin, "kfi", op.g_in, q_in);
  b.link("f3", "f2", 1, "1_in", "f3 = f2");
  // Motor inlet volume.
  for (const char* e : {"e3", "e6", "e7", "e11"}) b.link(e, "e4", 1, "0_mi", "common pressure Pmi");
  b.link("f4", "f3", 1, "0_mi", "f4 = f3 - f6 - f7 - f11");
  b.link("f4", "f7", -1, "0_mi", "f4 = f3 - f6 - f7 - f11");
  b.link("f4", "f6", -1, "0_mi", "f4 = f3 - f6 - f7 - f11");
  b.link("f4", "f11", -1, "0_mi", "f4 = f3 - f6 - f7 - f11");
  b.param("e4", "f4", kDt, "Kpmi", 1, p.K, p.K * kNet, "C4", "de4/dt = Kpmi*f4");
  b.param("f6", "e6", kI, "Rlkg1", -1, 1.0 / p.Rlkg, -Pmi / p.Rlkg, "R6", "f6 = e6/Rlkg1");
  // Motor, inlet side.
  b.param("e8", "e7", kI, "Dm", 1, p.Dm, p.Dm * Pmi, "TF7/8", "e8 = Dm*e7");
  b.param("f7", "f8", kI, "Dm", 1, p.Dm, p.Dm * w, "TF7/8", "f7 = Dm*f8");
  b.link("e10", "e8", 1, "1_m1", "e10 = e8 - e9");
  b.link("e10", "e9", -1, "1_m1", "e10 = e8 - e9");
  b.link("f8", "f10", 1, "1_m1", "common speed");
  b.link("f9", "f10", 1, "1_m1", "common speed");
  b.param("e9", "f9", kI, "Rbl1", 1, Rbl1, Rbl1 * w, "R9", "e9 = Rbl1*f9");
  // Cross-port leakage.
  b.link("e13", "e11", 1, "1_ipl", "e13 = e11 - e12");
  b.link("e13", "e12", -1, "1_ipl", "e13 = e11 - e12");
  b.param("f13", "e13", kI, "Ripl", -1, 1.0 / p.Ripl, -q_ipl, "R13", "f13 = e13/Ripl");
  b.link("f11", "f13", 1, "1_ipl", "common flow");
  b.link("f12", "f13", 1, "1_ipl", "common flow");
  // Motor outlet volume.
  for (const char* e : {"e12", "e16", "e17", "e20"}) b.link(e, "e18", 1, "0_mo", "common pressure Pmo");
  b.link("f18", "f12", 1, "0_mo", "f18 = f12 - f16 - f17 + f20");
  b.link("f18", "f16", -1, "0_mo", "f18 = f12 - f16 - f17 + f20");
  b.link("f18", "f17", -1, "0_mo", "f18 = f12 - f16 - f17 + f20");
  b.link("f18", "f20", 1, "0_mo", "f18 = f12 - f16 - f17 + f20");
  b.param("e18", "f18", kDt, "Kpmo", 1, p.K, p.K * kNet, "C18", "de18/dt = Kpmo*f18");
  b.param("f17", "e17", kI, "Rlkg2", -1, 1.0 / p.Rlkg, -Pmo / p.Rlkg, "R17", "f17 = e17/Rlkg2");
  // DCV outlet.
  b.link("e15", "e16", 1, "1_out", "e15 = e16 - e14");
  b.link("e15", "e14", -1, "1_out", "e15 = e16 - e14");
  b.valve(lin, "f15", "e15", "R15", "Rout", op.Rout, "kfo", op.g_out, q_out);
  b.link("f16", "f15", 1, "1_out", "f16 = f15");
  // Motor, outlet side.
  b.param("e21", "e20", kI, "Dm", 1, p.Dm, p.Dm * Pmo, "TF20/21", "e21 = Dm*e20");
  b.param("f20", "f21", kI, "Dm", 1, p.Dm, p.Dm * w, "TF20/21", "f20 = Dm*f21");
  b.link("e23", "e21", 1, "1_m2", "e23 = e21 + e22");
  b.link("e23", "e22", 1, "1_m2", "e23 = e21 + e22");
  b.link("f21", "f23", 1, "1_m2", "common speed");
  b.link("f22", "f23", 1, "1_m2", "common speed");
  b.param("e22", "f22", kI, "Rbl2", 1, Rbl2, Rbl2 * w, "R22", "e22 = Rbl2*f22");
}

// The shaft, the loading pump, the PRV and booster line, and the sensors (lin: the PRV linearised).
void add_shaft_pump_and_sensor_edges(Builder& b, const OperatingPoint& op, const SteadyValues& v, bool lin) {
  const ThesisParams<double>& p = op.p;
  const ThesisInputs<double>& u = op.u;
  const double Ppp = v.Ppp, w = v.w, q_prv = v.q_prv;
  const EdgeType kI = EdgeType::kInstant, kDt = EdgeType::kIntegral;
  // Shaft: in-edges of e24 in the order of Table 2.4 row 15.
  b.link("e24", "e10", 1, "1_shaft", "e24 = e10 - e23 - e25 - e26 + e27");
  b.link("e24", "e23", -1, "1_shaft", "e24 = e10 - e23 - e25 - e26 + e27");
  b.link("e24", "e25", -1, "1_shaft", "e24 = e10 - e23 - e25 - e26 + e27");
  b.link("e24", "e26", -1, "1_shaft", "e24 = e10 - e23 - e25 - e26 + e27");
  b.link("e24", "e27", 1, "1_shaft", "e24 = e10 - e23 - e25 - e26 + e27");
  b.param("f24", "e24", kDt, "J1", -1, 1.0 / p.J, -kNet / p.J, "I24", "df24/dt = e24/J1");
  for (const char* f : {"f10", "f23", "f25", "f26", "f27"}) b.link(f, "f24", 1, "1_shaft", "common speed ωm");
  b.param("e25", "f25", kI, "Rf", 1, p.Rf, p.Rf * w, "R25", "e25 = Rf*f25");
  // Loading pump.
  b.param("e26", "e29", kI, "Dp", 1, p.Dp, p.Dp * Ppp, "TF26/29", "e26 = Dp*e29");
  b.param("f29", "f26", kI, "Dp", 1, p.Dp, p.Dp * w, "TF26/29", "f29 = Dp*f26");
  b.param("e27", "e35", kI, "Dp", 1, p.Dp, p.Dp * u.Pbp, "TF27/35", "e27 = Dp*e35");
  b.link("e29", "e31", 1, "0_pp", "common pressure Ppp");
  b.link("e32", "e31", 1, "0_pp", "common pressure Ppp");
  b.link("f31", "f29", 1, "0_pp", "f31 = f29 - f32");
  b.link("f31", "f32", -1, "0_pp", "f31 = f29 - f32");
  b.param("e31", "f31", kDt, "Kpp", 1, p.K, p.K * kNet, "C31", "de31/dt = Kpp*f31");
  // PRV and booster line.
  b.link("e33", "e32", 1, "1_prv", "e33 = e32 - e34");
  b.link("e33", "e34", -1, "1_prv", "e33 = e32 - e34");
  b.valve(lin, "f33", "e33", "R33", "Rpl", op.Rpl, "kp", op.g_prv, q_prv);
  b.link("f32", "f33", 1, "1_prv", "f32 = f33");
  b.link("e34", "e28", 1, "0_bp", "common pressure Pbp");
  b.link("e35", "e28", 1, "0_bp", "common pressure Pbp");
  // Sensors.
  b.link("p_mi", "e4", 1, "De5", "p_mi = e4");
  b.link("p_mo", "e18", 1, "De19", "p_mo = e18");
  b.link("p_pp", "e31", 1, "De30", "p_pp = e31");
  b.link("w_m", "f24", 1, "tacho", "w_m = f24");
}

}  // namespace

CausalGraph thesis_tcg(ValveModel valves, const OperatingPoint& op) {
  const bool lin = valves == ValveModel::kLinearised;
  const SteadyValues v = steady_values(op);
  CausalGraph g;
  Builder b(g);
  add_nodes(b, op, v);
  add_hydraulic_edges(b, op, v, lin);
  add_shaft_pump_and_sensor_edges(b, op, v, lin);
  return g;
}

}  // namespace hstmon::fdi
