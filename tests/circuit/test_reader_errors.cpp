// Circuit and parameter files with mistakes: each is reported as file:line:column with a
// message saying what is wrong, and nothing crashes (including on binary junk).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "../support/text_variant.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace {

using hstmon::host::parse_circuit_json;

const char* const kGood = R"({
  "circuit": "tiny",
  "envelope": {"pressure": "100 bar", "speed": "1000 rpm"},
  "parameters": {"k": {"quantity": "orifice"}},
  "inputs": {"q": {"quantity": "flow", "unit": "L/min"}},
  "nodes": {"tank": {"boundary": 0}, "n": {"K": 1e12}},
  "components": {
    "src": {"type": "flow_source", "from": "tank", "to": "n", "flow": "q"},
    "ori": {"type": "orifice", "from": "n", "to": "tank", "k": "k"}
  },
  "sensors": {"p": {"node": "n", "unit": "bar"}}
})";

/// Replaces the first `from` in kGood by `to`.
std::string variant(const std::string& from, const std::string& to) {
  return hstmon_test::replace_first(kGood, from, to);
}

/// The error of reading text, as "file:line:column: error: ...".
std::string error_of(const std::string& text) {
  const auto r = parse_circuit_json(text, "c.json");
  return r.ok() ? std::string("(no error)") : r.error->to_string();
}

TEST(CircuitReader, GoodFileReads) {
  const auto r = parse_circuit_json(kGood, "c.json");
  ASSERT_TRUE(r.ok()) << r.error->to_string();
  EXPECT_EQ(r.file->nodes.size(), 2u);
  EXPECT_EQ(r.file->elements.size(), 2u);
  EXPECT_EQ(r.file->circuit.n_channels, 1);
}

TEST(CircuitReader, ErrorsCarryLineAndColumn) {
  struct Case {
    std::string text;
    std::string expect;  // the start of the message, position included
  };
  const Case cases[] = {
      {variant(R"("to": "n", "flow")", R"("to": "nn", "flow")"), "c.json:8:58: error: src.to: no node 'nn'"},
      {variant(R"("k": "k"}
  },)", R"("k": "kk"}
  },)"), "c.json:9:64: error: ori.k: 'kk' is neither a declared parameter nor an input"},
      {variant(R"("type": "orifice")", R"("type": "orifise")"), "c.json:9:21: error: ori: unknown type 'orifise'"},
      {variant(R"({"K": 1e12})", R"({"K": "1e12 bar"})"), "c.json:6:49: error: n.K: unknown stiffness unit 'bar'"},
      {variant(R"("unit": "L/min")", R"("unit": "gallons")"), "c.json:5:48: error: q: unknown flow unit 'gallons'"},
      {variant(R"("k": {"quantity": "orifice"})", R"("k": {"quantity": "pressure"})"),
       "c.json:9:64: error: ori.k is a quantity 'orifice', but parameter 'k' is declared as 'pressure'"},
      {variant(R"("p": {"node": "n")", R"("p": {"node": "n", "shaft": "x")"),
       "c.json:11:20: error: sensor 'p' measures exactly one of"},
      {variant(R"("tank": {"boundary": 0}, )", R"("tank": {"boundary": 0}, "tank": {"boundary": 0}, )"),
       "c.json:6:38: error: duplicate key 'tank'"},
      {variant(R"("envelope")", R"("envelop")"), "c.json:3:3: error: unknown key 'envelop'"},
      {variant(R"("ori": {)", R"("ori": {"colour": 1, )"), "c.json:9:13: error: unknown key 'colour'"},
      {variant(R"("n": {"K": 1e12})", R"("n": {})"), "c.json:6:38: error: node 'n' has neither a capacitance"},
      {variant(R"("from": "n", "to": "tank")", R"("from": "n", "to": "n")"), "c.json:9:51: error: ori: 'from' and 'to' are the same node"},
      {std::string(kGood).substr(0, 120), "c.json:4:38: error: JSON:"},
      {"\x01\x02\xff junk", "c.json:1:1: error: JSON:"},
      {"[1, 2]", "c.json:1:1: error: the top level must be an object"},
  };
  // Each position is that of the offending token (the value, the key, the end of the text).
  for (const Case& c : cases) {
    const std::string e = error_of(c.text);
    EXPECT_EQ(e.substr(0, c.expect.size()), c.expect) << "got: " << e;
  }
}

