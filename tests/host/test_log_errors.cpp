// Log reader: every malformed input gives one error with the exact line and column, no
// crash, and (strict mode) no rows; lenient mode keeps the rows before the bad one, and
// skips rows whose time is not above the last kept row's with a note.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../support/error_cases.hpp"
#include "../support/mem_log.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hh = hstmon::host;
using hh::Signal;

namespace {

using hstmon_test::read;
using namespace std::string_literals;  // a log with a NUL byte in it

// read() with lenient = true: the valid part of a bad log is kept.
hh::LogData read_lenient(std::string_view text) {
  hh::ReadOptions opt;
  opt.lenient = true;
  return read(text, opt);
}

/// Reads `c.text` strictly and checks the error; also checks that no rows are left.
void expect_refused(const hstmon_test::ErrorCase& c, const hh::ReadOptions& opt = {}) {
  const hh::LogData d = read(c.text, opt);
  hstmon_test::expect_error_at(d.error, "mem.csv", c);
  EXPECT_EQ(d.rows(), 0u);
  for (const auto& v : d.values) EXPECT_TRUE(v.empty());
}

/// expect_refused() for a text outside the table.
void expect_error(std::string_view text, std::size_t line, std::size_t column, const std::string& part,
                  const hh::ReadOptions& opt = {}) {
  expect_refused({"", std::string(text), line, column, part}, opt);
}

}  // namespace

TEST(LogErrors, MessageFormat) {
  const auto d = read("t,p_mi\n0,1\n0.001,1.2.3\n");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->to_string(), "mem.csv:3:7: error: bad number '1.2.3' in column 'p_mi'");
}

// Each malformed log of the table, read strictly: one error at its line:column.
class LogRefusal : public testing::TestWithParam<hstmon_test::ErrorCase> {};

TEST_P(LogRefusal, PointsAtTheMistake) { expect_refused(GetParam()); }

