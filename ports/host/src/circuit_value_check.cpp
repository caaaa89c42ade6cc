// Value checks of a circuit with its values (circuit_checks.hpp): each law's numbers in
// the range where the law means something physical. The engine refuses the same values
// (CircuitModel::valid()) but cannot say which; this names the element, field and value.
#include <cmath>
#include <cstdio>

#include "circuit_checks.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon/pump_curve.hpp"

namespace hstmon::host::detail {

namespace {

using circuit::ElementKind;
using circuit::Ref;
using circuit::RefKind;

/// A unit a reader of the message thinks in, beside SI: {name, SI per unit}.
struct Everyday {
  const char* unit;
  double si;
};

Everyday everyday(CircuitQuantity q) {
  switch (q) {
    case CircuitQuantity::kPressure: return {"bar", 1e5};
    case CircuitQuantity::kDisplacement: return {"cc/rev", 1e-6 / 6.283185307179586};
    case CircuitQuantity::kVolume: return {"L", 1e-3};
    case CircuitQuantity::kFlow: return {"L/min", 1e-3 / 60.0};
    default: return {nullptr, 1.0};
  }
}

class Checker {
 public:
  Checker(const CircuitFile& f, const CircuitValues& v) : f_(f), v_(v) {}

  std::optional<ValueProblem> run() {
    const HostCircuit& c = f_.circuit;
    positive(c.pressure_max, "envelope", "pressure", "the envelope");
    positive(c.speed_max, "envelope", "speed", "the envelope");
    for (int i = 0; i < c.n_nodes; ++i) node(i);
    for (int s = 0; s < c.n_shafts; ++s) {
      if (!c.shafts[s].driven) positive(c.shafts[s].J, f_.shafts[static_cast<std::size_t>(s)], "J", "an inertia");
    }
    for (int k = 0; k < c.n_elements; ++k) element(k);
    if (!out_) engine_refuses();
    return out_;
  }

 private:
  double value(Ref r) const { return r.kind == RefKind::kInput ? v_.inputs.v[r.index] : v_.params.v[r.index]; }

  CircuitQuantity quantity(Ref r) const {
    return r.kind == RefKind::kInput ? f_.inputs[r.index].quantity : f_.params[r.index].quantity;
  }

  /// "2.5e+07 Pa (250 bar, parameter 'Pset')": the value, its units and where it is named.
  std::string shown(Ref r) const {
    const double x = value(r);
    const CircuitQuantity q = quantity(r);
    std::string s = number_text(x) + " " + circuit_si_unit(q);
    std::string aside;
    if (const Everyday e = everyday(q); e.unit != nullptr) aside = number_text(x / e.si) + " " + e.unit;
    if (r.kind == RefKind::kInput) {
      aside += (aside.empty() ? "" : ", ") + std::string("input '") + f_.inputs[r.index].name + "', nominal";
    } else if (!f_.params[r.index].literal) {
      aside += (aside.empty() ? "" : ", ") + std::string("parameter '") + f_.params[r.index].name + "'";
    }
    return aside.empty() ? s : s + " (" + aside + ")";
  }

  void fail(Ref r, std::string message) {
    if (!out_) out_ = ValueProblem{r, std::move(message)};
  }

  /// owner.field must be > 0 (or ≥ 0 when zero is physical: a shut orifice, no friction).
  void need(Ref r, const std::string& owner, const char* field, const char* what, bool zero_ok) {
    if (out_ || r.kind == RefKind::kNone) return;
    const double x = value(r);
    if (zero_ok ? x >= 0.0 : x > 0.0) return;
    fail(r, owner + "." + field + " = " + shown(r) + ": " + what + " must be " + (zero_ok ? ">= 0" : "> 0"));
  }
  void positive(Ref r, const std::string& owner, const char* field, const char* what) { need(r, owner, field, what, false); }
  void non_negative(Ref r, const std::string& owner, const char* field, const char* what) { need(r, owner, field, what, true); }

  void node(int i) {
    const circuit::Node& n = f_.circuit.nodes[i];
    if (n.kind != circuit::NodeKind::kVolume) return;
    const std::string& name = f_.nodes[static_cast<std::size_t>(i)];
    positive(n.K, name, "K", "a bulk stiffness");
    positive(n.beta, name, "beta", "a bulk modulus");
    positive(n.volume, name, "volume", "a volume");
  }

  void coefficient(const circuit::Element& e, const std::string& name) {
    non_negative(e.r[circuit::kK], name, "k", "a flow coefficient");
    non_negative(e.r[circuit::kArea], name, "area", "an area");
    non_negative(e.r[circuit::kCd], name, "Cd", "a discharge coefficient");
    positive(e.r[circuit::kRho], name, "rho", "a density");
    positive(e.r[circuit::kDpT], name, "dp_t", "a laminar transition pressure");
  }

