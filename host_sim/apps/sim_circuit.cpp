#include "sim_circuit.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
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
  std::string profile_note;
  if (!a.inputs.empty()) {
    // A logged run's inputs: its span and median rate unless given.
    const circuit_tools::CircuitLog in = circuit_tools::read_circuit_log(a.inputs, c.file);
    for (const auto& n : in.notes) std::cerr << n << '\n';
    if (in.error) {
      std::cerr << in.error->to_string() << '\n';
      return 2;
    }
    std::size_t columns = 0;
    for (const auto& col : in.inputs) columns += col.size() == in.rows() ? 1 : 0;
    if (in.rows() < 2 || columns == 0) {
      std::cerr << a.inputs << ": error: --inputs needs at least 2 rows and one of the circuit's input columns\n";
      return 2;
    }
    o.steps = circuit_tools::logged_input_steps(in);
    const double span = in.t.back() - in.t.front();
    o.rate = static_cast<double>(in.rows() - 1) / span;
    o.duration = span + 1.0 / o.rate;
    profile_note = "inputs from " + a.inputs + ": " + std::to_string(columns) + " column(s), " +
                   std::to_string(in.rows()) + " rows, each held until the next (zero-order hold)";
  }
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
  if (!profile_note.empty()) comments.push_back(profile_note);
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