// One case a line.
// clang-format off
const hstmon_test::ErrorCase kRefused[] = {
    {"BadNumbers", "t,p_mi\n0,1\n0.001,1.2.3\n", 3, 7, "bad number '1.2.3'"},
    {"BadNumbers", "t,p_mi\n0,abc\n", 2, 3, "bad number 'abc' in column 'p_mi'"},
    {"BadNumbers", "t,p_mi\nx,1\n", 2, 1, "bad number 'x' in column 't'"},
    {"BadNumbers", "t,p_mi\n0,1.5x\n", 2, 3, "bad number '1.5x'"},
    {"BadNumbers", "t,p_mi\n0,0x10\n", 2, 3, "bad number '0x10'"},
    {"BadNumbers", "t,p_mi\n0,1 2\n", 2, 3, "bad number '1 2'"},
    {"BadNumbers", "t,p_mi\n0,--1\n", 2, 3, "bad number '--1'"},
    {"BadNumbers", "t,p_mi\n0,\"1\"\n", 2, 3, "bad number"},
    {"BadNumbers", "t;p_mi\n0;1,2,3\n", 2, 3, "bad number '1,2,3'"},
    {"BadNumbers", "t,p_mi\n0,1\r5\n", 2, 3, "bad number '1\\x0D5'"},
    {"BadNumbers", "t;p_mi\n0;1,2345678901234567890123456789012345678901234567890123456789012345\n", 2, 3, "bad number"},
    {"EmptyField", "t,p_mi\n0,\n", 2, 3, "empty field in column 'p_mi'"},
    {"EmptyField", "t,p_mi,p_mo\n0,,1\n", 2, 3, "empty field in column 'p_mi'"},
    {"EmptyField", "t\tp_mi\n\t1\n", 2, 1, "empty field in column 't'"},
    {"RaggedRows", "t,p_mi,p_mo\n0,1,2\n0.001,1\n", 3, 8, "row has 2 fields, header has 3"},
    {"RaggedRows", "t,p_mi\n0,1,2\n", 2, 5, "row has more than 2 fields"},
    {"RaggedRows", "t,p_mi\n0,1,5\n", 2, 5, "decimal comma needs ';' or tab"},
    {"RaggedRows", "t;p_mi;x\n0;1\n", 2, 4, "row has 2 fields, header has 3"},
    {"RaggedRows", "t\tp_mi\n0\t1\t\n", 2, 5, "row has more than 2 fields"},
    {"UnitsRefused", "t[s],p_mi[bars]\n0,1\n", 1, 11, "unknown pressure unit 'bars' (use"},
    {"UnitsRefused", "t,p_mi[mpa]\n0,1\n", 1, 8, "ambiguous pressure unit 'mpa'"},
    {"UnitsRefused", "t[us],p_mi\n0,1\n", 1, 3, "unknown time unit 'us'"},
    {"UnitsRefused", "t,w_m[Hz]\n0,1\n", 1, 7, "unknown speed unit 'Hz'"},
    {"UnitsRefused", "t,kp[l/min]\n0,1\n", 1, 6, "unknown orifice coefficient unit"},
    {"UnitsRefused", "t\tp_mi\ns\tbars\n0\t1\n", 2, 3, "unknown pressure unit 'bars'"},
    {"UnitsRefused", "t[s]\tp_mi[bar]\ns\tkPa\n0\t1\n", 2, 3, "differs from 'bar' in the header"},
    {"UnitsRefused", "t\tp_mi\ns\n0\t1\n", 2, 2, "units row has 1 fields, header has 2"},
    {"HeaderProblems", "t,p_mi,P_MI\n0,1,2\n", 1, 8, "duplicate column name 'P_MI' (also field 2)"},
    {"HeaderProblems", "t,x,x\n0,1,2\n", 1, 5, "duplicate column name 'x'"},
    {"HeaderProblems", "p_mi,p_mo\n1,2\n", 1, 1, "no time column 't'"},
    {"HeaderProblems", "t,,p_mi\n0,1,2\n", 1, 3, "empty column name"},
    {"HeaderProblems", "t[s,p_mi\n0,1\n", 1, 2, "must end with ']'"},
    {"HeaderProblems", "t,p_mi (bar\n0,1\n", 1, 8, "must end with ')'"},
    {"TimeNotStrictlyIncreasing", "t,p_mi\n0,1\n0.001,1\n0.001,1\n", 4, 1, "time not strictly increasing: 0.001 s after 0.001 s"},
    {"TimeNotStrictlyIncreasing", "t,p_mi\n1,1\n0.5,1\n", 3, 1, "time not strictly increasing"},
    {"TimeNotStrictlyIncreasing", "p_mi;t[ms]\n1;0\n1;-1\n", 3, 3, "time not strictly increasing: -0.001 s after 0 s"},
    // The error for a time that does not increase names the fix for a rounded time column.
    {"TimeNotStrictlyIncreasing", "t,p_mi\n0,1\n0.001,1\n0.001,1\n", 4, 1, "rebuild time from the row index with --rate HZ"},
    {"NonFiniteValues", "t,p_mi\n0,nan\n", 2, 3, "non-finite value 'nan' in column 'p_mi'"},
    {"NonFiniteValues", "t,p_mi\n0,NaN\n", 2, 3, "non-finite value 'NaN'"},
    {"NonFiniteValues", "t,p_mi\n0,inf\n", 2, 3, "non-finite value 'inf'"},
    {"NonFiniteValues", "t,p_mi\n0,-Infinity\n", 2, 3, "non-finite value '-Infinity'"},
    {"NonFiniteValues", "t,p_mi\ninf,1\n", 2, 1, "non-finite value 'inf' in column 't'"},
    {"NonFiniteValues", "t,p_mi\n0,1e999\n", 2, 3, "number out of range '1e999'"},
    {"NonFiniteValues", "t,p_mi[bar]\n0,1e305\n", 2, 3, "value out of range after unit conversion '1e305'"},
    {"EmptyAndHeaderOnly", "", 1, 1, "empty file"},
    {"EmptyAndHeaderOnly", "\n\r\n  \n", 1, 1, "empty file"},
    {"EmptyAndHeaderOnly", "\xEF\xBB\xBF", 1, 1, "empty file"},
    {"EmptyAndHeaderOnly", "# a\n# b\n", 3, 1, "no header line"},
    {"EmptyAndHeaderOnly", "t,p_mi\n", 2, 1, "no data rows"},
    {"EmptyAndHeaderOnly", "t,p_mi", 1, 7, "no data rows"},
    {"EmptyAndHeaderOnly", "t,p_mi\n# only a comment\n\n", 4, 1, "no data rows"},
    {"EmptyAndHeaderOnly", "t\tp_mi\ns\tbar\n", 3, 1, "no data rows"},
    {"BinaryJunk", "t,p_mi\n0,1\n0.001,1\0\x01\n"s, 3, 8, "NUL byte"},
    {"BinaryJunk", "t,p_mi\n0,1\xff\n", 2, 4, "invalid UTF-8 byte 0xFF"},
    {"BinaryJunk", "t,p\xC2\xB0\xff\n0,1\n", 1, 5, "invalid UTF-8 byte 0xFF"},
    {"BinaryJunk", "t,p_mi\n0,1\xC3", 2, 4, "invalid UTF-8 byte 0xC3"},
    {"BinaryJunk", "t,p_mi\n0,\xC0\x80\n", 2, 3, "invalid UTF-8 byte 0xC0"},
    {"BinaryJunk", "t,p_mi\n0,\xED\xA0\x80\n", 2, 3, "invalid UTF-8 byte 0xED"},
    {"BinaryJunk", "t,p_mi\n0,1\n# comment \x80\n1,2\n", 3, 11, "invalid UTF-8 byte 0x80"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(LogErrors, LogRefusal, testing::ValuesIn(kRefused), hstmon_test::error_case_name);

TEST(LogErrors, ColumnMapProblems) {
  hh::ReadOptions opt;
  opt.column_map = {{"a", "p_mi"}};
  expect_error("t,a,p_mi\n0,1,2\n", 1, 5, "gives signal 'p_mi', already given by field 2", opt);
  opt.column_map = {{"a", "p_m"}};
  expect_error("t,a\n0,1\n", 1, 3, "column map sends 'a' to 'p_m', which is not a known signal", opt);
}

TEST(LogErrors, BinaryJunk) {
  std::string junk;
  for (int i = 0; i < 4096; ++i) junk += static_cast<char>((i * 37 + 11) & 0xFF);
  const auto d = read(junk);
  ASSERT_FALSE(d.ok());
  EXPECT_GE(d.error->line, 1u);
  EXPECT_GE(d.error->column, 1u);
  // A clean ASCII file 8 bytes at a time with the bad byte at every offset of a word.
  for (std::size_t k = 0; k < 16; ++k) {
    std::string text = "t,p_mi\n0,1\n0.001,1234567890123456\n";
    text[13 + k] = '\0';
    const auto e = read(text);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.error->line, 3u);
    EXPECT_EQ(e.error->column, 3 + k);
  }
}

TEST(LogErrors, StrictModeKeepsNoRows) {
  const auto d = read("t,p_mi,p_mo\n0,1,2\n1,2,3\n2,3,x\n3,4,5\n");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.rows(), 0u);
  EXPECT_TRUE(d.column(Signal::kPMi).empty());
  EXPECT_TRUE(d.column(Signal::kPMo).empty());
  EXPECT_TRUE(d.has(Signal::kPMi));  // the header was understood
}

