/// @file fdi_circuit_tcg.cpp
#include "fdi_circuit_tcg.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fdi_report.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_fdi/backward.hpp"
#include "hstmon_fdi/circuit_crosscheck.hpp"
#include "hstmon_fdi/circuit_tcg.hpp"
#include "hstmon_fdi/fault_tree.hpp"
#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

std::string sym(QualSign q) { return std::string(1, qual_symbol(q)); }
std::string order_digit(int k) { return k < 0 ? "." : std::to_string(k); }

/// The loaded circuit and its TCG at the nominal values.
struct Loaded {
  circuit_tools::LoadedCircuit c;
  CircuitOperatingPoint op;
  CircuitTcg t;
};

/// Loads and derives; prints the error and returns false on a bad file or no steady state.
bool load(const CircuitSource& s, Loaded& l) {
  if (auto err = circuit_tools::load_circuit(s.circuit, s.params, l.c)) {
    std::cerr << err->to_string() << '\n';
    return false;
  }
  if (auto err = circuit_operating_point(l.c, l.c.values.params, l.c.values.inputs, l.op)) {
    std::cerr << s.circuit << ": " << *err << '\n';
    return false;
  }
  l.t = circuit_tcg(l.c, l.op);
  return true;
}

const char* kind_name(ElementKind k) {
  switch (k) {
    case ElementKind::kSe: return "Se";
    case ElementKind::kSf: return "Sf";
    case ElementKind::kR: return "R";
    case ElementKind::kC: return "C";
    case ElementKind::kI: return "I";
    case ElementKind::kTF: return "TF";
    case ElementKind::kZero: return "0";
    case ElementKind::kOne: return "1";
    default: return "De/Df";
  }
}

/// The circuit parameter of a graph parameter or source, or "".
std::string circuit_name(const CircuitTcg& t, const std::string& graph_name) {
  for (const GraphParameter& g : t.parameters) {
    if (g.name == graph_name) return g.circuit_name;
  }
  return "";
}

/// Pairs "NAME=VALUE" of a repeated option.
std::pair<std::string, double> name_value(const std::string& s) {
  const std::size_t eq = s.find('=');
  if (eq == std::string::npos || eq == 0) throw std::invalid_argument("expected NAME=NUMBER: " + s);
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s.substr(eq + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != s.size() - eq - 1 || !(v > 0.0) || !std::isfinite(v)) {
    throw std::invalid_argument("expected NAME=POSITIVE_NUMBER: " + s);
  }
  return {s.substr(0, eq), v};
}

}  // namespace

int run_circuit_graph(const CircuitSource& s, bool json) {
  Loaded l;
  if (!load(s, l)) return 2;
  const BondGraph& bg = l.t.bond_graph.graph;
  if (json) {
    nlohmann::json el = nlohmann::json::array(), bonds = nlohmann::json::array();
    for (const Element& e : bg.elements) el.push_back({{"name", e.name}, {"kind", kind_name(e.kind)}, {"parameter", e.parameter}, {"meaning", e.meaning}});
    for (std::size_t b = 0; b < bg.bonds.size(); ++b) {
      bonds.push_back({{"number", bg.bonds[b].number}, {"from", bg.bonds[b].from}, {"to", bg.bonds[b].to},
                       {"effort_by", l.t.bond_graph.effort_by[b]}});
    }
    std::cout << nlohmann::json{{"circuit", l.c.file.name}, {"elements", el}, {"bonds", bonds}, {"tcg", json_edges(l.t.graph)}}.dump(2) << '\n';
    return 0;
  }
  std::cout << "# Bond graph and temporal causal graph of circuit " << l.c.file.name << "\n\n## Elements\n\n"
            << "| element | kind | parameter | circuit name | meaning |\n|---|---|---|---|---|\n";
  for (const Element& e : bg.elements) {
    std::cout << fmt::format("| {} | {} | {} | {} | {} |\n", e.name, kind_name(e.kind), e.parameter,
                             circuit_name(l.t, e.parameter), e.meaning);
  }
  std::cout << "\n## Bonds (half-arrow from → to; effort imposed by)\n\n| bond | from | to | effort by |\n|---|---|---|---|\n";
  for (std::size_t b = 0; b < bg.bonds.size(); ++b) {
    std::cout << fmt::format("| {} | {} | {} | {} |\n", bg.bonds[b].number, bg.bonds[b].from, bg.bonds[b].to,
                             l.t.bond_graph.effort_by[b]);
  }
  std::cout << "\n## Temporal causal graph at the nominal operating point\n\n" << markdown_edges(l.t.graph);
  return 0;
}

