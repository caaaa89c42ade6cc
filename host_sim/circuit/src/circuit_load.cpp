#include "hstmon_circuit/circuit_load.hpp"

#include <fstream>

#include "hstmon_circuit/builtin_rig.hpp"

namespace hstmon::circuit_tools {

namespace {

// "<dir>/<stem>.params.json" for "<dir>/<stem>.json" (or "<path>.params.json").
std::string sibling_params(const std::string& circuit_path) {
  const std::string ext = ".json";
  std::string stem = circuit_path;
  if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0) {
    stem.resize(stem.size() - ext.size());
  }
  return stem + ".params.json";
}

bool readable(const std::string& path) {
  std::ifstream f(path);
  return static_cast<bool>(f);
}

}  // namespace

std::optional<host::SourceError> load_circuit(const std::string& circuit_path, const std::string& params_path,
                                              LoadedCircuit& out) {
  const bool builtin = circuit_path.empty();
  host::CircuitFileResult f = builtin
                                  ? host::parse_circuit_json(builtin_thesis_circuit(), std::string(kBuiltinCircuitName))
                                  : host::read_circuit_file(circuit_path);
  if (!f.ok()) return f.error;
  out.file = std::move(*f.file);
  out.file.circuit.stiff_mask = 0;
  std::string pp = params_path;
  if (pp.empty() && !builtin) {
    const std::string sib = sibling_params(circuit_path);
    if (readable(sib)) pp = sib;
  }
  host::CircuitValuesResult v =
      pp.empty() ? host::circuit_file_values(out.file) : host::read_circuit_values(pp, out.file);
  if (!v.ok()) return v.error;
  out.values = std::move(*v.values);
  out.params_path = pp;
  host::apply_sensor_ranges(out.values, out.file);
  return std::nullopt;
}

}  // namespace hstmon::circuit_tools