TEST(LenientRead, KeepsTheValidPrefix) {
  struct Case {
    const char* what;
    std::string text;
    std::size_t rows, line, column;
  };
  const Case cases[] = {
      {"bad number", "t,p_mi,p_mo\n0,1,2\n1,2,3\n2,x,4\n3,4,5\n", 2, 4, 3},
      {"bad number in the last column", "t,p_mi,p_mo\n0,1,2\n1,2,3\n2,3,x\n3,4,5\n", 2, 4, 5},
      {"truncated last line", "t,p_mi,p_mo\n0,1,2\n1,2,3\n2,3", 2, 4, 4},
      {"nan", "t,p_mi,p_mo\n0,1,2\n1,2,3\n2,nan,4\n", 2, 4, 3},
      {"binary tail", std::string("t,p_mi,p_mo\n0,1,2\n1,2,3\n2,3,4\xff\xfe\n", 31), 2, 4, 6},
      {"NUL tail", std::string("t,p_mi,p_mo\n0,1,2\n# c\n1,2,3\n\0\0\0\0", 33), 2, 5, 1},
      {"first row bad", "t,p_mi,p_mo\n0,1\n", 0, 2, 4},
  };
  for (const Case& c : cases) {
    const auto d = read_lenient(c.text);
    ASSERT_FALSE(d.ok()) << c.what;
    EXPECT_EQ(d.rows(), c.rows) << c.what;
    EXPECT_EQ(d.column(Signal::kPMi).size(), c.rows) << c.what;
    EXPECT_EQ(d.column(Signal::kPMo).size(), c.rows) << c.what;
    EXPECT_EQ(d.error->line, c.line) << c.what << ": " << d.error->to_string();
    EXPECT_EQ(d.error->column, c.column) << c.what << ": " << d.error->to_string();
    if (c.rows == 2) {
      EXPECT_EQ(d.t[1], 1.0) << c.what;
      EXPECT_EQ(d.column(Signal::kPMo)[1], 3.0) << c.what;
    }
  }
}

TEST(LenientRead, SkipsRowsWithTimeNotIncreasingWithANote) {
  const std::string text = "t,p_mi,p_mo\n0,1,2\n1,2,3\n1,9,9\n0.5,8,8\n2,3,4\n";
  const auto d = read_lenient(text);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  ASSERT_EQ(d.rows(), 3u);
  EXPECT_EQ(d.t, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(d.column(Signal::kPMi), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(d.column(Signal::kPMo), (std::vector<double>{2, 3, 4}));
  EXPECT_EQ(d.skipped_rows, 2u);
  ASSERT_EQ(d.notes.size(), 2u);
  EXPECT_EQ(d.notes[0], "mem.csv:4:1: note: time not strictly increasing: 1 s after 1 s; row skipped (lenient)");
  EXPECT_EQ(d.notes[1], "mem.csv:5:1: note: time not strictly increasing: 0.5 s after 1 s; row skipped (lenient)");
  // Strict: the same text fails at the first of them.
  expect_error(text, 4, 1, "time not strictly increasing: 1 s after 1 s");
}

TEST(LenientRead, SkippedRowLeavesNoValueWhereTimeIsNotTheFirstColumn) {
  const auto d = read_lenient("p_mi;t[ms];p_mo\n1;0;1\n2;0;2\n3;1;3\n");
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.column(Signal::kPMi), (std::vector<double>{1, 3}));
  EXPECT_EQ(d.column(Signal::kPMo), (std::vector<double>{1, 3}));
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0], "mem.csv:3:3: note: time not strictly increasing: 0 s after 0 s; row skipped (lenient)");
}