TEST(CircuitReader, ParameterFileErrors) {
  const auto r = parse_circuit_json(kGood, "c.json");
  ASSERT_TRUE(r.ok());
  const auto& cf = *r.file;
  using hstmon::host::parse_circuit_values_json;
  const auto ok = parse_circuit_values_json(R"({"circuit": "tiny", "params": {"k": 1e-7}, "inputs": {"q": "10 L/min"}})", "p.json", cf);
  ASSERT_TRUE(ok.ok()) << ok.error->to_string();
  EXPECT_NEAR(ok.values->inputs.v[0], 10e-3 / 60, 1e-15);
  struct Case {
    const char* text;
    const char* expect;
  };
  const Case cases[] = {
      {R"({"circuit": "tiny", "params": {"kk": 1e-7}})", "p.json:1:32: error: no parameter 'kk' in circuit 'tiny'"},
      {R"({"circuit": "big", "params": {}})", "p.json:1:13: error: 'circuit' must be \"tiny\""},
      {R"({"circuit": "tiny",
 "params": {"k": "1e-7 bar"}})", "p.json:2:18: error: k: unknown"},
      {R"({"circuit": "tiny", "params": {"k": 1e-7}})", "p.json:1:1: error: input 'q' has no nominal value"},
      {R"({"circuit": "tiny", "params": {"k": 1e-7}, "inputs": {"q": [1]}})", "p.json:1:60: error: q must be a number"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": {"kk": 0.1}})", "p.json:1:57: error: no parameter 'kk' in circuit 'tiny'"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": {"k": "5 bar"}})", "p.json:1:62: error: k: unknown fraction unit 'bar'"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": {"k": 0.8}})", "p.json:1:62: error: k: a relative uncertainty must be from 0 to 50 %"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": {"k": "-1 %"}})", "p.json:1:62: error: k: a relative uncertainty must be from 0 to 50 %"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": {"k": [0.1]}})", "p.json:1:62: error: k must be a fraction (0.05) or a percentage"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "uncertainty": 0.1})", "p.json:1:56: error: 'uncertainty' must be an object"},
  };
  for (const Case& c : cases) {
    const auto v = parse_circuit_values_json(c.text, "p.json", cf);
    ASSERT_FALSE(v.ok()) << c.text;
    const std::string e = v.error->to_string();
    EXPECT_EQ(e.substr(0, std::string(c.expect).size()), c.expect) << "got: " << e;
  }
}

// The optional "uncertainty" section: a fraction or a percentage per parameter, the rest
// left to the monitor's default.
TEST(CircuitReader, ParameterFileStatesUncertainty) {
  const auto r = parse_circuit_json(kGood, "c.json");
  ASSERT_TRUE(r.ok());
  using hstmon::host::parse_circuit_values_json;
  const auto none = parse_circuit_values_json(R"({"circuit": "tiny", "params": {"k": 1e-7}, "inputs": {"q": 1}})", "p.json", *r.file);
  ASSERT_TRUE(none.ok()) << none.error->to_string();
  ASSERT_EQ(none.values->uncertainty.size(), r.file->params.size());
  for (const auto& e : none.values->uncertainty) EXPECT_FALSE(e.has_value());
  const auto k = static_cast<std::size_t>(r.file->param_index("k"));
  for (const auto& [text, want] : {std::pair<const char*, double>{R"("5 %")", 0.05}, {R"(" 12.5% ")", 0.125}, {"0.3", 0.3}, {"0", 0.0}}) {
    const std::string file = std::string(R"({"circuit": "tiny", "params": {"k": 1e-7}, "inputs": {"q": 1}, "uncertainty": {"k": )") + text + "}}";
    const auto v = parse_circuit_values_json(file, "p.json", *r.file);
    ASSERT_TRUE(v.ok()) << v.error->to_string();
    ASSERT_TRUE(v.values->uncertainty[k].has_value()) << text;
    EXPECT_DOUBLE_EQ(*v.values->uncertainty[k], want) << text;
  }
}

