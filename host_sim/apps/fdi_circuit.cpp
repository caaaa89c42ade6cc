#include "fdi_circuit.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_table_header.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace hstmon::fdi {

namespace {

std::string joined(const std::vector<std::string>& v, const char* sep = ", ") {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

bool load(const std::string& circuit, const std::string& params, circuit_tools::LoadedCircuit& c) {
  if (auto err = circuit_tools::load_circuit(circuit, params, c)) {
    std::cerr << err->to_string() << '\n';
    return false;
  }
  return true;
}

}  // namespace

int run_isolability(const std::string& circuit, const std::string& params, bool json) {
  circuit_tools::LoadedCircuit c;
  if (!load(circuit, params, c)) return 2;
  const circuit_tools::Isolability r = circuit_tools::circuit_isolability(circuit_tools::circuit_fault_table(c));
  if (json) {
    nlohmann::json weak = nlohmann::json::array();
    for (const auto& [a, b] : r.weak) weak.push_back({a, b});
    const nlohmann::json j = {{"circuit", c.file.name}, {"faults", r.faults},   {"matrix", r.isolable},
                              {"classes", r.classes},   {"weak", weak},         {"undetectable", r.undetectable}};
    std::cout << j.dump() << '\n';
    return 0;
  }
  std::cout << "# Isolability of circuit " << c.file.name << " (steady-state signatures at the nominal inputs)\n\n";
  std::cout << r.faults.size() << " hypotheses; sensors: ";
  std::vector<std::string> sensors;
  for (const auto& s : c.file.sensors) sensors.push_back(s.name);
  std::cout << joined(sensors) << "\n\n## Not detectable\n\n"
            << (r.undetectable.empty() ? "none" : joined(r.undetectable)) << "\n\n## Not isolable (classes)\n\n";
  if (r.classes.empty()) std::cout << "none: every detectable pair can be told apart\n";
  for (const auto& cls : r.classes) std::cout << "- " << joined(cls) << '\n';
  std::cout << "\n## Weakly isolable (directions within 11 degrees)\n\n";
  if (r.weak.empty()) std::cout << "none\n";
  for (const auto& [a, b] : r.weak) std::cout << "- " << a << " / " << b << '\n';
  std::cout << "\n## Matrix (. isolable, x not, ~ weakly)\n\n```\n";
  std::size_t w = 0;
  for (const auto& f : r.faults) w = std::max(w, f.size());
  for (std::size_t i = 0; i < r.faults.size(); ++i) {
    std::cout << r.faults[i] << std::string(w + 1 - r.faults[i].size(), ' ');
    for (std::size_t j = 0; j < r.faults.size(); ++j) {
      const int v = r.isolable[i][j];
      std::cout << (i == j ? '\\' : v == 0 ? 'x' : v == 2 ? '~' : '.');
    }
    std::cout << '\n';
  }
  std::cout << "```\n";
  return 0;
}

int run_sensor_placement(const std::string& circuit, const std::string& params, bool json) {
  circuit_tools::LoadedCircuit c;
  if (!load(circuit, params, c)) return 2;
  const auto ranked = circuit_tools::rank_added_sensors(c);
  if (json) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& s : ranked) {
      a.push_back({{"sensor", s.name}, {"classes_split", s.classes_split}, {"made_detectable", s.made_detectable},
                   {"weak_cleared", s.weak_cleared}, {"classes_with_it", s.classes}});
    }
    std::cout << nlohmann::json{{"circuit", c.file.name}, {"candidates", a}}.dump() << '\n';
    return 0;
  }
  std::cout << "# Sensor placement for circuit " << c.file.name << " (one added sensor, best first)\n\n";
  std::cout << "| sensor | classes split | made detectable | weak pairs cleared | classes left |\n|---|---|---|---|---|\n";
  for (const auto& s : ranked) {
    std::vector<std::string> left;
    for (const auto& cls : s.classes) left.push_back("{" + joined(cls) + "}");
    std::cout << "| " << s.name << " | " << s.classes_split << " | " << s.made_detectable << " | " << s.weak_cleared
              << " | " << (left.empty() ? "none" : joined(left, " ")) << " |\n";
  }
  return 0;
}

int run_table_header(const std::string& circuit, const std::string& params, const std::string& name,
                     const std::string& out) {
  bool ident = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0]));
  for (char ch : name) ident = ident && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
  if (!ident) {
    std::cerr << "hstmon-fdi table: error: --name must be a C++ identifier, got '" << name << "'\n";
    return 1;
  }
  circuit_tools::LoadedCircuit c;
  if (!load(circuit, params, c)) return 2;
  std::string source = std::filesystem::path(circuit).filename().string();
  if (!c.params_path.empty()) source += " with " + std::filesystem::path(c.params_path).filename().string();
  const circuit_tools::CircuitFaultTable table = circuit_signature_table(c);
  for (const std::string& n : table.notes) std::cerr << "hstmon-fdi table: note: " << n << '\n';
  const std::string text = circuit_tools::circuit_table_header(c, table, name, source);
  if (out == "-") {
    std::cout << text;
    return 0;
  }
  std::ofstream f(out, std::ios::binary);
  if (!(f << text)) {
    std::cerr << "hstmon-fdi table: error: cannot write " << out << '\n';
    return 1;
  }
  return 0;
}

}  // namespace hstmon::fdi
