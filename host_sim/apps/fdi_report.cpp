/// @file fdi_report.cpp
#include "fdi_report.hpp"

#include <fmt/format.h>

#include "hstmon_fdi/qual.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"

namespace hstmon::fdi {

namespace {

std::string sym(QualSign q) { return std::string(1, qual_symbol(q)); }

const char* kChannelTitles[4] = {"Pmi", "Pmo", "Ppp", "wm"};

/// Four symbols in channel order, one per channel.
template <class F>
std::string four(const CrosscheckRow& r, F f) {
  std::string s;
  for (const ChannelCheck& c : r.channel) s += f(c);
  return s;
}

std::string order_digit(int k) { return k < 0 ? "." : std::to_string(k); }

}  // namespace

std::string markdown_edges(const CausalGraph& g) {
  std::string s = "| to | from | sign | type | parameter | element | relation | gain at op. point |\n|---|---|---|---|---|---|---|---|\n";
  for (const Edge& e : g.edges()) {
    const std::string par = e.param.empty() ? "" : e.param + (e.param_sign > 0 ? " (+)" : " (−)");
    const std::string type = e.type == EdgeType::kInstant ? "inst" : edge_type_symbol(e.type);
    s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.4g} |\n", g.nodes()[static_cast<std::size_t>(e.to)].name,
                     g.nodes()[static_cast<std::size_t>(e.from)].name, e.sign > 0 ? "+" : "−", type, par, e.element,
                     e.relation, e.gain);
  }
  return s;
}

nlohmann::json json_edges(const CausalGraph& g) {
  nlohmann::json a = nlohmann::json::array();
  for (const Edge& e : g.edges()) {
    a.push_back({{"to", g.nodes()[static_cast<std::size_t>(e.to)].name},
                 {"from", g.nodes()[static_cast<std::size_t>(e.from)].name},
                 {"sign", e.sign},
                 {"type", e.type == EdgeType::kInstant ? "inst" : edge_type_symbol(e.type)},
                 {"param", e.param},
                 {"param_sign", e.param_sign},
                 {"element", e.element},
                 {"relation", e.relation},
                 {"gain", e.gain},
                 {"injection", e.injection}});
  }
  return a;
}

std::string text_backward(const BackwardResult& r) {
  std::string s = "parameters:";
  for (const Candidate& c : r.candidates) {
    if (!c.input) s += " " + c.name + sym(c.sign);
  }
  s += "\ninputs:";
  for (const Candidate& c : r.candidates) {
    if (c.input) s += " " + c.name + sym(c.sign);
  }
  s += "\n\n| candidate | order | path |\n|---|---|---|\n";
  for (const Candidate& c : r.candidates) {
    std::string path;
    for (const std::string& n : c.path) path += (path.empty() ? "" : " ← ") + n;
    s += fmt::format("| {}{}{} | {} | {} |\n", c.name, sym(c.sign), c.input ? " (input)" : "", c.order, path);
  }
  s += "\nconflicts (held / wanted):";
  for (const Conflict& c : r.conflicts) s += " " + c.name + sym(c.held) + "/" + sym(c.wanted);
  s += "\n";
  return s;
}

nlohmann::json json_backward(const BackwardResult& r) {
  nlohmann::json j;
  j["candidates"] = nlohmann::json::array();
  for (const Candidate& c : r.candidates) {
    j["candidates"].push_back({{"name", c.name}, {"sign", static_cast<int>(c.sign)}, {"order", c.order}, {"input", c.input}, {"path", c.path}});
  }
  j["conflicts"] = nlohmann::json::array();
  for (const Conflict& c : r.conflicts) {
    j["conflicts"].push_back({{"name", c.name}, {"held", static_cast<int>(c.held)}, {"wanted", static_cast<int>(c.wanted)}});
  }
  return j;
}

std::string markdown_forward(const ForwardResult& q, const ForwardResult& w) {
  std::string s = "| channel | magnitude | slope | order | derivatives 0…N (TCG) | derivatives 0…N (weighted) |\n|---|---|---|---|---|---|\n";
  for (std::size_t c = 0; c < 4; ++c) {
    const ChannelPrediction& p = q.channel[c];
    s += fmt::format("| {} | {} | {} | {} | {} | {} |\n", kChannelTitles[c], sym(p.magnitude), sym(p.slope),
                     order_digit(p.order), render_derivatives(p), render_derivatives(w.channel[c]));
  }
  return s;
}

nlohmann::json json_forward(const ForwardResult& q, const ForwardResult& w) {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t c = 0; c < 4; ++c) {
    auto derivs = [](const ChannelPrediction& p) {
      std::vector<int> v;
      for (QualSign d : p.derivative) v.push_back(static_cast<int>(d));
      return v;
    };
    a.push_back({{"channel", kMeasurementNodes[c]},
                 {"magnitude", static_cast<int>(q.channel[c].magnitude)},
                 {"slope", static_cast<int>(q.channel[c].slope)},
                 {"order", q.channel[c].order},
                 {"derivatives", derivs(q.channel[c])},
                 {"weighted_derivatives", derivs(w.channel[c])}});
  }
  return a;
}