// The optional "sensors" section: a transmitter range per sensor in the sensor's quantity
// (null for no end), which load_circuit writes over the circuit file's; and the circuit's
// name under "model", as the thesis rig's Table 2.2 files write it.
TEST(CircuitReader, ParameterFileSetsSensorRangesAndTakesModelForCircuit) {
  const auto r = parse_circuit_json(kGood, "c.json");
  ASSERT_TRUE(r.ok());
  using hstmon::host::parse_circuit_values_json;
  const auto v = parse_circuit_values_json(
      R"({"model": "tiny", "params": {"k": 1e-7}, "inputs": {"q": 1}, "sensors": {"p": [null, "250 bar"]}})", "p.json",
      *r.file);
  ASSERT_TRUE(v.ok()) << v.error->to_string();
  ASSERT_EQ(v.values->ranges.size(), 1u);
  ASSERT_TRUE(v.values->ranges[0].has_value());
  EXPECT_EQ(v.values->ranges[0]->lo, -HUGE_VAL);
  EXPECT_DOUBLE_EQ(v.values->ranges[0]->hi, 250e5);
  hstmon::host::CircuitFile cf = *r.file;
  hstmon::host::apply_sensor_ranges(*v.values, cf);
  EXPECT_DOUBLE_EQ(cf.sensors[0].hi, 250e5);
  struct Case {
    const char* text;
    const char* expect;
  };
  const Case cases[] = {
      {R"({"circuit": "tiny", "model": "tiny", "inputs": {"q": 1}})",
       "p.json:1:21: error: give the circuit's name once"},
      {R"({"model": "big", "inputs": {"q": 1}})", "p.json:1:11: error: 'model' must be \"tiny\""},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "sensors": {"w": [0, 1]}})", "p.json:1:53: error: no sensor 'w'"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "sensors": {"p": "200 bar"}})", "p.json:1:58: error: p: a range is"},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "sensors": {"p": ["9 rpm", null]}})", "p.json:1:58: error: p: "},
      {R"({"circuit": "tiny", "inputs": {"q": 1}, "sensors": {"p": ["200 bar", "100 bar"]}})",
       "p.json:1:58: error: p: the low end must be below the high end"},
  };
  for (const Case& c : cases) {
    const auto e = parse_circuit_values_json(c.text, "p.json", *r.file);
    ASSERT_FALSE(e.ok()) << c.text;
    const std::string m = e.error->to_string();
    EXPECT_EQ(m.substr(0, std::string(c.expect).size()), c.expect) << "got: " << m;
  }
}

TEST(CircuitReader, EveryTruncationFailsCleanly) {
  // Every prefix of a good file is an error with a position (or, the whole file, none).
  const std::string good = kGood;
  for (std::size_t n = 0; n < good.size(); ++n) {
    const auto r = parse_circuit_json(good.substr(0, n), "c.json");
    ASSERT_FALSE(r.ok()) << n;
    EXPECT_GT(r.error->line, 0u) << n;
  }
}

TEST(CircuitReader, MissingFileIsAnError) {
  const auto r = hstmon::host::read_circuit_file("/nonexistent/circuit.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->to_string().rfind("/nonexistent/circuit.json: error: cannot open", 0), 0u);
}

}  // namespace