TEST(LenientRead, ASkippedRowMustStillBeWellFormed) {
  const auto d = read_lenient("t,p_mi\n0,1\n0,x\n1,2\n");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.rows(), 1u);
  EXPECT_EQ(d.column(Signal::kPMi).size(), 1u);
  EXPECT_EQ(d.error->line, 3u);
  EXPECT_EQ(d.error->column, 3u);
  const auto e = read_lenient("t,p_mi\n0,1\n0,2,3\n1,2\n");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.rows(), 1u);
  EXPECT_EQ(e.error->line, 3u);
}

TEST(LenientRead, ClockResetSkipsUpToTheOldTimeWithCappedNotes) {
  // 0..999 s, then the logger's clock steps back 30 s: rows at 970..999 s again are
  // skipped (not above the last kept time), 1000..1029 s are kept. 30 of 1060 rows
  // (2.8 %) is within what a lenient read may drop.
  std::string text = "t,p_mi\n";
  for (int k = 0; k < 1000; ++k) text += std::to_string(k) + ",1\n";
  for (int k = 970; k < 1030; ++k) text += std::to_string(k) + ",2\n";
  const auto d = read_lenient(text);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.rows(), 1030u);
  EXPECT_EQ(d.skipped_rows, 30u);
  EXPECT_EQ(d.t[999], 999.0);
  EXPECT_EQ(d.t[1000], 1000.0);
  EXPECT_EQ(d.column(Signal::kPMi)[1000], 2.0);
  ASSERT_EQ(d.notes.size(), 21u) << "20 notes of their own, then one with the count";
  EXPECT_EQ(d.notes[0].rfind("mem.csv:1002:1: note: time not strictly increasing: 970 s after 999 s", 0), 0u)
      << d.notes[0];
  EXPECT_EQ(d.notes[20].rfind("mem.csv:1031:1: note: 30 rows skipped in all", 0), 0u) << d.notes[20];
  // Strict reads still refuse the log.
  expect_error(text, 1002, 1, "time not strictly increasing: 970 s after 999 s");
}

// Issue 16: a lenient read never drops most of a file quietly. A clock reset that
// would skip 100 of 250 rows (40 %) fails at the first of them, keeps no rows, has no
// list of skipped rows, and names --rate as the fix.
TEST(LenientRead, RefusesToDropMoreThanAFewPerCent) {
  std::string text = "t,p_mi\n";
  for (int k = 0; k < 100; ++k) text += std::to_string(k) + ",1\n";
  for (int k = 0; k < 150; ++k) text += std::to_string(k) + ",2\n";
  const auto d = read_lenient(text);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.rows(), 0u);
  EXPECT_TRUE(d.column(Signal::kPMi).empty());
  EXPECT_EQ(d.error->line, 102u);
  EXPECT_EQ(d.error->column, 1u);
  EXPECT_NE(d.error->message.find("100 of 250 rows (40 %)"), std::string::npos) << d.error->message;
  EXPECT_NE(d.error->message.find("--rate HZ"), std::string::npos) << d.error->message;
  EXPECT_TRUE(d.notes.empty()) << d.notes.size() << " notes";
  EXPECT_LT(d.error->to_string().size(), 300u);
  // Up to 10 skipped rows are a glitch whatever the share: 10 of 20 rows is accepted.
  std::string few = "t,p_mi\n";
  for (int k = 0; k < 10; ++k) few += std::to_string(k) + ",1\n";
  for (int k = 0; k < 10; ++k) few += "9,1\n";
  const auto f = read_lenient(few);
  ASSERT_TRUE(f.ok()) << f.error->to_string();
  EXPECT_EQ(f.skipped_rows, 10u);
}

TEST(LenientRead, HeaderErrorsStillGiveNoRows) {
  const auto d = read_lenient("t,p_mi[bars]\n0,1\n");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.rows(), 0u);
}

TEST(LenientRead, CleanFileIsUnaffected) {
  const auto d = read_lenient("t,p_mi\n0,1\n1,2\n");
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d.rows(), 2u);
}
