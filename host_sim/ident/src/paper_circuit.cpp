// The circuit's values beside the paper table analysis (paper_circuit.hpp).
#include "hstmon_ident/paper_circuit.hpp"

#include <cctype>
#include <cmath>

namespace hstmon::ident {

namespace {

namespace hc = hstmon::circuit;

CircuitNumber number_of(const circuit_tools::LoadedCircuit& c, hc::Ref r) {
  CircuitNumber n;
  n.value = std::nan("");
  if (r.kind == hc::RefKind::kParam && r.index < c.file.params.size()) {
    n.name = c.file.params[r.index].name;
    n.value = c.values.params.v[r.index];
  } else if (r.kind == hc::RefKind::kInput && r.index < c.file.inputs.size()) {
    n.name = c.file.inputs[r.index].name;
    n.input = true;
    n.value = c.values.inputs.v[r.index];
  }
  return n;
}

std::string lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

}  // namespace

std::vector<CircuitPumpCurve> circuit_pump_curves(const circuit_tools::LoadedCircuit& c) {
  std::vector<CircuitPumpCurve> out;
  const auto& d = c.file.circuit;
  const int slot[5] = {hc::kQ0, hc::kRleak, hc::kPc, hc::kPk, hc::kPmax};
  for (std::size_t e = 0; e < d.n_elements; ++e) {
    if (d.elements[e].kind != hc::ElementKind::kCompPump) continue;
    CircuitPumpCurve p;
    p.element = e < c.file.elements.size() ? c.file.elements[e] : std::to_string(e);
    for (std::size_t k = 0; k < 5; ++k) p.params[k] = number_of(c, d.elements[e].r[slot[k]]);
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<CircuitOrificeValues> circuit_orifices_named(const circuit_tools::LoadedCircuit& c,
                                                         const std::string& kind) {
  std::vector<CircuitOrificeValues> out;
  const auto& d = c.file.circuit;
  const std::string want = lower(kind);
  for (std::size_t e = 0; e < d.n_elements && e < c.file.elements.size(); ++e) {
    const hc::Element& el = d.elements[e];
    const std::string name = lower(c.file.elements[e]);
    if (el.kind != hc::ElementKind::kOrifice || !(name == want || name.rfind(want + ".", 0) == 0)) continue;
    CircuitOrificeValues o;
    o.element = c.file.elements[e];
    o.area = number_of(c, el.r[hc::kArea]);
    o.k = number_of(c, el.r[hc::kK]);
    o.cd = number_of(c, el.r[hc::kCd]);
    o.rho = number_of(c, el.r[hc::kRho]);
    // A fixed opening scales the flow as the area does; a spool position (signed) does not
    // name one area, so the comparison uses the full port.
    const CircuitNumber opening = number_of(c, el.r[hc::kOpening]);
    if (el.opening_sign == 0 && opening.given() && std::isfinite(opening.value)) {
      if (o.area.given()) o.area.value *= opening.value;
      if (o.k.given()) o.k.value *= opening.value;
    }
    if (o.k.given()) o.area = CircuitNumber{"", false, std::nan("")};
    out.push_back(std::move(o));
  }
  return out;
}

double percent_difference(double fitted, double circuit) {
  if (!(std::isfinite(circuit) && circuit != 0.0)) return std::nan("");
  return 100.0 * (fitted - circuit) / circuit;
}

}  // namespace hstmon::ident
