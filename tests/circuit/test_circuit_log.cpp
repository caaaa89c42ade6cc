// Circuit logs (circuit_log.hpp) and input steps (circuit_schedule.hpp) with mistakes:
// file:line:column at the token, never a crash; units in brackets, parentheses or the
// circuit file's; unknown columns noted.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../support/loaded_circuit.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_schedule.hpp"
#include "hstmon_host/log_reader.hpp"

namespace {

namespace ct = hstmon::circuit_tools;

ct::LoadedCircuit test_stand() { return hstmon_test::load_example("test_stand"); }

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
  EXPECT_EQ(error_of("p_line[bar]\n1\n"),
            "log.csv:1:1: error: no time column (t[s]) in the header (or give the sample rate: --rate HZ); the "
            "columns are 'p_line'");
  EXPECT_EQ(error_of("t[s],p_line[furlong]\n0,1\n").rfind("log.csv:1:13: error: unknown pressure unit 'furlong'", 0),
            0u);
  EXPECT_EQ(error_of("t[s],p_line[bar],P_LINE[bar]\n"), "log.csv:1:18: error: duplicated column 'P_LINE'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0.1,1x\n"), "log.csv:3:5: error: bad number '1x' in column 'p_line'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0.1\n"), "log.csv:3:4: error: row has 1 fields, the header 2");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1\n0,2\n").rfind("log.csv:3:1: error: time not strictly increasing", 0), 0u);
  EXPECT_EQ(error_of("t[s],p_line[bar]\n0,1e400\n"),
            "log.csv:2:3: error: number out of range '1e400' in column 'p_line'");
  EXPECT_EQ(error_of("t[s],p_line[bar]\n"), "log.csv:2:1: error: no data rows after the header");
  EXPECT_EQ(error_of(std::string("t[s]\n0\0", 7)), "log.csv:2:2: error: NUL byte: not a text log");
}

// The log options every reader takes (host::ReadOptions), with the thesis logs' meaning.
ct::CircuitLog parse_with(const std::string& text, const hstmon::host::ReadOptions& o) {
  const ct::LoadedCircuit c = test_stand();
  return ct::parse_circuit_log(text, "log.txt", c.file, o);
}

// A test-stand export as a Spider8 writes one: tab, decimal comma, CRLF, channel names
// with "CH=n", time rounded to 1 ms at 4800 Hz (most timestamps repeat).
std::string spider8_stand(int rows) {
  std::string text = "Time  Spider8_1 CH=1\tn CH=2\tthrottle CH=3\tp CH=8\tQ CH=9\r\n";
  for (int i = 0; i < rows; ++i) {
    char line[128];
    std::snprintf(line, sizeof line, "%.3f\t1500\t1\t%.2f\t67,1\r\n", static_cast<double>(i) / 4800.0, 148.0 + 0.01 * i);
    for (char* q = line; *q != 0; ++q) {
      if (*q == '.') *q = ',';
    }
    text += line;
  }
  return text;
}

TEST(CircuitLog, Spider8ExportLoadsWithRateAndMap) {
  hstmon::host::ReadOptions o;
  o.rate = 4800.0;
  o.column_number_map[1] = "t";
  o.column_map = {{"n CH=2", "n_pump"}, {"THROTTLE ch=3", "throttle"}, {"p  CH=8", "p_line"}, {"Q CH=9", "q"}};
  const ct::CircuitLog log = parse_with(spider8_stand(300), o);
  ASSERT_TRUE(log.ok()) << log.error->to_string();
  ASSERT_EQ(log.rows(), 300u);
  EXPECT_DOUBLE_EQ(log.t[299], 299.0 / 4800.0);
  EXPECT_NEAR(log.inputs[0][0], 1500 * 2 * 3.14159265358979 / 60, 1e-9);  // n_pump: the circuit file's rpm
  EXPECT_NEAR(log.sensors[0][10], 148.1e5, 1e-3);                         // p_line: bar, decimal comma
  EXPECT_NEAR(log.sensors[1][0], 67.1 / 60000, 1e-15);                    // q: L/min
  EXPECT_TRUE(log.notes.empty()) << log.notes.front();
}

