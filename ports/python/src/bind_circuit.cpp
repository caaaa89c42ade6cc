// hstmon._core.Circuit: a circuit file with its values (circuit_load.hpp), and the log
// options every reader takes.
#include <pybind11/stl.h>

#include "binding.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"
#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/log_options.hpp"

namespace hstmon::python {

Circuit::Circuit(std::string path, std::string params) : path_(std::move(path)), params_(std::move(params)) {
  auto c = std::make_shared<circuit_tools::LoadedCircuit>();
  std::optional<host::SourceError> err;
  {
    py::gil_scoped_release release;
    err = circuit_tools::load_circuit(path_, params_, *c);
  }
  if (err) throw LocatedError(*err);
  c_ = std::move(c);
}

const circuit_tools::CircuitFaultTable* Circuit::fault_table() const {
  // As `hstmon replay --circuit FOLDER`: built once; a circuit it cannot be built for is
  // replayed with the replay's own attempt, which notes why (residuals only).
  std::call_once(table_once_, [this] {
    try {
      table_ = std::make_shared<const circuit_tools::CircuitFaultTable>(fdi::circuit_signature_table(*c_));
    } catch (const std::exception&) {
      table_.reset();
    }
  });
  return table_.get();
}

host::ReadOptions read_options(const std::string& separator, bool lenient, double rate, const std::string& encoding,
                               const py::object& maps) {
  host::ReadOptions ro;
  ro.lenient = lenient;
  std::string err;
  if (!separator.empty()) err = host::set_separator(ro, separator);
  if (!err.empty()) throw py::value_error("separator " + err);
  if (rate != 0.0) err = host::set_rate(ro, rate);
  if (!err.empty()) throw py::value_error("rate " + err);
  if (!encoding.empty()) err = host::set_encoding(ro, encoding);
  if (!err.empty()) throw py::value_error("encoding " + err);
  if (!maps.is_none()) {
    std::vector<std::string> entries;
    if (py::isinstance<py::dict>(maps)) {
      for (const auto& kv : maps.cast<py::dict>()) {
        entries.push_back(py::str(kv.first).cast<std::string>() + "=" + py::str(kv.second).cast<std::string>());
      }
    } else if (py::isinstance<py::str>(maps)) {
      entries.push_back(maps.cast<std::string>());
    } else {
      entries = maps.cast<std::vector<std::string>>();
    }
    for (const std::string& e : entries) {
      err = host::add_column_map(ro, e);
      if (!err.empty()) throw py::value_error("map " + err);
    }
  }
  return ro;
}

void raise_if_unusable(const circuit_tools::CircuitLog& log, bool lenient) {
  if (log.error && (!lenient || log.rows() == 0)) throw LocatedError(*log.error);
}

namespace {

// What an input and a sensor column have alike: name, log column, display and SI unit, quantity.
template <class Column>
py::dict column_of(const Column& c) {
  py::dict d;
  d["name"] = c.name;
  d["column"] = c.column;
  d["unit"] = c.unit.empty() ? std::string(host::circuit_si_unit(c.quantity)) : c.unit;
  d["si_unit"] = host::circuit_si_unit(c.quantity);
  d["quantity"] = host::circuit_quantity_name(c.quantity);
  return d;
}

py::list inputs_of(const host::CircuitFile& f) {
  py::list out;
  for (const host::CircuitInput& i : f.inputs) {
    py::dict d = column_of(i);
    d["value"] = i.value ? py::object(py::float_(*i.value)) : py::object(py::none());
    out.append(d);
  }
  return out;
}

py::list sensors_of(const host::CircuitFile& f) {
  py::list out;
  for (const host::CircuitSensor& s : f.sensors) {
    py::dict d = column_of(s);
    d["noise"] = s.noise;
    d["lo"] = s.lo;
    d["hi"] = s.hi;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_circuit(py::module_& m) {
  py::class_<Circuit, std::shared_ptr<Circuit>>(m, "Circuit", "A circuit file with its values (hstmon._core)")
      .def(py::init<std::string, std::string>(), py::arg("path"), py::arg("params") = "",
           "Loads a circuit file and its parameter file ('' = <stem>.params.json beside it, else the file's values)")
      .def_property_readonly("path", &Circuit::path, "the circuit file as given")
      .def_property_readonly("params_given", &Circuit::params_given, "the parameter file as given ('' = default)")
      .def_property_readonly("params_path", [](const Circuit& c) { return c.loaded().params_path; },
                             "the parameter file used ('' = the circuit file's own values)")
      .def_property_readonly("name", [](const Circuit& c) { return c.loaded().file.name; })
      .def_property_readonly("description", [](const Circuit& c) { return c.loaded().file.description; })
      .def_property_readonly("inputs", [](const Circuit& c) { return inputs_of(c.loaded().file); },
                             "inputs: name, log column, unit, quantity, nominal value [SI]")
      .def_property_readonly("sensors", [](const Circuit& c) { return sensors_of(c.loaded().file); },
                             "sensors: name, log column, unit, quantity, noise, range lo/hi [SI]")
      .def_property_readonly("parameters", [](const Circuit& c) {
        std::vector<std::string> names;
        for (const auto& p : c.loaded().file.params) names.push_back(p.name);
        return names;
      }, "the circuit's parameter names")
      .def("fault_table_rows", [](const Circuit& c) {
        const circuit_tools::CircuitFaultTable* t = nullptr;
        {
          py::gil_scoped_release release;
          t = c.fault_table();
        }
        return t == nullptr ? std::vector<std::string>{} : t->names;
      }, "the fault hypotheses of the matcher's table (built on first use)");
}

}  // namespace hstmon::python
