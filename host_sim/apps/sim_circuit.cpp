#include "sim_circuit.hpp"

#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <string>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_circuit/logged_run.hpp"
#include "hstmon_circuit/machine_spread.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_sensors/sensor_presets.hpp"  // kPaPerBar
#include "sim_compare.hpp"

namespace hstmon::sim_app {

namespace {

// The log's comment on the transducers ("" when ideal).
std::string transducer_note(const circuit_tools::TransducerOptions& t) {
  std::string s;
  if (t.lag > 0.0) s += "lag " + host::number_text(t.lag * 1e3) + " ms";
  if (t.pressure_adc_bits > 0) {
    s += (s.empty() ? "" : ", ") + std::string("pressure ADC ") + std::to_string(t.pressure_adc_bits) + " bits";
  } else if (t.pressure_step > 0.0) {
    s += (s.empty() ? "" : ", ") + std::string("pressure step ") + host::number_text(t.pressure_step / sim::kPaPerBar) +
         " bar";
  }
  return s.empty() ? s : "transducers: " + s;
}

// Appends each of specs, read by parse (--step's or --fault's parser), to steps; false after
// printing the first error.
template <class Parse>
bool parse_steps(const std::vector<std::string>& specs, Parse parse, const host::CircuitFile& file,
                 std::vector<circuit_tools::InputStep>& steps) {
  for (const std::string& s : specs) {
    circuit_tools::InputStep st;
    if (auto err = parse(s, file, st)) {
      std::cerr << "hstmon-sim: " << *err << '\n';
      return false;
    }
    steps.push_back(st);
  }
  return true;
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
  circuit_tools::CircuitLog measured;
  const std::optional<circuit_tools::InputHold> hold = circuit_tools::input_hold_from(a.inputs_hold);
  if (!hold) {
    std::cerr << "hstmon-sim: --inputs-hold takes linear or step, got '" << a.inputs_hold << "'\n";
    return 1;
  }
  if (!a.inputs.empty()) {
    // A logged run's inputs, on its own clock and rows (logged_run.hpp).
    measured = circuit_tools::read_circuit_log(a.inputs, c.file);
    for (const auto& n : measured.notes) std::cerr << n << '\n';
    if (measured.error) {
      std::cerr << measured.error->to_string() << '\n';
      return 2;
    }
    std::vector<std::string> notes;
    if (auto err = circuit_tools::logged_run(measured, c, *hold, a.duration, a.rate, o, notes)) {
      std::cerr << err->to_string() << '\n';
      return 2;
    }
    for (const auto& n : notes) std::cerr << n << '\n';
    std::string driven;
    for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
      if (o.profile.drives(i)) driven += (driven.empty() ? "" : ", ") + c.file.inputs[i].name;
    }
    profile_note = "inputs " + driven + " from " + a.inputs + " (" + std::to_string(measured.rows()) +
                   " rows from t = " + host::number_text(o.start_time) + " s), " +
                   (*hold == circuit_tools::InputHold::kLinear ? "linear between rows"
                                                               : "each row held until the next (zero-order hold)") +
                   "; " + (a.rate > 0.0 ? "rows at " + host::number_text(a.rate) + " Hz" : "the log's own row times");
  } else {
    if (a.duration > 0.0) o.duration = a.duration;
    if (a.rate > 0.0) o.rate = a.rate;
  }
  o.seed = a.seed;
  o.from_rest = a.start == "rest";
  o.noise = !a.no_noise && !a.ideal;
  if (!a.ideal) {
    o.transducers.lag = a.lag;
    o.transducers.pressure_step = a.pressure_step;
    o.transducers.pressure_adc_bits = a.adc_bits;
  }
  if (!parse_steps(a.steps, circuit_tools::parse_input_step, c.file, o.steps) ||
      !parse_steps(a.faults, circuit_tools::parse_param_fault, c.file, o.steps)) {
    return 1;
  }
  circuit_tools::CircuitLog log;
  try {
    std::mt19937_64 machine_rng(a.machine_seed);
    log = circuit_tools::simulate_circuit(circuit_tools::spread_machine(c, a.param_error, machine_rng), o);
  } catch (const std::exception& e) {
    std::cerr << "hstmon-sim: " << e.what() << '\n';
    return 2;
  }
  if (a.compare && !a.inputs.empty()) {
    (a.out == "-" ? std::cerr : std::cout) << compare_text(c.file, measured, log);
  }
  std::vector<std::string> comments = {
      "hstmon-sim --circuit " + a.circuit + (c.params_path.empty() ? std::string() : " --params " + c.params_path),
      "circuit " + c.file.name + ": full equations (Rosenbrock-4), " +
          (o.from_rest ? "from rest" : "from steady state") + ", " + host::number_text(o.duration) + " s" +
          (a.inputs.empty() || a.rate > 0.0 ? " at " + host::number_text(o.rate) + " Hz" : " on the log's rows") +
          ", seed " + std::to_string(o.seed) + (o.noise ? "" : ", no noise")};
  if (!profile_note.empty()) comments.push_back(profile_note);
  if (const std::string t = transducer_note(o.transducers); !t.empty()) comments.push_back(t);
  if (a.param_error > 0.0) {
    comments.push_back("machine: every uncertain parameter off the file by uniform ±" +
                       host::number_text(a.param_error) + " (machine seed " + std::to_string(a.machine_seed) + ")");
  }
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
