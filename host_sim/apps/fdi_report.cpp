/// @file fdi_report.cpp
#include "fdi_report.hpp"

#include <fmt/format.h>

#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

std::string sym(QualSign q) { return std::string(1, qual_symbol(q)); }

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

}  // namespace hstmon::fdi
