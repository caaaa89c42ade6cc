#include "fdi_circuit.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "hstmon_circuit/circuit_isolability.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_table_header.hpp"
#include "hstmon_circuit/operating_points.hpp"
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

circuit_tools::SignatureParts parts_of(bool steady_only) {
  return steady_only ? circuit_tools::SignatureParts::kSteadyOnly : circuit_tools::SignatureParts::kFull;
}

// The steady-only relation reads no slope or order: the steady table (no causal graph, no
// simulations) gives the same magnitudes and directions at a fraction of the cost.
circuit_tools::FaultTableBuilders builder_of(bool steady_only) {
  return steady_only ? circuit_tools::steady_fault_tables() : signature_fault_tables();
}

std::vector<std::string> split_names(unsigned bits) {
  std::vector<std::string> v;
  if (bits & circuit_tools::kSplitSteady) v.emplace_back("steady");
  if (bits & circuit_tools::kSplitSteadyWeak) v.emplace_back("steady-weak");
  if (bits & circuit_tools::kSplitSlope) v.emplace_back("slope");
  if (bits & circuit_tools::kSplitOrder) v.emplace_back("order");
  return v;
}

// A matrix cell: what splits the pair, the steady signature first.
char cell(int entry, unsigned bits) {
  if (entry == 0) return 'x';
  if (entry == 2) return '~';
  if (bits & circuit_tools::kSplitSteady) return '.';
  const bool slope = (bits & circuit_tools::kSplitSlope) != 0, order = (bits & circuit_tools::kSplitOrder) != 0;
  return slope && order ? 'b' : (slope ? 's' : 'o');
}

}  // namespace

int run_isolability(const std::string& circuit, const std::string& params, bool json, bool steady_only) {
  circuit_tools::LoadedCircuit c;
  if (!load(circuit, params, c)) return 2;
  const circuit_tools::CircuitFaultTable table = builder_of(steady_only).table(c);
  const circuit_tools::Isolability r = circuit_tools::circuit_isolability(table, parts_of(steady_only));
  const circuit_tools::OperatingPointSplit op =
      circuit_tools::split_by_operating_point(c, builder_of(steady_only), parts_of(steady_only), {}, &table);
  const std::size_t n = r.faults.size();
  if (json) {
    nlohmann::json by_point = nlohmann::json::array();
    for (std::size_t k = 0; k < op.pairs.size(); ++k) {
      by_point.push_back({{"pair", {op.pairs[k].first, op.pairs[k].second}}, {"at", op.where[k]}});
    }
    nlohmann::json weak = nlohmann::json::array();
    for (const auto& [a, b] : r.weak) weak.push_back({a, b});
    nlohmann::json split = nlohmann::json::array();
    for (std::size_t i = 0; i < n; ++i) {
      nlohmann::json row = nlohmann::json::array();
      for (std::size_t j = 0; j < n; ++j) row.push_back(split_names(r.split[i][j]));
      split.push_back(row);
    }
    const nlohmann::json j = {{"circuit", c.file.name},
                              {"relation", steady_only ? "steady" : "full"},
                              {"faults", r.faults},
                              {"matrix", r.isolable},
                              {"split", split},
                              {"classes", r.classes},
                              {"weak", weak},
                              {"undetectable", r.undetectable},
                              {"operating_points", op.points},
                              {"split_by_operating_point", by_point},
                              {"classes_across_operating_points", op.classes}};
    std::cout << j.dump() << '\n';
    return 0;
  }
  std::cout << "# Isolability of circuit " << c.file.name
            << (steady_only ? " (steady-state signatures at the nominal inputs)\n\n"
                            : " (the monitor's table: steady signs and directions, slopes and orders)\n\n");
  std::cout << n << " hypotheses; sensors: ";
  std::vector<std::string> sensors;
  for (const auto& s : c.file.sensors) sensors.push_back(s.name);
  std::cout << joined(sensors) << "\n\n## Not detectable\n\n"
            << (r.undetectable.empty() ? "none" : joined(r.undetectable)) << "\n\n## Not isolable (classes)\n\n";
  if (r.classes.empty()) std::cout << "none: every detectable pair can be told apart\n";
  for (const auto& cls : r.classes) std::cout << "- " << joined(cls) << '\n';
  std::cout << "\n## Weakly isolable (only steady directions within 11 degrees split them)\n\n";
  if (r.weak.empty()) std::cout << "none\n";
  for (const auto& [a, b] : r.weak) std::cout << "- " << a << " / " << b << '\n';
  std::cout << "\n## Split by a change of operating point (not isolable at the nominal inputs)\n\n"
            << "points: " << joined(op.points) << "\n\n";
  if (op.pairs.empty()) std::cout << "none\n";
  for (std::size_t k = 0; k < op.pairs.size(); ++k) {
    std::cout << "- " << op.pairs[k].first << " / " << op.pairs[k].second << ": at " << op.where[k] << '\n';
  }
  std::cout << "\n## Not isolable at any of these operating points (classes)\n\n";
  if (op.classes.empty()) std::cout << "none\n";
  for (const auto& cls : op.classes) std::cout << "- " << joined(cls) << '\n';
  if (!steady_only) {
    std::cout << "\n## Split by the transient alone (the steady signature does not, or only weakly)\n\n";
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const unsigned bits = r.split[i][j];
        if ((bits & circuit_tools::kSplitSteady) != 0 || (bits & (circuit_tools::kSplitSlope | circuit_tools::kSplitOrder)) == 0) continue;
        std::cout << "- " << r.faults[i] << " / " << r.faults[j] << ": " << joined(split_names(bits)) << '\n';
        any = true;
      }
    }
    if (!any) std::cout << "none\n";
  }
  std::cout << "\n## Matrix (x not isolable, ~ weakly; isolable by . the steady signature"
            << (steady_only ? "" : ", else s a slope, o the orders, b both") << ")\n\n```\n";
  std::size_t w = 0;
  for (const auto& f : r.faults) w = std::max(w, f.size());
  for (std::size_t i = 0; i < n; ++i) {
    std::cout << r.faults[i] << std::string(w + 1 - r.faults[i].size(), ' ');
    for (std::size_t j = 0; j < n; ++j) std::cout << (i == j ? '\\' : cell(r.isolable[i][j], r.split[i][j]));
    std::cout << '\n';
  }
  std::cout << "```\n";
  return 0;
}

int run_sensor_placement(const std::string& circuit, const std::string& params, bool json, bool steady_only) {
  circuit_tools::LoadedCircuit c;
  if (!load(circuit, params, c)) return 2;
  const auto ranked = circuit_tools::rank_added_sensors(c, builder_of(steady_only), parts_of(steady_only));
  if (json) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& s : ranked) {
      a.push_back({{"sensor", s.name}, {"classes_split", s.classes_split}, {"made_detectable", s.made_detectable},
                   {"weak_cleared", s.weak_cleared}, {"classes_with_it", s.classes}});
    }
    std::cout << nlohmann::json{{"circuit", c.file.name}, {"relation", steady_only ? "steady" : "full"}, {"candidates", a}}.dump()
              << '\n';
    return 0;
  }
  std::cout << "# Sensor placement for circuit " << c.file.name << " (one added sensor, best first"
            << (steady_only ? "; steady-state signatures)\n\n" : "; the monitor's table with it: slopes and orders too)\n\n");
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
  std::string source = std::filesystem::path(c.file.path).filename().string();  // "thesis.json (built in)" too
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
