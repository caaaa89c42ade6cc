#include "sim_circuit.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_sim.hpp"

namespace hstmon::sim_app {

namespace {

std::string shortest(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

int run_circuit_sim(const CircuitSimArgs& a) {
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    std::cerr << err->to_string() << '\n';
    return 2;
  }
  circuit_tools::CircuitSimOptions o;
  if (a.duration > 0.0) o.duration = a.duration;
  if (a.rate > 0.0) o.rate = a.rate;
  o.seed = a.seed;
  o.from_rest = a.start == "rest";
  o.noise = !a.no_noise;
  for (const std::string& s : a.steps) {
    circuit_tools::InputStep st;
    if (auto err = circuit_tools::parse_input_step(s, c.file, st)) {
      std::cerr << "hstmon-sim: " << *err << '\n';
      return 1;
    }
    o.steps.push_back(st);
  }
  for (const std::string& s : a.faults) {
    circuit_tools::InputStep st;
    if (auto err = circuit_tools::parse_param_fault(s, c.file, st)) {
      std::cerr << "hstmon-sim: " << *err << '\n';
      return 1;
    }
    o.steps.push_back(st);
  }
  circuit_tools::CircuitLog log;
  try {
    log = circuit_tools::simulate_circuit(c, o);
  } catch (const std::exception& e) {
    std::cerr << "hstmon-sim: " << e.what() << '\n';
    return 2;
  }
  std::vector<std::string> comments = {
      "hstmon-sim --circuit " + a.circuit + (c.params_path.empty() ? std::string() : " --params " + c.params_path),
      "circuit " + c.file.name + ": full equations (Rosenbrock-4), " + (o.from_rest ? "from rest" : "from steady state") +
          ", " + shortest(o.duration) + " s at " + shortest(o.rate) + " Hz, seed " + std::to_string(o.seed) +
          (o.noise ? "" : ", no noise")};
  for (const std::string& s : a.steps) comments.push_back("step " + s);
  for (const std::string& s : a.faults) comments.push_back("fault " + s);
  const std::string text = circuit_tools::circuit_log_text(c.file, log, comments);
  if (a.out == "-") {
    std::cout << text;
    std::cout.flush();
    return std::cout ? 0 : 2;
  }
  std::ofstream f(a.out, std::ios::binary);
  if (!f) {
    std::cerr << "hstmon-sim: cannot open " << a.out << '\n';
    return 2;
  }
  f << text;
  f.close();
  if (!f) {
    std::cerr << "hstmon-sim: write failed: " << a.out << '\n';
    return 2;
  }
  return 0;
}

}  // namespace hstmon::sim_app
