#pragma once
/// @file fault_catalogue.hpp
/// The single-parameter faults of the thesis model: which field of ThesisParams or
/// ThesisInputs each one changes, and which parameters of the temporal causal graph it
/// stands for (the graph splits Rbl into Rbl1 + Rbl2, K into Kpmi, Kpmo, Kpp, …).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_fdi/thesis_bond_graph.hpp"
#include "hstmon_fdi/thesis_forward.hpp"

namespace hstmon::fdi {

/// One model parameter that can be faulty.
struct FaultParameter {
  std::string name;        ///< seed name: "kp", "kf", "Psupl", "Pbp", "Rbl", "Rf", "Dp", "Dm", "Rlkg", "Ripl", "J", "K"
  std::string meaning;     ///< what it is
  double crosscheck_step = 0.1;  ///< relative step of the nonlinear cross-check (0.1; 0.5 for kp) [-]
  bool up_in_table = true;       ///< the increase is a physical fault and gets a table row
  bool down_in_table = true;     ///< the decrease is a physical fault and gets a table row
};

/// The catalogue, in table order.
const std::vector<FaultParameter>& fault_parameters();

/// Catalogue entry by name, or nullptr.
const FaultParameter* find_fault_parameter(std::string_view name);

/// Multiplies parameter `name` by `factor` in (p, u).
/// @throws std::invalid_argument for an unknown name
void scale_parameter(std::string_view name, double factor, ThesisParams<double>& p, ThesisInputs<double>& u);

/// The graph parameters (or sources) that parameter `name` stands for in a graph with
/// the given valve model, each with the sign relating them (kp ↔ Rpl: −1).
/// @throws std::invalid_argument for an unknown name
std::vector<ParamStep> graph_parameters(std::string_view name, ValveModel valves);

/// Fault name "<parameter><+|->".
std::string fault_name(std::string_view param, int sign);

/// Parses a fault name "kp-" or a graph parameter fault "Rpl+" into a parameter name and sign.
/// @throws std::invalid_argument without a trailing '+' or '-'
void parse_fault(const std::string& text, std::string& param, int& sign);

/// The steps of the graph for fault (param, sign): a catalogue name maps through
/// graph_parameters; any other name is taken as a graph parameter or source itself.
std::vector<ParamStep> fault_steps(const std::string& param, int sign, ValveModel valves);

}  // namespace hstmon::fdi