int run_circuit_backward(const CircuitSource& s, const std::string& observation, bool json) {
  Loaded l;
  if (!load(s, l)) return 2;
  std::string node;
  int sign = 0;
  parse_observation(observation, node, sign);
  const BackwardResult r = backward_propagate(l.t.graph, node, sign);
  if (json) {
    nlohmann::json j = json_backward(r);
    for (auto& c : j["candidates"]) c["circuit_name"] = circuit_name(l.t, c["name"].get<std::string>());
    std::cout << j.dump(2) << '\n';
    return 0;
  }
  // The same candidates by circuit parameter: one parameter on several edges may be asked
  // for with both signs (K on every volume), shown as ?.
  std::vector<std::pair<std::string, QualSign>> by_circuit;
  for (const Candidate& c : r.candidates) {
    const std::string n = circuit_name(l.t, c.name);
    if (n.empty()) continue;
    bool seen = false;
    for (auto& [name, q] : by_circuit) {
      if (name != n) continue;
      seen = true;
      q = qual_add(q, c.sign);
    }
    if (!seen) by_circuit.emplace_back(n, c.sign);
  }
  std::cout << text_backward(r) << "\ncircuit parameters and inputs:";
  for (const auto& [name, q] : by_circuit) std::cout << ' ' << name << sym(q);
  std::cout << '\n';
  return 0;
}

int run_circuit_forward(const CircuitSource& s, const std::string& fault, int order, bool json) {
  Loaded l;
  if (!load(s, l)) return 2;
  std::string name;
  int sign = 0;
  parse_observation(fault, name, sign);
  const std::vector<ParamStep> steps = circuit_fault_steps(l.t, name, sign);
  const std::vector<ChannelPrediction> q = forward_qualitative_at(l.t.graph, steps, order, l.t.measured);
  const std::vector<ChannelPrediction> w = forward_weighted_at(l.t.graph, steps, order, l.t.measured);
  const std::vector<double> lin = linear_steady_change_at(l.t.graph, steps, l.t.measured);
  if (json) {
    auto derivatives = [](const ChannelPrediction& p) {
      std::vector<int> v;
      for (QualSign d : p.derivative) v.push_back(static_cast<int>(d));
      return v;
    };
    nlohmann::json a = nlohmann::json::array();
    for (std::size_t c = 0; c < q.size(); ++c) {
      a.push_back({{"channel", l.t.measured[c]},
                   {"magnitude", static_cast<int>(q[c].magnitude)},
                   {"slope", static_cast<int>(q[c].slope)},
                   {"order", q[c].order},
                   {"derivatives", derivatives(q[c])},
                   {"weighted_slope", static_cast<int>(w[c].slope)},
                   {"weighted_derivatives", derivatives(w[c])},
                   {"linear_steady_change", lin[c]}});
    }
    std::cout << a.dump(2) << '\n';
    return 0;
  }
  std::string on;
  for (const ParamStep& p : steps) on += (on.empty() ? "" : ", ") + p.param + (p.sign > 0 ? "+" : "-");
  std::cout << "fault " << fault << " on the graph: " << on << "\n\n"
            << "| channel | magnitude | slope | order | derivatives 0…N (TCG) | derivatives 0…N (weighted) | linearised steady change per unit ln θ |\n"
               "|---|---|---|---|---|---|---|\n";
  for (std::size_t c = 0; c < q.size(); ++c) {
    std::cout << fmt::format("| {} | {} | {} | {} | {} | {} | {:.4g} |\n", l.t.measured[c], sym(q[c].magnitude),
                             sym(q[c].slope), order_digit(q[c].order), render_derivatives(q[c]),
                             render_derivatives(w[c]), lin[c]);
  }
  return 0;
}

int run_circuit_tree(const CircuitSource& s, const std::string& channel, bool minus) {
  Loaded l;
  if (!load(s, l)) return 2;
  const FaultTreeNode tree = fault_tree(l.t.graph, channel, minus ? -1 : 1);
  std::cout << render_fault_tree(tree) << "\ncauses (shallowest first):";
  for (const TreeCause& c : tree_causes(tree)) {
    const std::string n = circuit_name(l.t, c.name);
    std::cout << ' ' << c.name << sym(c.sign) << (n.empty() || n == c.name ? "" : " (" + n + ")") << (c.ambiguous ? " [both signs]" : "");
  }
  std::cout << '\n';
  return 0;
}

