// Circuits that are not physical: each is an error at the value (or the node, or the
// shaft) naming the element, the field and the value with units, whether the value is
// written in the circuit file or in its parameter file.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../support/text_variant.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace {

using hstmon::host::parse_circuit_json;

const char* const kStand = R"({
  "circuit": "stand",
  "envelope": {"pressure": "400 bar", "speed": "3000 rpm"},
  "parameters": {"D": {"quantity": "displacement", "value": "45 cc/rev"}},
  "inputs": {"n": {"quantity": "speed", "unit": "rpm", "value": "1500 rpm"}},
  "nodes": {"tank": {"boundary": 0}, "line": {"beta": 1.4e9, "volume": "2 L"}},
  "shafts": {"drive": {"speed": "n"}},
  "components": {
    "pump": {"type": "pump", "from": "tank", "to": "line", "shaft": "drive", "displacement": "D"},
    "throttle": {"type": "orifice", "from": "line", "to": "tank", "k": 2.9e-7},
    "relief": {"type": "relief_valve", "from": "line", "to": "tank", "k": 3.5e-7, "cracking": "200 bar", "setting": "230 bar"},
    "leak": {"type": "laminar_leakage", "from": "line", "to": "tank", "R": 1.5e12}
  },
  "sensors": {"p": {"node": "line", "unit": "bar"}}
})";

/// kStand with the first `from` replaced by `to`.
std::string variant(const std::string& from, const std::string& to) {
  return hstmon_test::replace_first(kStand, from, to);
}

