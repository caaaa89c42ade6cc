/// @file fdi_app.cpp
/// hstmon-fdi: qualitative diagnosis of the thesis rig on the host.
///   hstmon-fdi graph [--nonlinear] [--json]          edges of the temporal causal graph
///   hstmon-fdi tree CHANNEL [--minus] [--linearised] fault tree of p_mi|p_mo|p_pp|w_m (or any node)
///   hstmon-fdi backward e31+ [--nonlinear] [--json]  fault candidates of an observation
///   hstmon-fdi forward kp- [--order N] [--linearised] [--json]  predicted signature
///   hstmon-fdi crosscheck [--t-early S] [--json]     TCG vs the nonlinear model
///   hstmon-fdi header --out FILE [--sigma-p BAR] [--sigma-w RPM] [--step F] [--order N]
///   hstmon-fdi isolability --circuit FILE [--params FILE] [--json] [--steady-only]  any circuit: detectability, classes
///   hstmon-fdi sensors --circuit FILE [--params FILE] [--json] [--steady-only]      any circuit: added sensors ranked
///   hstmon-fdi table --circuit FILE [--params FILE] --name NAME --out FILE  any circuit: constexpr fault table
/// graph, tree, backward, forward and crosscheck take --circuit FILE [--params FILE] too: the
/// circuit's own bond graph and TCG (docs/fdi.md, "Any circuit"), e.g.
///   hstmon-fdi backward --circuit examples/circuits/thesis.json p_pp+
///   hstmon-fdi forward --circuit examples/circuits/thesis.json kp-
///   hstmon-fdi crosscheck --circuit examples/circuits/thesis.json --case kp=1.6 --case kp=0.65 --fault-step kp=0.5
/// backward and graph default to the linearised graph of Fig. 2.14 (the thesis's TCG);
/// tree and forward default to Fig. 2.3's parameters (kp, kfi, kfo), the names of the catalogue.

#include <CLI/CLI.hpp>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli_validators.hpp"
#include "fdi_circuit.hpp"
#include "fdi_circuit_tcg.hpp"
#include "fdi_report.hpp"
#include "hstmon_fdi/backward.hpp"
#include "hstmon_fdi/crosscheck.hpp"
#include "hstmon_fdi/fault_catalogue.hpp"
#include "hstmon_fdi/fault_tree.hpp"
#include "hstmon_fdi/forward.hpp"
#include "hstmon_fdi/signature_table.hpp"
#include "hstmon_fdi/thesis_tcg.hpp"