// Instrument layouts, by the thesis reader's rules (hstmon_host/log_layout.hpp): a units
// row above the names (catman/Spider8), a metadata block above names and units (HYDAC
// HMG), a units row below the names; a unit the circuit cannot take is located in the
// units row, not the header.
TEST(CircuitLog, InstrumentLayoutsAreRecognised) {
  const ct::LoadedCircuit c = test_stand();
  std::string rows;
  for (int i = 0; i < 50; ++i) rows += std::to_string(i) + ",00\t1500\t1\t148,5\t67,1\r\n";  // t = i s
  const ct::CircuitLog units_above =
      ct::parse_circuit_log("s\trpm\t-\tbar\tL/min\r\nt\tn_pump\tthrottle\tp_line\tq\r\n" + rows, "spider8.txt", c.file);
  ASSERT_TRUE(units_above.ok()) << units_above.error->to_string();
  ASSERT_EQ(units_above.rows(), 50u);
  EXPECT_DOUBLE_EQ(units_above.t[49], 49.0);
  EXPECT_DOUBLE_EQ(units_above.sensors[0][0], 148.5e5);      // bar, from the units row
  EXPECT_NEAR(units_above.sensors[1][0], 67.1 / 60000, 1e-15);  // L/min
  EXPECT_TRUE(units_above.notes.empty());

  const ct::CircuitLog hmg = ct::parse_circuit_log(
      "Device;HMG 4000\nDate;2026-11-01\nChannels;4\nt;n_pump;p_line;q\ns;1/min;MPa;L/min\n0;1500;14,8;60\n1;1500;14,9;60\n",
      "hmg.csv", c.file);
  ASSERT_TRUE(hmg.ok()) << hmg.error->to_string();
  ASSERT_EQ(hmg.rows(), 2u);
  EXPECT_DOUBLE_EQ(hmg.sensors[0][1], 14.9e6);
  ASSERT_EQ(hmg.notes.size(), 1u);
  EXPECT_EQ(hmg.notes[0], "hmg.csv:1:1: note: lines 1-3 above the column names taken as metadata, not columns");

  const ct::CircuitLog units_below = ct::parse_circuit_log("t,p_line,q\ns,MPa,L/s\n0,15,1\n0.1,15,1\n", "b.csv", c.file);
  ASSERT_TRUE(units_below.ok()) << units_below.error->to_string();
  EXPECT_DOUBLE_EQ(units_below.sensors[0][0], 15e6);
  EXPECT_DOUBLE_EQ(units_below.sensors[1][0], 1e-3);

  const ct::CircuitLog bad_unit = ct::parse_circuit_log("t,p_line,q\ns,bar,V\n0,15,1\n", "v.csv", c.file);
  ASSERT_TRUE(bad_unit.error.has_value());
  EXPECT_EQ(bad_unit.error->to_string().rfind("v.csv:2:7: error: unknown flow unit 'V'", 0), 0u)
      << bad_unit.error->to_string();
  EXPECT_NE(bad_unit.error->to_string().find("in column 'q'"), std::string::npos) << bad_unit.error->to_string();
  // A text line below a header that states its units must agree with them.
  const ct::CircuitLog text_row = ct::parse_circuit_log("t[s],p_line[bar]\nfoo,bar\n0,1\n", "f.csv", c.file);
  ASSERT_TRUE(text_row.error.has_value());
  EXPECT_EQ(text_row.error->to_string(), "f.csv:2:1: error: unit 'foo' of column 't' differs from 's' in the header");
}

