#pragma once
// Loading a circuit file with its parameter file (circuit_tools::load_circuit) in a test:
// a failed load is a test failure and an empty result.
#include <gtest/gtest.h>

#include <string>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon_test {

/// examples/circuits/<file>.
inline std::string example_circuit(const std::string& file) {
  return std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/" + file;
}

/// The circuit at `circuit_path` with `params_path` (empty: the parameter file beside it).
inline hstmon::circuit_tools::LoadedCircuit load_circuit_file(const std::string& circuit_path,
                                                              const std::string& params_path = "") {
  hstmon::circuit_tools::LoadedCircuit c;
  const auto err = hstmon::circuit_tools::load_circuit(circuit_path, params_path, c);
  EXPECT_FALSE(err.has_value()) << (err ? err->to_string() : std::string());
  return c;
}

/// examples/circuits/<name>.json with its parameter file.
inline hstmon::circuit_tools::LoadedCircuit load_example(const std::string& name) {
  return load_circuit_file(example_circuit(name + ".json"));
}

/// The validation set's closed-circuit HST (hst45, tests/data/validation_circuits) with
/// its parameter file.
inline hstmon::circuit_tools::LoadedCircuit load_hst45() {
  return load_circuit_file(std::string(HSTMON_SOURCE_DIR) + "/tests/data/validation_circuits/circuit.json");
}

}  // namespace hstmon_test
