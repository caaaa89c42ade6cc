// libFuzzer target: the circuit-file and parameter-file readers, then the engine built
// on what they accept. The input is a circuit file, optionally followed by the separator
// line "@@params@@" and a parameter file (without one, the circuit's own values).
// Invariants: never crash; an error has a position with line and column ≥ 1 (or none)
// and no result; a circuit and values both accepted make an engine that is valid()
// (the load-time checks refuse every value the engine would refuse), and evaluating it
// at rest, with the replay's stiff mask, stays within the sanitizers' rules.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hstmon/circuit/stiffness.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace {

using hstmon::host::SourceError;

[[noreturn]] void fail(const char* what, const SourceError* e = nullptr) {
  std::fprintf(stderr, "fuzz_circuit invariant violated: %s\n", what);
  if (e != nullptr) std::fprintf(stderr, "  error: %s\n", e->to_string().c_str());
  std::abort();
}

void check_position(const SourceError& e) {
  const bool none = e.line == 0 && e.column == 0;
  if (!none && (e.line < 1 || e.column < 1)) fail("error position has line or column 0", &e);
}

/// The engine on accepted values, as the replay builds it (stiff mask at a 1 ms tick).
void run_engine(const hstmon::host::CircuitFile& f, const hstmon::host::CircuitValues& v) {
  using Model = hstmon::host::HostCircuitModel;
  hstmon::host::HostCircuit desc = f.circuit;
  const Model full(desc, v.params, v.inputs);
  if (full.error() != hstmon::circuit::CircuitError::kOk || !full.valid()) fail("accepted values the engine refuses");
  desc.stiff_mask = hstmon::circuit::auto_stiff_mask<double>(desc, v.params, v.inputs, 1e-3);
  const Model model(desc, v.params, v.inputs);
  if (!model.valid()) fail("the stiff mask made the engine invalid");
  Model::Output y;
  (void)model.derivative(model.rest_state(), &y);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hstmon::host;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const std::string_view sep = "\n@@params@@\n";
  const std::size_t at = all.find(sep);
  const std::string_view circuit = all.substr(0, at);
  const CircuitFileResult f = parse_circuit_json(circuit, "fuzz.json");
  if (!f.ok()) {
    check_position(*f.error);
    if (f.file) fail("error but a circuit", &*f.error);
    return 0;
  }
  if (!f.file) fail("ok but no circuit");
  const CircuitValuesResult v = at == std::string_view::npos
                                    ? circuit_file_values(*f.file)
                                    : parse_circuit_values_json(all.substr(at + sep.size()), "fuzz.params.json", *f.file);
  if (!v.ok()) {
    check_position(*v.error);
    if (v.values) fail("error but values", &*v.error);
    return 0;
  }
  if (!v.values) fail("ok but no values");
  run_engine(*f.file, *v.values);
  return 0;
}
