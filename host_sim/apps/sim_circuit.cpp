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
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_sensors/sensor_presets.hpp"  // kPaPerBar
#include "sim_compare.hpp"
#include "sim_scenario.hpp"

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

// The log's units: pressure and speed columns in the units asked for (--units, --rpm).
void override_units(const CircuitSimArgs& a, host::CircuitFile& f) {
  const auto unit_for = [&a](host::CircuitQuantity q, std::string& unit) {
    if (q == host::CircuitQuantity::kPressure && !a.pressure_unit.empty()) unit = a.pressure_unit;
    if (q == host::CircuitQuantity::kSpeed && a.rpm) unit = "rpm";
  };
  for (auto& in : f.inputs) unit_for(in.quantity, in.unit);
  for (auto& s : f.sensors) unit_for(s.quantity, s.unit);
}

// A value with its SI unit.
std::string si_value(double v, host::CircuitQuantity q) {
  return host::number_text(v) + " " + host::circuit_si_unit(q);
}

// --list: the names --step, --fault and the log's columns take, with their units and values.
void print_circuit_list(const circuit_tools::LoadedCircuit& c) {
  const host::CircuitFile& f = c.file;
  std::cout << "circuit " << f.name << " (" << f.path
            << ")\n\ninputs (--step INPUT=VALUE@T, --fault INPUT=FACTOR@T; log columns):\n";
  for (std::size_t i = 0; i < f.inputs.size(); ++i) {
    const auto& in = f.inputs[i];
    std::cout << "  " << in.name << "  " << host::circuit_quantity_name(in.quantity) << ", column " << in.column
              << (in.unit.empty() ? "" : " [" + in.unit + "]") << ", nominal "
              << si_value(c.values.inputs.v[static_cast<int>(i)], in.quantity) << '\n';
  }
  std::cout << "\nparameters (--fault PARAM=FACTOR@T):\n";
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    if (f.params[i].literal) continue;
    std::cout << "  " << f.params[i].name << "  "
              << si_value(c.values.params.v[static_cast<int>(i)], f.params[i].quantity)
              << (f.params[i].description.empty() ? "" : "  (" + f.params[i].description + ")") << '\n';
  }
  std::cout << "\nsensors (log columns):\n";
  for (const auto& s : f.sensors) {
    std::cout << "  " << s.name << "  " << host::circuit_quantity_name(s.quantity) << ", column " << s.column
              << (s.unit.empty() ? "" : " [" + s.unit + "]") << ", noise σ " << si_value(s.noise, s.quantity) << '\n';
  }
}

}  // namespace

int run_circuit_sim(const CircuitSimArgs& a) {
  circuit_tools::LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    std::cerr << err->to_string() << '\n';
    return 2;
  }
  if (a.list) {
    print_circuit_list(c);
    return 0;
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
  }
  ScenarioRun scenario;
  if (a.scenario) {
    if (auto err = scenario_run(*a.scenario, c.file, scenario)) {
      std::cerr << "hstmon-sim: " << *err << '\n';
      return 1;
    }
    o.steps = scenario.steps;
    o.duration = scenario.duration;
  }
  if (a.logger && !a.ideal) {
    if (auto err = preset_channels(a.preset, *a.logger, c.file, o.channels)) {
      std::cerr << "hstmon-sim: " << *err << '\n';
      return 1;
    }
  }
  if (a.inputs.empty()) {
    if (a.duration > 0.0) o.duration = a.duration;
    if (a.rate > 0.0) {
      o.rate = a.rate;
    } else if (a.logger) {
      o.rate = 1.0 / a.logger->sample_period;
    }
  }
  o.seed = a.seed;
  o.from_rest = a.start.empty() ? a.scenario && scenario.from_rest : a.start == "rest";
  o.noise = !a.no_noise && !a.ideal;
  if (!a.ideal && !a.logger) {
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
      "hstmon-sim --circuit " + c.file.path + (c.params_path.empty() ? std::string() : " --params " + c.params_path),
      "circuit " + c.file.name + ": full equations (Rosenbrock-4), " +
          (o.from_rest ? "from rest" : "from steady state") + ", " + host::number_text(o.duration) + " s" +
          (a.inputs.empty() || a.rate > 0.0 ? " at " + host::number_text(o.rate) + " Hz" : " on the log's rows") +
          ", seed " + std::to_string(o.seed) + (o.noise ? "" : ", no noise")};
  if (a.scenario) comments.push_back("scenario " + a.scenario->name + ": " + a.scenario->description);
  if (!profile_note.empty()) comments.push_back(profile_note);
  if (!o.channels.empty()) comments.push_back("sensors: preset " + a.preset);
  if (const std::string t = transducer_note(o.transducers); !t.empty()) comments.push_back(t);
  if (a.param_error > 0.0) {
    comments.push_back("machine: every uncertain parameter off the file by uniform ±" +
                       host::number_text(a.param_error) + " (machine seed " + std::to_string(a.machine_seed) + ")");
  }
  for (const std::string& s : a.steps) comments.push_back("step " + s);
  for (const std::string& s : a.faults) comments.push_back("fault " + s);
  host::CircuitFile written = c.file;
  override_units(a, written);
  const std::string text = circuit_tools::circuit_log_text(written, log, comments);
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