  void poppet(const circuit::Element& e, const std::string& name) {
    coefficient(e, name);
    const Ref crack = e.r[circuit::kCrack], full = e.r[circuit::kFull];
    non_negative(crack, name, "cracking", "a cracking pressure");
    if (out_) return;
    const double c = crack.kind == RefKind::kNone ? 0.0 : value(crack);
    if (value(full) > c) return;
    if (crack.kind == RefKind::kNone) {
      fail(full, name + ".full_open = " + shown(full) + ": the full-open pressure must be > 0 (the cracking pressure)");
      return;
    }
    fail(crack, name + ".cracking = " + shown(crack) + " is not below the full-open pressure " + shown(full) +
                    " (a relief valve's 'setting', a check valve's 'full_open')");
  }

  void compensated_pump(const circuit::Element& e, const std::string& name) {
    positive(e.r[circuit::kQ0], name, "Q0", "the zero-pressure flow");
    positive(e.r[circuit::kRleak], name, "R", "a leakage resistance");
    positive(e.r[circuit::kPc], name, "Pc", "the compensator's start");
    if (out_) return;
    const Ref pc = e.r[circuit::kPc], pk = e.r[circuit::kPk], pmax = e.r[circuit::kPmax];
    if (!(value(pk) > value(pc))) fail(pk, name + ".Pk = " + shown(pk) + " is not above Pc = " + shown(pc));
    if (!(value(pmax) > value(pk))) fail(pmax, name + ".Pmax = " + shown(pmax) + " is not above Pk = " + shown(pk));
    PumpCurveParams<double> p{};
    p.Q0 = value(e.r[circuit::kQ0]);
    p.R = value(e.r[circuit::kRleak]);
    p.Pc = value(pc);
    p.Pk = value(pk);
    p.Pmax = value(pmax);
    PumpCurve<double> curve;
    if (!out_ && !curve.make(p)) {
      fail(e.r[circuit::kQ0], name + ".Q0 = " + shown(e.r[circuit::kQ0]) + " with R = " + shown(e.r[circuit::kRleak]) +
                                  ": no pump curve through these (its flow must stay > 0 up to Pk, its middle region concave)");
    }
  }

  /// The name a user wrote for element k: a directional valve's, not its path's ("dcv", not "dcv.PA").
  std::string owner(int k) const {
    const circuit::Element& e = f_.circuit.elements[k];
    const std::string& name = f_.elements[static_cast<std::size_t>(k)];
    return e.kind == ElementKind::kOrifice && e.opening_sign != 0 ? name.substr(0, name.rfind('.')) : name;
  }

  void element(int k) {
    const circuit::Element& e = f_.circuit.elements[k];
    const std::string name = owner(k);
    if (e.kind == ElementKind::kFriction && e.shaft >= 0 && name == f_.shafts[static_cast<std::size_t>(e.shaft)] + ".friction") {
      non_negative(e.r[circuit::kC], f_.shafts[static_cast<std::size_t>(e.shaft)], "friction", "a friction coefficient");
      return;  // a shaft's own `friction` field
    }
    switch (e.kind) {
      case ElementKind::kOrifice: coefficient(e, name); break;
      case ElementKind::kPoppet: poppet(e, name); break;
      case ElementKind::kLaminar: positive(e.r[circuit::kR], name, "R", "a resistance"); break;
      case ElementKind::kMachine: positive(e.r[circuit::kD], name, "displacement", "a displacement"); break;
      case ElementKind::kCompPump: compensated_pump(e, name); break;
      case ElementKind::kFriction: non_negative(e.r[circuit::kC], name, "c", "a friction coefficient"); break;
      default: break;  // flows, torques, fractions may take either sign
    }
  }

  /// What the checks above do not name (a capacitance that overflows, say) the engine
  /// still refuses: an error without an element rather than a run that never happens.
  void engine_refuses() {
    const HostCircuitModel model(f_.circuit, v_.params, v_.inputs);
    if (model.error() != circuit::CircuitError::kOk || !model.valid()) {
      fail(Ref{}, "the values do not make a physical circuit (a capacitance, inertia or coefficient out of range)");
    }
  }

  const CircuitFile& f_;
  const CircuitValues& v_;
  std::optional<ValueProblem> out_;
};

}  // namespace

std::optional<ValueProblem> value_problem(const CircuitFile& c, const CircuitValues& v) { return Checker(c, v).run(); }

}  // namespace hstmon::host::detail