namespace {

using namespace hstmon::fdi;

ValveModel valves(bool linearised) { return linearised ? ValveModel::kLinearised : ValveModel::kNonlinear; }

/// Accepts the thesis's variable names for the measured channels too.
std::string channel_node(const std::string& name) {
  if (name == "Pmi") return "p_mi";
  if (name == "Pmo") return "p_mo";
  if (name == "Ppp") return "p_pp";
  if (name == "wm" || name == "omega_m") return "w_m";
  return name;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hstmon-fdi: bond graph, temporal causal graph, fault trees and signature table of the thesis HST"};
  app.require_subcommand(1);

  bool json = false, nonlinear = false, linearised = false, minus = false;
  std::string observation, channel, fault, out;
  int order = 4;
  CrosscheckOptions cc;
  SignatureOptions so;
  double sigma_p_bar = so.sigma_pressure / 1e5;

  CLI::App* graph = app.add_subcommand("graph", "edges of the temporal causal graph (Markdown table)");
  graph->add_flag("--nonlinear", nonlinear, "Fig. 2.3 valve parameters (kfi, kfo, kp) instead of Fig. 2.14 (Rin, Rout, Rpl)");
  graph->add_flag("--json", json, "JSON output");

  CLI::App* tree = app.add_subcommand("tree", "fault tree of a channel going up (or --minus down)");
  tree->add_option("channel", channel, "p_mi | p_mo | p_pp | w_m (or Pmi, …, or any node e4, f24)")->required();
  tree->add_flag("--minus", minus, "root event is a decrease");
  tree->add_flag("--linearised", linearised, "Fig. 2.14 parameters (Rin, Rout, Rpl)");

  CLI::App* back = app.add_subcommand("backward", "fault candidates of an observation, e.g. e31+ or p_pp+");
  back->add_option("observation", observation, "node with + or -")->required();
  back->add_flag("--nonlinear", nonlinear, "Fig. 2.3 valve parameters");
  back->add_flag("--json", json, "JSON output");

  CLI::App* fwd = app.add_subcommand("forward", "predicted signature of a fault, e.g. kp- or Rpl+");
  fwd->add_option("fault", fault, "catalogue fault (kp-, Rbl+, …) or graph parameter (Rpl+, Kpmi-)")->required();
  fwd->add_option("--order", order, "highest derivative predicted")->check(CLI::Range(0, 12));
  fwd->add_flag("--linearised", linearised, "Fig. 2.14 graph (Rin, Rout, Rpl)");
  fwd->add_flag("--json", json, "JSON output");

  CLI::App* check = app.add_subcommand("crosscheck", "TCG predictions against the nonlinear model");
  check->add_option("--t-early", cc.t_early, "reference deviation read this long after the fault [s]")->check(hstmon::cli::positive_number());
  check->add_flag("--json", json, "JSON output");

  CLI::App* header = app.add_subcommand("header", "write the constexpr signature table");
  header->add_option("--out", out, "output file, - for stdout")->required();
  header->add_option("--sigma-p", sigma_p_bar, "pressure noise level [bar]")->check(hstmon::cli::positive_number());
  header->add_option("--sigma-w", so.sigma_speed_rpm, "speed noise level [rpm]")->check(hstmon::cli::positive_number());
  header->add_option("--step", so.direction_step, "relative fault size for the direction vector")->check(CLI::Range(1e-6, 0.5));
  header->add_option("--order", so.max_order, "highest derivative order of the TCG")->check(CLI::Range(0, 12));

  std::string circuit, circuit_params;
  CLI::App* iso = app.add_subcommand("isolability", "any circuit file: which faults its sensors detect and tell apart");
  CLI::App* place = app.add_subcommand("sensors", "any circuit file: which added sensor tells most faults apart");
  std::string table_name;
  CLI::App* table = app.add_subcommand("table", "any circuit file: its fault table as a constexpr header for firmware");
  table->add_option("--name", table_name, "namespace hstmon::generated::NAME (a C++ identifier)")->required();
  table->add_option("--out", out, "output file, - for stdout")->required();
  for (CLI::App* sub : {iso, place, table}) {
    sub->add_option("--circuit", circuit, "circuit file (docs/circuits.md)")->required();
    sub->add_option("--params", circuit_params, "its parameter file (default <stem>.params.json beside it)");
    sub->add_flag("--json", json, "JSON output");
  }
  bool steady_only = false;
  for (CLI::App* sub : {iso, place}) {
    sub->add_flag("--steady-only", steady_only,
                  "judge on the steady magnitudes and directions alone (default: with the slopes and orders the monitor's table has)");
  }

  // The circuit versions of the thesis commands.
  std::vector<std::string> cases, fault_steps_opt;
  double step = 0.1;
  for (CLI::App* sub : {graph, tree, back, fwd, check}) {
    sub->add_option("--circuit", circuit, "any circuit file: its own bond graph and TCG (docs/fdi.md)");
    sub->add_option("--params", circuit_params, "with --circuit: its parameter file (default <stem>.params.json)");
  }
  check->add_option("--case", cases, "with --circuit: an operating point NAME=FACTOR (input or parameter scaled); repeatable")->take_all();
  check->add_option("--fault-step", fault_steps_opt, "with --circuit: relative step of one fault NAME=STEP; repeatable");
  check->add_option("--step", step, "with --circuit: relative step of every other fault")->check(CLI::Range(1e-6, 0.9));

  CLI11_PARSE(app, argc, argv);
  try {
    const bool circuit_cmd = !circuit.empty() && !(*iso || *place || *table);
    // Options of one kind of graph are refused with the other, not silently ignored.
    if (circuit_cmd && (nonlinear || linearised || check->count("--t-early") > 0)) {
      std::cerr << "hstmon-fdi: --nonlinear, --linearised and --t-early are for the thesis graph, not --circuit\n";
      return 1;
    }
    if (circuit.empty() && (!cases.empty() || !fault_steps_opt.empty() || check->count("--step") > 0 ||
                            !circuit_params.empty())) {
      std::cerr << "hstmon-fdi: --case, --fault-step, --step and --params need --circuit\n";
      return 1;
    }
    if (circuit_cmd) {
      const CircuitSource src{circuit, circuit_params};
      if (*graph) return run_circuit_graph(src, json);
      if (*tree) return run_circuit_tree(src, channel, minus);
      if (*back) return run_circuit_backward(src, observation, json);
      if (*fwd) return run_circuit_forward(src, fault, order, json);
      if (*check) return run_circuit_crosscheck(src, cases, fault_steps_opt, step, json);
    }
    if (*iso) return hstmon::fdi::run_isolability(circuit, circuit_params, json, steady_only);
    if (*place) return hstmon::fdi::run_sensor_placement(circuit, circuit_params, json, steady_only);
    if (*table) return hstmon::fdi::run_table_header(circuit, circuit_params, table_name, out);
    if (*graph) {
      const CausalGraph g = thesis_tcg(valves(!nonlinear));
      std::cout << (json ? json_edges(g).dump(2) + "\n" : markdown_edges(g));
    } else if (*tree) {
      const CausalGraph g = thesis_tcg(valves(linearised));
      std::cout << render_fault_tree(fault_tree(g, channel_node(channel), minus ? -1 : 1));
    } else if (*back) {
      std::string node;
      int sign = 0;
      parse_observation(observation, node, sign);
      const CausalGraph g = thesis_tcg(valves(!nonlinear));
      const BackwardResult r = backward_propagate(g, channel_node(node), sign);
      std::cout << (json ? json_backward(r).dump(2) + "\n" : text_backward(r));
    } else if (*fwd) {
      std::string param;
      int sign = 0;
      parse_fault(fault, param, sign);
      const ValveModel v = valves(linearised);
      const CausalGraph g = thesis_tcg(v);
      const std::vector<ParamStep> steps = fault_steps(param, sign, v);
      const ForwardResult q = forward_qualitative(g, steps, order);
      const ForwardResult w = forward_weighted(g, steps, order);
      std::cout << (json ? json_forward(q, w).dump(2) + "\n" : markdown_forward(q, w));
    } else if (*check) {
      const std::vector<CrosscheckRow> rows = run_crosscheck(cc);
      std::cout << (json ? json_crosscheck(rows).dump(2) + "\n" : markdown_crosscheck(rows));
    } else if (*header) {
      so.sigma_pressure = sigma_p_bar * 1e5;
      const std::string text = render_signature_header(build_signature_rows(so), so);
      if (out == "-") {
        std::cout << text;
      } else {
        std::ofstream f(out, std::ios::binary);
        if (!(f << text)) throw std::runtime_error("cannot write " + out);
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "hstmon-fdi: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
