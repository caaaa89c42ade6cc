#pragma once
// Loading a shipped circuit and its parameter file for the circuit tests.
#include <gtest/gtest.h>

#include <string>

#include "hstmon/circuit/engine.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace circuit_test {

using hstmon::host::CircuitFile;
using hstmon::host::CircuitValues;
using Model = hstmon::host::HostCircuitModel;

/// examples/circuits/<file>.
inline std::string example(const std::string& file) {
  return std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/" + file;
}

/// A circuit file and its values (a failed read is a test failure, and empty results).
struct Loaded {
  CircuitFile file;
  CircuitValues values;
  bool ok = false;
};

/// Reads a circuit file and its parameter file, and sets the stiff mask for an observer
/// ticking at `tick` [s].
inline Loaded load_paths(const std::string& circuit_path, const std::string& params_path, double tick) {
  Loaded l;
  const auto f = hstmon::host::read_circuit_file(circuit_path);
  if (!f.ok()) {
    ADD_FAILURE() << f.error->to_string();
    return l;
  }
  l.file = *f.file;
  const auto v = hstmon::host::read_circuit_values(params_path, l.file);
  if (!v.ok()) {
    ADD_FAILURE() << v.error->to_string();
    return l;
  }
  l.values = *v.values;
  l.file.circuit.stiff_mask =
      hstmon::circuit::auto_stiff_mask<double>(l.file.circuit, l.values.params, l.values.inputs, tick);
  l.ok = true;
  return l;
}

/// load_paths for examples/circuits/<name>.json and <name>.params.json.
inline Loaded load(const std::string& name, double tick) {
  return load_paths(example(name + ".json"), example(name + ".params.json"), tick);
}

/// A model of l (bound to l.file.circuit, which must outlive it) at l's values.
inline Model model_of(const Loaded& l) { return Model(l.file.circuit, l.values.params, l.values.inputs); }

}  // namespace circuit_test
