/// @file fdi_app.cpp
/// hstmon-fdi: qualitative diagnosis of a circuit on the host, from its own bond graph and
/// temporal causal graph (docs/fdi.md). Every subcommand takes --circuit FILE [--params
/// FILE]; without --circuit the circuit is the thesis rig (examples/circuits/thesis.json,
/// built in), as for `hstmon replay`.
///   hstmon-fdi graph [--json]                          bond graph, causality, TCG edges
///   hstmon-fdi tree CHANNEL [--minus]                  fault tree of a sensor (or any node)
///   hstmon-fdi backward p_pp+ [--json]                 fault candidates of an observation
///   hstmon-fdi forward kp- [--order N] [--json]        predicted signature
///   hstmon-fdi crosscheck [--case N=F] [--fault-step N=S] [--step S] [--json]  TCG vs the nonlinear model
///   hstmon-fdi isolability [--json] [--steady-only]    which faults its sensors detect and tell apart
///   hstmon-fdi sensors [--json] [--steady-only]        which added sensor tells most faults apart
///   hstmon-fdi table --name NAME --out FILE            its fault table as a constexpr header for firmware

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "fdi_circuit.hpp"
#include "fdi_circuit_tcg.hpp"

int main(int argc, char** argv) {
  using namespace hstmon::fdi;
  CLI::App app{
      "hstmon-fdi: bond graph, temporal causal graph, fault trees, isolability and fault table of a circuit "
      "(the thesis rig without --circuit)"};
  app.require_subcommand(1);
  bool json = false, minus = false, steady_only = false;
  std::string observation, channel, fault, out, table_name;
  int order = 4;
  std::vector<std::string> cases, fault_steps;
  double step = 0.1;
  CircuitSource src;

  CLI::App* graph = app.add_subcommand("graph", "bond graph with its causality, and the temporal causal graph's edges");
  CLI::App* tree = app.add_subcommand("tree", "fault tree of a channel going up (or --minus down)");
  tree->add_option("channel", channel, "a sensor channel (p_pp, w_m, ...) or any graph node (e4, f24)")->required();
  tree->add_flag("--minus", minus, "root event is a decrease");
  CLI::App* back = app.add_subcommand("backward", "fault candidates of an observation, e.g. p_pp+ or e6-");
  back->add_option("observation", observation, "sensor channel or node with + or -")->required();
  CLI::App* fwd = app.add_subcommand("forward", "predicted signature of a fault, e.g. kp- or prv.k-");
  fwd->add_option("fault", fault, "circuit parameter or input (kp-), or graph parameter (prv.k-), with + or -")
      ->required();
  fwd->add_option("--order", order, "highest derivative predicted")->check(CLI::Range(0, 12));
  CLI::App* check = app.add_subcommand("crosscheck", "TCG predictions against the nonlinear model");
  check->add_option("--case", cases, "an operating point NAME=FACTOR (input or parameter scaled); repeatable")
      ->take_all();
  check->add_option("--fault-step", fault_steps, "relative step of one fault NAME=STEP; repeatable");
  check->add_option("--step", step, "relative step of every other fault")->check(CLI::Range(1e-6, 0.9));
  CLI::App* iso = app.add_subcommand("isolability", "which faults the circuit's sensors detect and tell apart");
  CLI::App* place = app.add_subcommand("sensors", "which added sensor tells most faults apart");
  CLI::App* table = app.add_subcommand("table", "the circuit's fault table as a constexpr header for firmware");
  table->add_option("--name", table_name, "namespace hstmon::generated::NAME (a C++ identifier)")->required();
  table->add_option("--out", out, "output file, - for stdout")->required();
  for (CLI::App* sub : {graph, tree, back, fwd, check, iso, place, table}) {
    sub->add_option("--circuit", src.circuit, "circuit file (docs/circuits.md); default the thesis rig (thesis.json)");
    sub->add_option("--params", src.params, "its parameter file (default <stem>.params.json beside it)");
  }
  for (CLI::App* sub : {graph, back, fwd, check, iso, place}) sub->add_flag("--json", json, "JSON output");
  for (CLI::App* sub : {iso, place}) {
    sub->add_flag("--steady-only", steady_only,
                  "judge on the steady magnitudes and directions alone (default: with the slopes and orders the monitor's table has)");
  }

  CLI11_PARSE(app, argc, argv);
  try {
    if (*graph) return run_circuit_graph(src, json);
    if (*tree) return run_circuit_tree(src, channel, minus);
    if (*back) return run_circuit_backward(src, observation, json);
    if (*fwd) return run_circuit_forward(src, fault, order, json);
    if (*check) return run_circuit_crosscheck(src, cases, fault_steps, step, json);
    if (*iso) return run_isolability(src.circuit, src.params, json, steady_only);
    if (*place) return run_sensor_placement(src.circuit, src.params, json, steady_only);
    if (*table) return run_table_header(src.circuit, src.params, table_name, out);
  } catch (const std::exception& e) {
    std::cerr << "hstmon-fdi: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
