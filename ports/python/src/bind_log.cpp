// hstmon._core.Log: a circuit log read from a file or from a DataFrame's columns
// (circuit_log.hpp), through the same reader as the CLI.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "binding.hpp"

namespace hstmon::python {

namespace {

py::array_t<double> to_array(const std::vector<double>& v) { return py::array_t<double>(py::ssize_t(v.size()), v.data()); }

py::object error_of(const circuit_tools::CircuitLog& log) {
  if (!log.error) return py::none();
  const host::SourceError& e = *log.error;
  return py::make_tuple(e.file, e.line, e.column, e.message);
}

// Columns of one kind (inputs or sensors) present in the log, by name, SI.
template <typename Items>
py::dict present(const Items& items, const std::vector<std::vector<double>>& cols, std::size_t rows) {
  py::dict d;
  for (std::size_t i = 0; i < items.size() && i < cols.size(); ++i) {
    if (cols[i].size() == rows && rows > 0) d[py::str(items[i].name)] = to_array(cols[i]);
  }
  return d;
}

std::shared_ptr<Log> read_log(const std::shared_ptr<Circuit>& c, const std::string& path,
                              const host::ReadOptions& o) {
  auto log = std::make_shared<Log>();
  log->circuit = c;
  {
    py::gil_scoped_release release;
    log->data = circuit_tools::read_circuit_log(path, c->loaded().file, o);
  }
  raise_if_unusable(log->data, o.lenient);
  return log;
}

std::shared_ptr<Log> from_columns(const std::shared_ptr<Circuit>& c, const std::vector<std::string>& names,
                                  const std::vector<py::object>& columns, std::size_t rows, std::string source,
                                  const host::ReadOptions& o) {
  if (columns.size() != names.size()) throw py::value_error("one column of values per name");
  // Keep the arrays alive (and contiguous float64) while the GIL is released.
  std::vector<py::array_t<double, py::array::c_style | py::array::forcecast>> keep;
  std::vector<const double*> ptrs(names.size(), nullptr);
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (columns[k].is_none()) continue;
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(columns[k]);
    if (!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != rows) {
      throw LocatedError(host::SourceError{source, 1, k + 1, "column '" + names[k] + "' is not " + std::to_string(rows) +
                                                                 " numbers"});
    }
    ptrs[k] = a.data();
    keep.push_back(std::move(a));
  }
  auto log = std::make_shared<Log>();
  log->circuit = c;
  {
    py::gil_scoped_release release;
    log->data = circuit_tools::circuit_log_from_columns(names, ptrs, rows, std::move(source), c->loaded().file, o);
  }
  raise_if_unusable(log->data, o.lenient);
  return log;
}

}  // namespace

void bind_log(py::module_& m) {
  py::class_<Log, std::shared_ptr<Log>>(m, "Log", "A circuit log in memory, SI units (hstmon._core)")
      .def_property_readonly("path", [](const Log& l) { return l.data.path; }, "the source named in messages")
      .def_property_readonly("rows", [](const Log& l) { return l.data.rows(); })
      .def_property_readonly("t", [](const Log& l) { return to_array(l.data.t); }, "time [s]")
      .def_property_readonly("inputs", [](const Log& l) {
        return present(l.circuit->loaded().file.inputs, l.data.inputs, l.data.rows());
      }, "logged inputs by input name [SI]")
      .def_property_readonly("sensors", [](const Log& l) {
        return present(l.circuit->loaded().file.sensors, l.data.sensors, l.data.rows());
      }, "logged sensor channels by channel name [SI]")
      .def_property_readonly("notes", [](const Log& l) { return l.data.notes; }, "the reader's notes, file:line:column")
      .def_property_readonly("error", [](const Log& l) { return error_of(l.data); },
                             "(file, line, column, message) of a lenient read's stop, or None")
      .def("text", [](const Log& l, const std::vector<std::string>& comments) {
        return circuit_tools::circuit_log_text(l.circuit->loaded().file, l.data, comments);
      }, py::arg("comments") = std::vector<std::string>{}, "the log as hstmon-sim writes it (CSV text)");

  m.def("read_options", &read_options, py::arg("separator") = "", py::arg("lenient") = false, py::arg("rate") = 0.0,
        py::arg("encoding") = "", py::arg("maps") = py::none(),
        "Checks the log options (raises ValueError as the CLI refuses them)");
  m.def("read_log", [](const std::shared_ptr<Circuit>& c, const std::string& path, const std::string& separator,
                       bool lenient, double rate, const std::string& encoding, const py::object& maps) {
    return read_log(c, path, read_options(separator, lenient, rate, encoding, maps));
  }, py::arg("circuit"), py::arg("path"), py::arg("separator") = "", py::arg("lenient") = false, py::arg("rate") = 0.0,
        py::arg("encoding") = "", py::arg("maps") = py::none(), "Reads a circuit log file (the CLI's reader)");
  m.def("columns_used", [](const std::shared_ptr<Circuit>& c, const std::vector<std::string>& names,
                           const std::string& source, const std::string& separator, bool lenient, double rate,
                           const std::string& encoding, const py::object& maps) {
    std::optional<host::SourceError> err;
    const std::vector<bool> used = circuit_tools::circuit_log_columns_used(
        names, c->loaded().file, read_options(separator, lenient, rate, encoding, maps), err);
    if (err) {
      err->file = source;
      throw LocatedError(*err);
    }
    return used;
  }, py::arg("circuit"), py::arg("names"), py::arg("source"), py::arg("separator") = "", py::arg("lenient") = false,
        py::arg("rate") = 0.0, py::arg("encoding") = "", py::arg("maps") = py::none(),
        "Which header names the circuit's reader uses (time, inputs, sensors)");
  m.def("log_from_columns", [](const std::shared_ptr<Circuit>& c, const std::vector<std::string>& names,
                               const std::vector<py::object>& columns, std::size_t rows, std::string source,
                               const std::string& separator, bool lenient, double rate, const std::string& encoding,
                               const py::object& maps) {
    return from_columns(c, names, columns, rows, std::move(source), read_options(separator, lenient, rate, encoding, maps));
  }, py::arg("circuit"), py::arg("names"), py::arg("columns"), py::arg("rows"), py::arg("source"),
        py::arg("separator") = "", py::arg("lenient") = false, py::arg("rate") = 0.0, py::arg("encoding") = "",
        py::arg("maps") = py::none(), "A log from columns (None where not used), in the header's units");
}

}  // namespace hstmon::python
