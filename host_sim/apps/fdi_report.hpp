#pragma once
/// @file fdi_report.hpp
/// Text (Markdown) and JSON renderings of the hstmon-fdi results, shared by the
/// subcommands of fdi_app.cpp.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hstmon_fdi/backward.hpp"
#include "hstmon_fdi/causal_graph.hpp"
#include "hstmon_fdi/crosscheck.hpp"
#include "hstmon_fdi/forward.hpp"

namespace hstmon::fdi {

/// Markdown table of the edges: to, from, sign, type, parameter, element, relation, gain.
std::string markdown_edges(const CausalGraph& g);
/// The edges as a JSON array.
nlohmann::json json_edges(const CausalGraph& g);

/// Candidates and conflicts as text.
std::string text_backward(const BackwardResult& r);
/// Candidates and conflicts as JSON.
nlohmann::json json_backward(const BackwardResult& r);

/// Predictions per channel as a Markdown table.
std::string markdown_forward(const ForwardResult& q, const ForwardResult& w);
/// Predictions per channel as JSON.
nlohmann::json json_forward(const ForwardResult& q, const ForwardResult& w);

/// The cross-check as Markdown: one table per operating case, then the agreement counts.
std::string markdown_crosscheck(const std::vector<CrosscheckRow>& rows);
/// The cross-check as JSON.
nlohmann::json json_crosscheck(const std::vector<CrosscheckRow>& rows);

}  // namespace hstmon::fdi