TEST(CircuitLog, Spider8ExportWithoutRateNamesTheFix) {
  hstmon::host::ReadOptions o;
  o.column_number_map[1] = "t";
  o.column_map = {{"p CH=8", "p_line"}};
  const ct::CircuitLog strict = parse_with(spider8_stand(300), o);
  ASSERT_TRUE(strict.error.has_value());
  EXPECT_EQ(strict.error->line, 3u);
  EXPECT_NE(strict.error->message.find("--rate HZ"), std::string::npos) << strict.error->message;
  EXPECT_EQ(strict.rows(), 0u);
  // Lenient would drop most rows: refused, with the reason and the fix, no rows kept.
  o.lenient = true;
  const ct::CircuitLog lenient = parse_with(spider8_stand(300), o);
  ASSERT_TRUE(lenient.error.has_value());
  EXPECT_NE(lenient.error->message.find("in 237 of 300 rows (79 %); a lenient read skips at most 5 %"),
            std::string::npos)
      << lenient.error->message;
  EXPECT_NE(lenient.error->message.find("--rate HZ"), std::string::npos);
  EXPECT_EQ(lenient.error->line, 3u) << "at the first skipped row, as every reader";
  EXPECT_TRUE(lenient.notes.empty() || lenient.notes.back().find("row skipped") == std::string::npos)
      << "no list of the skipped rows";
  EXPECT_EQ(lenient.rows(), 0u);
}

TEST(CircuitLog, LenientSkipsARepeatedTimeAndKeepsRowsBeforeABadOne) {
  hstmon::host::ReadOptions o;
  o.lenient = true;
  std::string text = "t[s],p_line[bar]\n";
  for (int i = 0; i < 40; ++i) text += std::to_string(0.01 * (i == 20 ? i - 1 : i)) + ",150\n";
  const ct::CircuitLog skipped = parse_with(text, o);
  ASSERT_TRUE(skipped.ok()) << skipped.error->to_string();
  EXPECT_EQ(skipped.rows(), 39u);
  ASSERT_EQ(skipped.notes.size(), 1u);
  EXPECT_EQ(skipped.notes[0].rfind("log.txt:22:1: note: time not strictly increasing", 0), 0u) << skipped.notes[0];
  const ct::CircuitLog stopped = parse_with(text + "0.5,oops\n0.6,150\n", o);
  ASSERT_TRUE(stopped.error.has_value());
  EXPECT_EQ(stopped.error->to_string(), "log.txt:42:5: error: bad number 'oops' in column 'p_line'");
  EXPECT_EQ(stopped.rows(), 39u);  // the rows before the bad one
}

TEST(CircuitLog, SeparatorAndMapOptions) {
  hstmon::host::ReadOptions o;
  o.separator = ';';
  o.column_map = {{"Druck", "p_line"}, {"junk", ""}};
  const ct::CircuitLog log = parse_with("t[s];Druck[bar];junk\n0;150,5;x\n0,001;151;y\n", o);
  ASSERT_TRUE(log.ok()) << log.error->to_string();
  EXPECT_DOUBLE_EQ(log.sensors[0][0], 150.5e5);
  EXPECT_TRUE(log.notes.empty());  // a column mapped to "" is dropped without a note
  o.column_number_map[7] = "q";
  const ct::CircuitLog beyond = parse_with("t[s];Druck[bar];junk\n0;150,5;x\n", o);
  ASSERT_TRUE(beyond.error.has_value());
  EXPECT_EQ(beyond.error->to_string(), "log.txt:1:1: error: --map #7: the header has 3 columns");
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

// A bare number for a speed would be 1000 rad/s: an error that names the unit to write.
TEST(CircuitSchedule, BareNumberForADimensionedInputIsAnErrorNamingItsUnit) {
  const ct::LoadedCircuit c = test_stand();
  ct::InputStep s;
  const auto err = ct::parse_input_step("n_drive=1000@2.5", c.file, s);
  ASSERT_TRUE(err.has_value());
  EXPECT_NE(err->find("give the unit of n_drive (speed)"), std::string::npos) << *err;
  EXPECT_NE(err->find("'n_drive=1000 "), std::string::npos) << *err;
  EXPECT_FALSE(ct::parse_input_step("n_drive=1000 rad/s@2.5", c.file, s).has_value());
  EXPECT_FALSE(ct::parse_input_step("throttle=0.7@1", c.file, s).has_value());  // a fraction needs none
}

}  // namespace
