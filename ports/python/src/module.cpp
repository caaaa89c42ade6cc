// hstmon._core: the extension behind the Python package `hstmon` (docs/python.md).
#include <pybind11/pybind11.h>

#include "binding.hpp"

namespace {

// A located error becomes hstmon.SourceError(file, line, column, message), defined in
// Python (hstmon/_errors.py) so that it pickles and reads like any Python exception.
void translate(std::exception_ptr p) {
  namespace py = pybind11;
  try {
    if (p) std::rethrow_exception(p);
  } catch (const hstmon::python::LocatedError& e) {
    const py::object cls = py::module_::import("hstmon._errors").attr("SourceError");
    const py::object err = cls(e.error.file, e.error.line, e.error.column, e.error.message);
    PyErr_SetObject(cls.ptr(), err.ptr());
  }
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "hstmon's C++ core: circuits, logs, replay, simulation, identify and gap (use the package hstmon)";
  pybind11::register_exception_translator(translate);
  hstmon::python::bind_circuit(m);
  hstmon::python::bind_log(m);
  hstmon::python::bind_replay(m);
  hstmon::python::bind_simulate(m);
  hstmon::python::bind_identify_gap(m);
}
