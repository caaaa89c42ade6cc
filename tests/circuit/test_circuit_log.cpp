// Circuit logs (circuit_log.hpp) and input steps (circuit_schedule.hpp) with mistakes:
// file:line:column at the token, never a crash; units in brackets, parentheses or the
// circuit file's; unknown columns noted.
#include <gtest/gtest.h>

#include <string>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

ct::LoadedCircuit test_stand() {
  ct::LoadedCircuit c;
  const auto err =
      ct::load_circuit(std::string(HSTMON_SOURCE_DIR) + "/examples/circuits/test_stand.json", "", c);
  EXPECT_FALSE(err.has_value());
  return c;
}

std::string error_of(const std::string& text) {
  const ct::LoadedCircuit c = test_stand();
  const ct::CircuitLog log = ct::parse_circuit_log(text, "log.csv", c.file);
  EXPECT_EQ(log.rows(), 0u);
  return log.error ? log.error->to_string() : std::string("(no error)");
}

TEST(CircuitLog, ReadsUnitsAndNotesUnknownColumns) {
  const ct::LoadedCircuit c = test_stand();
  const ct::CircuitLog log = ct::parse_circuit_log(
      "# comment\r\nt [s];n_pump (1/min);throttle;p_line[MPa];q;extra\r\n0;1500;1;14,8;0.001;x\r\n0,01;1500;0,7;15;0.0011;y\r\n",
      "log.csv", c.file);
  ASSERT_TRUE(log.ok()) << log.error->to_string();
  ASSERT_EQ(log.rows(), 2u);
  EXPECT_NEAR(log.inputs[0][0], 1500 * 2 * 3.14159265358979 / 60, 1e-9);
  EXPECT_DOUBLE_EQ(log.inputs[1][1], 0.7);
  EXPECT_DOUBLE_EQ(log.sensors[0][0], 14.8e6);
  // A bare q is in the circuit file's unit for it (L/min).
  EXPECT_NEAR(log.sensors[1][1], 0.0011 / 60000, 1e-15);
  ASSERT_EQ(log.notes.size(), 1u);
  EXPECT_EQ(log.notes[0].rfind("log.csv:2:45: note: column 'extra'", 0), 0u) << log.notes[0];
}

TEST(CircuitLog, MistakesAreLocated) {
  EXPECT_EQ(error_of(""), "log.csv:1:1: error: empty log: no header row");
  EXPECT_EQ(error_of("p_line[bar]\n1\n"), "log.csv:1:1: error: no time column (t[s]) in the header");
  EXPECT_EQ(error_of("t[s],p_line[furlong]\n0,1\n").rfind("log.csv:1:6: error: column 'p_line': ", 0), 0u);
  EXPECT_EQ(error_of("t[s],p_line[bar],P_LINE[bar]\n"), "log.csv:1:18: error: duplicated column 'P_LINE'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0.1,1x\n"), "log.csv:3:5: error: not a number: '1x'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0.1\n"), "log.csv:3:4: error: row has 1 fields, the header 2");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0,2\n").rfind("log.csv:3:1: error: time not strictly increasing", 0), 0u);
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1e400\n"), "log.csv:2:3: error: not a number: '1e400'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n"), "log.csv:2:1: error: no data rows after the header");
  EXPECT_EQ(error_of(std::string("t[s]\n0\0", 7)), "log.csv:2:2: error: NUL byte: not a text log");
}

TEST(CircuitLog, EveryTruncationOfALogIsHandled) {
  const ct::LoadedCircuit c = test_stand();
  const std::string text = "t[s],n_pump[rpm],throttle,p_line[bar],q[L/min]\n0,1500,1,147.9,67.2\n0.005,1500,1,147.8,67.1\n";
  for (std::size_t n = 0; n <= text.size(); ++n) {
    const ct::CircuitLog log = ct::parse_circuit_log(text.substr(0, n), "log.csv", c.file);
    EXPECT_TRUE(log.ok() || log.error->line >= 1) << n;
  }
}

TEST(CircuitLog, MissingFileIsAnError) {
  const ct::LoadedCircuit c = test_stand();
  const ct::CircuitLog log = ct::read_circuit_log("/nonexistent/log.csv", c.file);
  ASSERT_TRUE(log.error.has_value());
  EXPECT_EQ(log.error->line, 0u);
}

TEST(CircuitSchedule, Steps) {
  const ct::LoadedCircuit c = test_stand();
  ct::InputStep s;
  ASSERT_FALSE(ct::parse_input_step("n_drive=1000 rpm@2.5", c.file, s).has_value());
  EXPECT_EQ(s.input, c.file.input_index("n_drive"));
  EXPECT_NEAR(s.value, 1000 * 2 * 3.14159265358979 / 60, 1e-9);
  EXPECT_DOUBLE_EQ(s.t, 2.5);
  EXPECT_TRUE(ct::parse_input_step("throttle=0.7", c.file, s).has_value());
  EXPECT_TRUE(ct::parse_input_step("nope=0.7@1", c.file, s).has_value());
  EXPECT_TRUE(ct::parse_input_step("throttle=0.7 bar@1", c.file, s).has_value());
  EXPECT_TRUE(ct::parse_input_step("throttle=0.7@-1", c.file, s).has_value());
}

}  // namespace
