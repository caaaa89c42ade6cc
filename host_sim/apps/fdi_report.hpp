#pragma once
/// @file fdi_report.hpp
/// Text (Markdown) and JSON renderings of the hstmon-fdi results, shared by the
/// subcommands of hstmon-fdi (fdi_circuit_tcg.cpp).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hstmon_fdi/backward.hpp"
#include "hstmon_fdi/causal_graph.hpp"

namespace hstmon::fdi {

/// Markdown table of the edges: to, from, sign, type, parameter, element, relation, gain.
std::string markdown_edges(const CausalGraph& g);
/// The edges as a JSON array.
nlohmann::json json_edges(const CausalGraph& g);

/// Candidates and conflicts as text.
std::string text_backward(const BackwardResult& r);
/// Candidates and conflicts as JSON.
nlohmann::json json_backward(const BackwardResult& r);

}  // namespace hstmon::fdi