/// "file:line:column" of the first `token` in text, `skip` bytes on (ASCII: column = byte + 1).
std::string where(const std::string& file, const std::string& text, const std::string& token, std::size_t skip = 0) {
  const std::size_t at = text.find(token) + skip;
  EXPECT_NE(at, std::string::npos) << token;
  const std::size_t start = text.rfind('\n', at);
  const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const std::size_t column = at - (start == std::string::npos ? 0 : start + 1) + 1;
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

/// The error of loading the circuit text with the parameter text ("": the file's own values).
std::string error_of(const std::string& circuit, const std::string& params = "") {
  const auto f = parse_circuit_json(circuit, "c.json");
  if (!f.ok()) return f.error->to_string();
  const auto v = params.empty() ? hstmon::host::circuit_file_values(*f.file)
                                : hstmon::host::parse_circuit_values_json(params, "p.json", *f.file);
  return v.ok() ? std::string("(no error)") : v.error->to_string();
}

void expect_starts(const std::string& got, const std::string& want) {
  EXPECT_EQ(got.substr(0, want.size()), want) << "got: " << got;
}

TEST(CircuitChecks, ThePhysicalCircuitLoads) { EXPECT_EQ(error_of(kStand), "(no error)"); }

TEST(CircuitChecks, ValuesInTheCircuitFile) {
  struct Case {
    std::string from, to, token, message;
    std::size_t skip = 0;  // from the token's start to the value's
  };
  const Case cases[] = {
      {R"("volume": "2 L")", R"("volume": "0 L")", R"("0 L")", "line.volume = 0 m3 (0 L): a volume must be > 0"},
      {R"("beta": 1.4e9)", R"("beta": -1.4e9)", "-1.4e9", "line.beta = -1.4e+09 Pa (-14000 bar): a bulk modulus must be > 0"},
      {R"("value": "45 cc/rev")", R"("value": "-45 cc/rev")", R"("-45 cc/rev")",
       "pump.displacement = -7.16197e-06 m3/rad (-45 cc/rev, parameter 'D'): a displacement must be > 0"},
      {R"("cracking": "200 bar")", R"("cracking": "250 bar")", R"("250 bar")",
       "relief.cracking = 2.5e+07 Pa (250 bar) is not below the full-open pressure 2.3e+07 Pa (230 bar)"},
      {R"("R": 1.5e12)", R"("R": -1.5e12)", "-1.5e12", "leak.R = -1.5e+12 Pa*s/m3: a resistance must be > 0"},
      {R"("k": 2.9e-7)", R"("k": -2.9e-7)", "-2.9e-7", "throttle.k = -2.9e-07 m3/(s*Pa^0.5): a flow coefficient must be >= 0"},
      {R"("drive": {"speed": "n"})", R"("drive": {"J": 0})", R"("J": 0)", "drive.J = 0 kg*m2: an inertia must be > 0", 5},
      {R"("pressure": "400 bar")", R"("pressure": "0 bar")", R"("0 bar")", "envelope.pressure = 0 Pa (0 bar): the envelope must be > 0"},
  };
  for (const Case& c : cases) {
    const std::string text = variant(c.from, c.to);
    expect_starts(error_of(text), where("c.json", text, c.token, c.skip) + ": error: " + c.message);
  }
}

// Names as the file writes them: a directional valve's (not its paths'), a shaft's friction field.
TEST(CircuitChecks, ValuesOfValvesAndShafts) {
  const std::string dcv = variant(R"("throttle": {"type": "orifice", "from": "line", "to": "tank", "k": 2.9e-7})",
                                  R"("dcv": {"type": "directional_valve", "P": "line", "T": "tank", "A": "tank", "B": "line", )"
                                  R"("area": "-2 mm2", "Cd": 0.6, "rho": 870, "spool": 1})");
  expect_starts(error_of(dcv), where("c.json", dcv, R"("-2 mm2")") + ": error: dcv.area = -2e-06 m2: an area must be >= 0");
  const std::string shaft = variant(R"("drive": {"speed": "n"})", R"("drive": {"J": 0.1, "friction": -0.01})");
  expect_starts(error_of(shaft), where("c.json", shaft, "-0.01") + ": error: drive.friction = -0.01 N*m*s/rad: a friction");
  const std::string pump = variant(R"("leak": {"type": "laminar_leakage", "from": "line", "to": "tank", "R": 1.5e12})",
                                   R"("cp": {"type": "compensated_pump", "from": "tank", "to": "line", "Q0": "1 L/min", "R": 1e9, )"
                                   R"("Pc": "75 bar", "Pk": "87 bar", "Pmax": "90 bar"})");
  expect_starts(error_of(pump), where("c.json", pump, R"("1 L/min")") + ": error: cp.Q0 = 1.66667e-05 m3/s (1 L/min) with R");
  const std::string knee = variant(R"("leak": {"type": "laminar_leakage", "from": "line", "to": "tank", "R": 1.5e12})",
                                   R"("cp": {"type": "compensated_pump", "from": "tank", "to": "line", "Q0": "1 L/min", "R": 1e12, )"
                                   R"("Pc": "75 bar", "Pk": "70 bar", "Pmax": "90 bar"})");
  expect_starts(error_of(knee), where("c.json", knee, R"("70 bar")") + ": error: cp.Pk = 7e+06 Pa (70 bar) is not above Pc");
}

TEST(CircuitChecks, Wiring) {
  struct Case {
    std::string from, to, token, message;
  };
  const Case cases[] = {
      {R"("line": {)", R"("spare": {"K": 1e12}, "line": {)", R"("spare")", "node 'spare' is no component's port"},
      {R"("tank": {"boundary": 0}, )", R"("tank": {"boundary": 0}, "drain": {"boundary": 0}, )", R"("drain")",
       "node 'drain' is no component's port"},
      {R"("drive": {"speed": "n"})", R"("drive": {"speed": "n"}, "idle": {"J": 0.1})", R"("idle")",
       "shaft 'idle' is a state that no boundary, driven shaft, flow source or load torque reaches"},
      // Two volumes joined to each other only: an island at rest.
      {R"("line": {)", R"("a": {"K": 1e12}, "b": {"K": 1e12}, "line": {)", R"("a")", "node 'a' is a state that no boundary"},
  };
  for (const Case& c : cases) {
    std::string text = variant(c.from, c.to);
    if (c.token == R"("a")") {
      const std::string leak = R"("leak": {)";
      text.replace(text.find(leak), leak.size(), R"("ab": {"type": "orifice", "from": "a", "to": "b", "k": 1e-7}, "leak": {)");
    }
    expect_starts(error_of(text), where("c.json", text, c.token) + ": error: " + c.message);
  }
}

TEST(CircuitChecks, ValuesInTheParameterFile) {
  // A value the parameter file sets is located there; one it leaves is located in the circuit file.
  const std::string d = R"({"circuit": "stand", "params": {"D": "-45 cc/rev"}})";
  expect_starts(error_of(kStand, d), where("p.json", d, R"("-45)") + ": error: pump.displacement = -7.16197e-06 m3/rad");
  const std::string crack = R"({"circuit": "stand", "params": {"relief.cracking": "300 bar"}})";
  expect_starts(error_of(kStand, crack), where("p.json", crack, R"("300)") + ": error: relief.cracking = 3e+07 Pa (300 bar)");
  const std::string zero = variant(R"("volume": "2 L")", R"("volume": 0)");
  expect_starts(error_of(zero, R"({"circuit": "stand"})"), where("c.json", zero, R"("volume": 0)", 10) + ": error: line.volume = 0 m3");
  const std::string fixed = R"({"circuit": "stand", "params": {"line.volume": "3 L"}})";
  EXPECT_EQ(error_of(zero, fixed), "(no error)");  // the parameter file's value replaces the default
}

}  // namespace
