// hstmon-circuit-header: writes a circuit (file + parameter file) as a C++ header for
// firmware (circuit_header.hpp says what is in it); with --compiled, the compiled model of
// that circuit (straight-line code for its topology, next to the header <NS>.hpp).
//   hstmon-circuit-header CIRCUIT.json [--params P.json] [--tick S] [--name NS] [--compiled] --out FILE
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "hstmon_circuit/circuit_header.hpp"

namespace {

// The file name without its directories: the header must not depend on where it is built.
std::string base_name(const std::string& p) {
  const std::size_t k = p.find_last_of('/');
  return k == std::string::npos ? p : p.substr(k + 1);
}

int usage() {
  std::fputs("usage: hstmon-circuit-header CIRCUIT.json [--params P.json] [--tick S] [--name NS] [--compiled] --out FILE\n"
      "  --compiled  write the compiled model (<NS>_compiled.hpp, includes <NS>.hpp) instead\n", stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string circuit, params, out;
  bool compiled = false;
  hstmon::circuit_tools::CircuitHeaderOptions o;
  o.name = "circuit";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--params" && has_value) {
      params = argv[++i];
    } else if (a == "--tick" && has_value) {
      o.tick = std::strtod(argv[++i], nullptr);
    } else if (a == "--name" && has_value) {
      o.name = argv[++i];
    } else if (a == "--compiled") {
      compiled = true;
    } else if (a == "--out" && has_value) {
      out = argv[++i];
    } else if (!a.empty() && a[0] != '-' && circuit.empty()) {
      circuit = a;
    } else {
      return usage();
    }
  }
  if (circuit.empty() || out.empty() || !(o.tick > 0.0)) return usage();
  hstmon::circuit_tools::LoadedCircuit c;
  if (const auto err = hstmon::circuit_tools::load_circuit(circuit, params, c)) {
    std::fprintf(stderr, "%s\n", err->to_string().c_str());
    return 2;  // a circuit or parameter file in error, as every circuit command
  }
  o.source_note = base_name(circuit) + (c.params_path.empty() ? "" : " + " + base_name(c.params_path));
  std::string error;
  const std::string text = compiled ? hstmon::circuit_tools::circuit_compiled_header(c, o, error)
                                    : hstmon::circuit_tools::circuit_header(c, o, error);
  if (text.empty()) {
    std::fprintf(stderr, "hstmon-circuit-header: %s\n", error.c_str());
    return 1;
  }
  std::ofstream f(out, std::ios::binary);
  f << text;
  if (!f) {
    std::fprintf(stderr, "hstmon-circuit-header: cannot write %s\n", out.c_str());
    return 1;
  }
  return 0;
}