std::string markdown_crosscheck(const std::vector<CrosscheckRow>& rows) {
  std::string s;
  std::string current;
  int n = 0, mag_tcg = 0, mag_sec = 0, mag_tan = 0, slope = 0, order = 0, weighted = 0, early = 0, early_n = 0;
  std::string disagreements;
  for (const CrosscheckRow& r : rows) {
    if (r.case_name != current) {
      current = r.case_name;
      s += "\n### " + current + "\n\nEach cell: Pmi Pmo Ppp ωm. ss = nonlinear steady-state sign; lin = linearised "
           "graph's steady state (secant Fig. 2.14 / tangent); TCG = qualitative slope and order (= the thesis's "
           "magnitude); 0+ = nonlinear first non-zero derivative and its order; w = TCG weighted by the "
           "operating-point gains; ref = stiff reference deviation at t_early (· below resolution).\n\n"
           "| fault | step | ss | lin sec | lin tan | TCG | TCG order | 0+ | 0+ order | w | ref |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|\n";
    }
    s += fmt::format(
        "| {} | {:.0f} % | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.fault, 100.0 * r.step,
        four(r, [](const ChannelCheck& c) { return sym(c.ss); }), four(r, [](const ChannelCheck& c) { return sym(c.lin_secant); }),
        four(r, [](const ChannelCheck& c) { return sym(c.lin_tangent); }), four(r, [](const ChannelCheck& c) { return sym(c.tcg_slope); }),
        four(r, [](const ChannelCheck& c) { return order_digit(c.tcg_order); }), four(r, [](const ChannelCheck& c) { return sym(c.slope0); }),
        four(r, [](const ChannelCheck& c) { return order_digit(c.order0); }), four(r, [](const ChannelCheck& c) { return sym(c.tcg_weighted); }),
        four(r, [](const ChannelCheck& c) { return c.early == kQualAny ? std::string("·") : sym(c.early); }));
    for (std::size_t k = 0; k < 4; ++k) {
      const ChannelCheck& c = r.channel[k];
      ++n;
      const bool m = c.tcg_slope == c.ss;
      mag_tcg += m;
      mag_sec += c.lin_secant == c.ss;
      mag_tan += c.lin_tangent == c.ss;
      slope += qual_agrees(c.tcg_slope, c.slope0);
      order += c.tcg_order == c.order0;
      weighted += c.tcg_weighted == c.slope0;
      if (c.early != kQualAny) {
        ++early_n;
        early += c.early == c.slope0;
      }
      if (!m) {
        disagreements += fmt::format("{}@{} {}: TCG {} vs ss {}; ", r.fault, r.case_name, kChannelTitles[k], sym(c.tcg_slope), sym(c.ss));
      }
    }
  }
  s += fmt::format(
      "\n### Agreement over {} fault × channel × case readings\n\n"
      "| comparison | agree |\n|---|---|\n"
      "| TCG magnitude (thesis reading) vs nonlinear steady state | {} |\n"
      "| linearised steady state, secant (Fig. 2.14) vs nonlinear | {} |\n"
      "| linearised steady state, tangent vs nonlinear | {} |\n"
      "| TCG slope vs nonlinear slope at 0+ (? agrees) | {} |\n"
      "| TCG order vs nonlinear order at 0+ | {} |\n"
      "| weighted TCG slope vs nonlinear slope at 0+ | {} |\n"
      "| stiff reference at t_early vs nonlinear slope at 0+ (resolved only) | {} of {} |\n",
      n, mag_tcg, mag_sec, mag_tan, slope, order, weighted, early, early_n);
  s += "\nTCG magnitude ≠ nonlinear steady state: " + disagreements + "\n";
  return s;
}

nlohmann::json json_crosscheck(const std::vector<CrosscheckRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const CrosscheckRow& r : rows) {
    nlohmann::json ch = nlohmann::json::array();
    for (std::size_t k = 0; k < 4; ++k) {
      const ChannelCheck& c = r.channel[k];
      ch.push_back({{"channel", kMeasurementNodes[k]},
                    {"ss", static_cast<int>(c.ss)},
                    {"ss_rel", c.ss_rel},
                    {"slope0", static_cast<int>(c.slope0)},
                    {"order0", c.order0},
                    {"early", static_cast<int>(c.early)},
                    {"tcg_slope", static_cast<int>(c.tcg_slope)},
                    {"tcg_order", c.tcg_order},
                    {"tcg_weighted", static_cast<int>(c.tcg_weighted)},
                    {"lin_secant", static_cast<int>(c.lin_secant)},
                    {"lin_tangent", static_cast<int>(c.lin_tangent)}});
    }
    a.push_back({{"case", r.case_name}, {"fault", r.fault}, {"step", r.step}, {"channels", ch}});
  }
  return a;
}

}  // namespace hstmon::fdi