int run_circuit_crosscheck(const CircuitSource& s, const std::vector<std::string>& cases,
                           const std::vector<std::string>& steps, double step, bool json) {
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(s.circuit, s.params, c)) {
    std::cerr << err->to_string() << '\n';
    return 2;
  }
  CircuitCrosscheckOptions opt;
  opt.step = step;
  try {
    if (!cases.empty()) opt.cases.push_back({"nominal", {}});
    for (const std::string& k : cases) {
      const auto [name, f] = name_value(k);
      opt.cases.push_back({fmt::format("{} x {:g}", name, f), {{name, f}}});
    }
    for (const std::string& k : steps) {
      opt.steps.push_back(name_value(k));
      if (!(opt.steps.back().second < 1.0)) throw std::invalid_argument("a fault step must be below 1 (a fraction): " + k);
    }
  } catch (const std::exception& e) {
    std::cerr << "hstmon-fdi crosscheck: " << e.what() << '\n';
    return 1;
  }
  const CircuitCrosscheck x = run_circuit_crosscheck(c, opt);
  const CircuitAgreement a = circuit_agreement(x);
  if (json) {
    nlohmann::json rows = nlohmann::json::array();
    for (const CircuitCrosscheckRow& r : x.rows) {
      nlohmann::json ch = nlohmann::json::array();
      for (std::size_t k = 0; k < r.channel.size(); ++k) {
        const CircuitChannelCheck& cc = r.channel[k];
        ch.push_back({{"channel", x.channels[k]}, {"ss", static_cast<int>(cc.ss)}, {"ss_rel", cc.ss_rel},
                      {"slope0", static_cast<int>(cc.slope0)}, {"order0", cc.order0},
                      {"tcg_slope", static_cast<int>(cc.tcg_slope)}, {"tcg_order", cc.tcg_order},
                      {"tcg_weighted", static_cast<int>(cc.tcg_weighted)}, {"lin", static_cast<int>(cc.lin)}});
      }
      rows.push_back({{"case", r.case_name}, {"fault", r.fault}, {"step", r.step}, {"channels", ch}});
    }
    const nlohmann::json agree = {{"readings", a.readings}, {"magnitude", a.magnitude}, {"linear", a.linear},
                                  {"slope", a.slope}, {"order", a.order}, {"weighted", a.weighted}};
    std::cout << nlohmann::json{{"circuit", c.file.name}, {"rows", rows}, {"agreement", agree}, {"notes", x.notes}}.dump(2) << '\n';
    return 0;
  }
  std::string head;
  for (const std::string& n : x.channels) head += (head.empty() ? "" : " ") + n;
  std::string current;
  for (const CircuitCrosscheckRow& r : x.rows) {
    if (r.case_name != current) {
      current = r.case_name;
      std::cout << "\n### " << current << "\n\nEach cell: " << head
                << ". ss = nonlinear steady-state sign; lin = linearised graph's steady state; TCG = qualitative "
                   "slope and order; 0+ = nonlinear first non-zero derivative and its order; w = TCG weighted by the operating-point gains.\n\n"
                   "| fault | step | ss | lin | TCG | TCG order | 0+ | 0+ order | w |\n|---|---|---|---|---|---|---|---|---|\n";
    }
    std::string ss, lin, tcg, to, s0, o0, w;
    for (const CircuitChannelCheck& cc : r.channel) {
      ss += sym(cc.ss);
      lin += sym(cc.lin);
      tcg += sym(cc.tcg_slope);
      to += order_digit(cc.tcg_order);
      s0 += sym(cc.slope0);
      o0 += order_digit(cc.order0);
      w += sym(cc.tcg_weighted);
    }
    std::cout << fmt::format("| {} | {:.0f} % | {} | {} | {} | {} | {} | {} | {} |\n", r.fault, 100.0 * r.step, ss, lin,
                             tcg, to, s0, o0, w);
  }
  std::cout << fmt::format(
      "\n### Agreement over {} fault × channel × case readings\n\n| comparison | agree |\n|---|---|\n"
      "| TCG magnitude (first effect persists) vs nonlinear steady state | {} |\n"
      "| linearised graph's steady state vs nonlinear | {} |\n"
      "| TCG slope vs nonlinear slope at 0+ (? agrees) | {} |\n"
      "| TCG order vs nonlinear order at 0+ | {} |\n"
      "| weighted TCG slope vs nonlinear slope at 0+ | {} |\n",
      a.readings, a.magnitude, a.linear, a.slope, a.order, a.weighted);
  if (!x.notes.empty()) {
    std::cout << "\nNot checked:";
    for (const std::string& n : x.notes) std::cout << "\n- " << n;
    std::cout << '\n';
  }
  return 0;
}

}  // namespace hstmon::fdi
