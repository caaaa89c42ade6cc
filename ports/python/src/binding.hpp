#pragma once
// What the binding's files share: the circuit and log handles Python holds, the read
// options from keyword arguments, and the one way an error reaches Python (a located
// hstmon.SourceError, or ValueError/RuntimeError).
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::python {

namespace py = pybind11;

/// Thrown by the binding for a located error; raised in Python as hstmon.SourceError
/// (file, line, column, message attributes; str() is the CLI's "file:line:column: error: …").
struct LocatedError : std::runtime_error {
  explicit LocatedError(host::SourceError e) : std::runtime_error(e.to_string()), error(std::move(e)) {}
  host::SourceError error;
};

/// A loaded circuit, shared by every result made from it; its fault table (the one
/// `hstmon replay --circuit` runs on) is built once, on first use.
class Circuit {
 public:
  Circuit(std::string path, std::string params);  ///< load_circuit; throws LocatedError

  const circuit_tools::LoadedCircuit& loaded() const { return *c_; }
  const std::string& path() const { return path_; }
  const std::string& params_given() const { return params_; }
  /// The matcher's table (fdi::circuit_signature_table), or nullptr when it cannot be built
  /// for this circuit (the replay then says so and runs residuals only, as the CLI's fleet).
  const circuit_tools::CircuitFaultTable* fault_table() const;

 private:
  std::string path_, params_;
  std::shared_ptr<const circuit_tools::LoadedCircuit> c_;
  mutable std::once_flag table_once_;
  mutable std::shared_ptr<const circuit_tools::CircuitFaultTable> table_;
};

/// A log read for a circuit (from a file, from columns, or simulated).
struct Log {
  std::shared_ptr<Circuit> circuit;
  circuit_tools::CircuitLog data;
};

/// The log options as keyword arguments, as the CLI's --separator, --lenient, --rate,
/// --encoding and --map (a list of "COLUMN=SIGNAL" or a dict); throws ValueError.
host::ReadOptions read_options(const std::string& separator, bool lenient, double rate, const std::string& encoding,
                               const py::object& maps);

/// Throws LocatedError when the log failed and is not a lenient read with rows left.
void raise_if_unusable(const circuit_tools::CircuitLog& log, bool lenient);

/// Adds fields of x to d: keys and members alternate ("t", &Row::t, "mean", &Stats::mean, …);
/// a member function is called (it takes no argument). The results' dicts are made so.
template <class T>
void put_fields(py::dict&, const T&) {}
template <class T, class Member, class... Rest>
void put_fields(py::dict& d, const T& x, const char* key, Member member, Rest... rest) {
  d[key] = std::invoke(member, x);
  put_fields(d, x, rest...);
}

/// A dict of fields of x (put_fields).
template <class T, class... KeysAndMembers>
py::dict dict_of(const T& x, KeysAndMembers... fields) {
  py::dict d;
  put_fields(d, x, fields...);
  return d;
}

void bind_circuit(py::module_& m);
void bind_log(py::module_& m);
void bind_replay(py::module_& m);
void bind_simulate(py::module_& m);
void bind_identify_gap(py::module_& m);

}  // namespace hstmon::python
