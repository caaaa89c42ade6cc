// hstmon._core.simulate: a synthetic log of a circuit (circuit_sim.hpp), with the options
// of `hstmon-sim --circuit` (--inputs, --duration, --rate, --seed, --start, --no-noise,
// --step, --fault, --inputs-hold as hold).
#include <pybind11/stl.h>

#include "binding.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_circuit/logged_run.hpp"

namespace hstmon::python {

namespace {

std::shared_ptr<Log> simulate(const std::shared_ptr<Circuit>& c, const std::shared_ptr<Log>& inputs, double duration,
                              double rate, std::uint64_t seed, const std::string& start, bool noise,
                              const std::vector<std::string>& steps, const std::vector<std::string>& faults,
                              const std::string& hold) {
  circuit_tools::CircuitSimOptions o;
  const std::optional<circuit_tools::InputHold> how = circuit_tools::input_hold_from(hold);
  if (!how) throw py::value_error("hold must be 'linear' or 'step'");
  if (inputs) {
    // A logged run's inputs, on its own clock and rows (as hstmon-sim --inputs; logged_run.hpp).
    std::vector<std::string> notes;
    if (auto err = circuit_tools::logged_run(inputs->data, c->loaded(), *how, duration, rate, o, notes)) {
      throw py::value_error(err->to_string());
    }
  } else {
    if (duration > 0.0) o.duration = duration;
    if (rate > 0.0) o.rate = rate;
  }
  if (!(o.duration > 0.0) || !(o.rate > 0.0)) throw py::value_error("duration [s] and rate [Hz] must be > 0");
  if (start != "steady" && start != "rest") throw py::value_error("start must be 'steady' or 'rest'");
  o.seed = seed;
  o.from_rest = start == "rest";
  o.noise = noise;
  for (const std::string& s : steps) {
    circuit_tools::InputStep st;
    if (auto err = circuit_tools::parse_input_step(s, c->loaded().file, st)) throw py::value_error("step " + *err);
    o.steps.push_back(st);
  }
  for (const std::string& s : faults) {
    circuit_tools::InputStep st;
    if (auto err = circuit_tools::parse_param_fault(s, c->loaded().file, st)) throw py::value_error("fault " + *err);
    o.steps.push_back(st);
  }
  auto log = std::make_shared<Log>();
  log->circuit = c;
  {
    py::gil_scoped_release release;
    log->data = circuit_tools::simulate_circuit(c->loaded(), o);  // std::runtime_error → RuntimeError
  }
  log->data.path = "hstmon.simulate(" + c->loaded().file.name + ")";
  return log;
}

}  // namespace

void bind_simulate(py::module_& m) {
  m.def("simulate", &simulate, py::arg("circuit"), py::arg("inputs") = nullptr, py::arg("duration") = 0.0,
        py::arg("rate") = 0.0, py::arg("seed") = 1, py::arg("start") = "steady", py::arg("noise") = true,
        py::arg("steps") = std::vector<std::string>{}, py::arg("faults") = std::vector<std::string>{},
        py::arg("hold") = "linear",
        "Simulates the circuit (full equations, Rosenbrock-4, sensor noise and ranges); a Log in SI units");
}

}  // namespace hstmon::python
