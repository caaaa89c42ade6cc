// Log reader: separators, decimal commas, units (inline and catman units row), BOM/CRLF,
// comments, column mapping, ignored and missing columns, reading from disk.
#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../support/mem_log.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hh = hstmon::host;
using hh::Signal;

namespace {

using hstmon_test::kRpm;
using hstmon_test::read;

#define EXPECT_LOG_OK(d) ASSERT_TRUE((d).ok()) << (d).error->to_string()

/// (p_mi, p_mo) of row `row`: the motor's port pressures, compared as a pair.
std::pair<double, double> port_pressures(const hh::LogData& d, std::size_t row) {
  return {d.column(Signal::kPMi).at(row), d.column(Signal::kPMo).at(row)};
}

}  // namespace

TEST(LogReader, CommaSeparatedWithInlineUnits) {
  const auto d = read(
      "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n"
      "0,35,4.41e-8,33.1,1.88,171.1,1677\n"
      "0.001,35,4.41e-8,33.2,1.89,171.2,1678\n");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.header_line, 1u);
  EXPECT_EQ(d.t[0], 0.0);
  EXPECT_EQ(d.t[1], 0.001);
  EXPECT_TRUE(d.has(Signal::kPSup));
  EXPECT_TRUE(d.has(Signal::kKp));
  EXPECT_FALSE(d.has(Signal::kPS));
  EXPECT_FALSE(d.has(Signal::kPBp));
  EXPECT_TRUE(d.column(Signal::kPS).empty());
  EXPECT_EQ(d.column(Signal::kPSup)[0], 3.5e6);
  EXPECT_EQ(d.column(Signal::kKp)[1], 4.41e-8);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPMi)[1], 33.2e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPMo)[0], 1.88e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPPp)[0], 171.1e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kWm)[1], 1678 * kRpm);
  EXPECT_EQ(d.source_units[hh::index(Signal::kPMi)], "bar");
  EXPECT_EQ(d.source_columns[hh::index(Signal::kWm)], 7u);
  EXPECT_EQ(&d.column(Signal::kT), &d.t);
  EXPECT_TRUE(d.notes.empty());
}

TEST(LogReader, NoUnitMeansSi) {
  const auto d = read("t,p_mi,w_m\n0,3.3e6,175.5\n1,3.4e6,176\n");
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPMi)[0], 3.3e6);
  EXPECT_EQ(d.column(Signal::kWm)[0], 175.5);
  EXPECT_EQ(d.source_units[hh::index(Signal::kPMi)], "");
}

TEST(LogReader, SeparatorAndDecimalVariants) {
  struct Variant {
    const char* name;
    const char* text;
  };
  const Variant variants[] = {
      {"comma, point", "t[s],p_mi[bar]\n0,1.5\n0.5,2.25\n"},
      {"semicolon, point", "t[s];p_mi[bar]\n0;1.5\n0.5;2.25\n"},
      {"semicolon, comma", "t[s];p_mi[bar]\n0;1,5\n0,5;2,25\n"},
      {"tab, point", "t[s]\tp_mi[bar]\n0\t1.5\n0.5\t2.25\n"},
      {"tab, comma", "t[s]\tp_mi[bar]\n0\t1,5\n0,5\t2,25\n"},
      {"blanks around fields", "t [s] ; p_mi [bar]\n 0 ; 1,5 \n+0,5;\t2,25\n"},
      {"parentheses", "t (s),p_mi (bar)\n0,1.5\n0.5,2.25\n"},
      {"quoted names", "\"t [s]\";\"p_mi [bar]\"\n0;1,5\n0,5;2,25\n"},
      {"exponents", "t[s];p_mi[bar]\n0;15e-1\n5,0E-1;2,25e0\n"},
  };
  for (const Variant& v : variants) {
    const auto d = read(v.text);
    ASSERT_TRUE(d.ok()) << v.name << ": " << d.error->to_string();
    ASSERT_EQ(d.rows(), 2u) << v.name;
    EXPECT_EQ(d.t[1], 0.5) << v.name;
    EXPECT_EQ(d.column(Signal::kPMi)[0], 1.5e5) << v.name;
    EXPECT_EQ(d.column(Signal::kPMi)[1], 2.25e5) << v.name;
  }
}

TEST(LogReader, DecimalCommaWithoutIntegerDigits) {
  const auto d = read("t;p_mi\n0;,5\n1; -,25 \n2;+1,\n");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 3u);
  EXPECT_EQ(d.column(Signal::kPMi)[0], 0.5);
  EXPECT_EQ(d.column(Signal::kPMi)[1], -0.25);
  EXPECT_EQ(d.column(Signal::kPMi)[2], 1.0);
}

TEST(LogReader, ForcedSeparator) {
  hh::ReadOptions opt;
  opt.separator = ';';
  const auto d = read("t;p_mi\n0;1,5\n1;2\n", opt);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPMi)[0], 1.5);
  opt.separator = '|';
  const auto bad = read("t|p_mi\n0|1\n", opt);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error->line, 0u);
}

TEST(LogReader, CatmanExportWithUnitsRow) {
  // HBM catman / Spider8 style: tab separated, decimal commas, units in the second row,
  // BOM, CRLF, and blank lines at the end.
  const std::string text =
      "\xEF\xBB\xBF"
      "t\tp_mi\tp_mo\tp_pp\tw_m\r\n"
      "s\tbar\tbar\tbar\t1/min\r\n"
      "0\t33,12\t1,879\t171,08\t1677,7\r\n"
      "0,001\t33,13\t1,880\t171,09\t1677,9\r\n"
      "0,002\t33,14\t1,881\t171,10\t1678,1\r\n"
      "\r\n\r\n";
  const auto d = read(text);
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 3u);
  EXPECT_EQ(d.t[2], 0.002);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPMi)[0], 33.12e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPMo)[2], 1.881e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kWm)[1], 1677.9 * kRpm);
  EXPECT_EQ(d.source_units[hh::index(Signal::kWm)], "1/min");
  EXPECT_EQ(d.source_units[hh::index(Signal::kT)], "s");
}

TEST(LogReader, UnitsRowWithEmptyAndBracketedFields) {
  const auto d = read("t;kp;p_mi;p_mo\n[s];;(kPa);-\n0;4e-8;100;2\n1;4e-8;200;3\n");
  // "-" is not a pressure unit: refused at its column.
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->line, 2u);
  EXPECT_EQ(d.error->column, 12u);
  const auto good = read("t;kp;p_mi;p_mo\n[s];;(kPa);\n0;4e-8;100;2\n1;4e-8;200;3\n");
  EXPECT_LOG_OK(good);
  EXPECT_EQ(port_pressures(good, 1), std::make_pair(2e5, 3.0));
}

TEST(LogReader, UnitsRowAgreeingWithHeaderUnits) {
  const auto d = read("t[s]\tp_mi[bar]\ns\tbar\n0\t1\n1\t2\n");
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 2e5);
}

TEST(LogReader, BomCrlfCommentsAndBlankLines) {
  const std::string text =
      "\xEF\xBB\xBF# exported by test\r\n"
      "\r\n"
      "  # indented comment\r\n"
      "t[ms],p_pp[MPa]\r\n"
      "0,17.1\r\n"
      "# a comment between rows\r\n"
      "   \r\n"
      "1,17.2\r\n"
      "\r\n";
  const auto d = read(text);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.header_line, 4u);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.t[1], 1e-3);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPPp)[1], 17.2e6);
}

TEST(LogReader, LastLineWithoutNewline) {
  const auto d = read("t,p_mi\n0,1\n1,2");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 2.0);
}

TEST(LogReader, ColumnMapping) {
  hh::ReadOptions opt;
  opt.column_map = {{"Zeit", "t"}, {"druck_a", "P_MI"}, {"Drehzahl", "w_m"}, {"Status", ""}};
  const auto d = read("ZEIT[s];Druck_A[bar];Drehzahl[U/min];Status;Temp[C]\n0;33;1677;ok;40\n0,1;34;1678;ok;41\n", opt);
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.t[1], 0.1);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 34e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kWm)[0], 1677 * kRpm);
  EXPECT_FALSE(d.has(Signal::kPMo));
  // "Status" is dropped silently; "Temp" gets a note.
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0], "mem.csv:1:45: note: column 'Temp' is not a known signal; ignored");
  // A map entry that matches no column is an error naming the columns there are.
  opt.column_map["unused"] = "p_mo";
  const auto bad = read("ZEIT[s];Druck_A[bar];Drehzahl[U/min];Status;Temp[C]\n0;33;1677;ok;40\n", opt);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error->to_string(), "mem.csv:1:1: error: column map entry 'unused' matches no column; the columns are "
                                    "'ZEIT', 'Druck_A', 'Drehzahl', 'Status', 'Temp'");
}

TEST(LogReader, MappingOverridesCanonicalNames) {
  hh::ReadOptions opt;
  opt.column_map = {{"p_mi", "p_mo"}, {"p_mo", "p_mi"}};
  const auto d = read("t,p_mi,p_mo\n0,1,2\n", opt);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(port_pressures(d, 0), std::make_pair(2.0, 1.0));  // swapped
}

TEST(LogReader, ExtraColumnsAreIgnoredWithANote) {
  // Ignored columns are not parsed, so text in them is fine.
  const auto d = read("t,temp[degC],p_mi,comment\n0,40.5,1,start\n1,abc,2,\n");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 2.0);
  ASSERT_EQ(d.notes.size(), 2u);
  EXPECT_EQ(d.notes[0], "mem.csv:1:3: note: column 'temp' is not a known signal; ignored");
  EXPECT_EQ(d.notes[1], "mem.csv:1:19: note: column 'comment' is not a known signal; ignored");
}

TEST(LogReader, MissingInputAndSensorColumnsAreAllowed) {
  const auto d = read("t,w_m\n0,100\n0.001,101\n");
  EXPECT_LOG_OK(d);
  for (Signal s : {Signal::kPSup, Signal::kPS, Signal::kPBp, Signal::kKp, Signal::kPMi, Signal::kPMo, Signal::kPPp,
                   Signal::kPPump, Signal::kADcv, Signal::kAPrv}) {
    EXPECT_FALSE(d.has(s));
    EXPECT_TRUE(d.column(s).empty());
  }
  EXPECT_TRUE(d.has(Signal::kT));
  EXPECT_TRUE(d.has(Signal::kWm));
}

TEST(LogReader, PaperRigColumns) {
  const auto d = read("t,p_pump[bar],a_dcv[mm2],a_prv[m2],p_mi[bar]\n0,50,5,3.525e-6,40\n");
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPPump)[0], 50e5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kADcv)[0], 5e-6);
  EXPECT_EQ(d.column(Signal::kAPrv)[0], 3.525e-6);
}

TEST(LogReader, UnicodeHeaderIsFine) {
  // Multi-byte characters count as one column each in notes.
  const auto d = read("t,Öltemp[°C],p_mi\n0,40,1\n");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0], "mem.csv:1:3: note: column 'Öltemp' is not a known signal; ignored");
}

TEST(LogReader, TextNeedNotBeNulTerminated) {
  const std::string buffer = "t,p_mi\n0,1\n1,25999";
  const std::string_view view(buffer.data(), buffer.size() - 3);  // ends in "...1,25"
  const auto d = hh::read_log_from_memory(view, "view", {});
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 25.0);
}

TEST(LogReader, FastRowsEqualTheGeneralPath) {
  // Plain rows take the fast path; a blank before every field sends each row through the
  // general one. Both must store the same bits, equal to std::from_chars.
  std::mt19937_64 rng(5u);
  const auto number = [&rng]() {
    std::string s = (rng() % 4 == 0) ? "-" : "";
    s += std::to_string(rng() % 100000);
    if (rng() % 4 != 0) s += "." + std::to_string(rng() % 100000000);
    if (rng() % 5 == 0) s += "e" + std::to_string(static_cast<int>(rng() % 30) - 15);
    if (rng() % 50 == 0) s = std::to_string(rng());  // too long for the fast path
    return s;
  };
  std::vector<std::vector<std::string>> rows;
  for (int k = 0; k < 3000; ++k) {
    rows.push_back({std::to_string(k) + "." + std::to_string(rng() % 1000), number(), "note " + std::to_string(k),
                    number(), number()});
  }
  for (const char* eol : {"\n", "\r\n"}) {
    // plain; a blank before every field; blanks in the first half only (the reader
    // stops trying the fast path after a few misses and must pick it up again).
    std::string plain = std::string("t[s],p_mi[bar],comment,kp,w_m[rpm]") + eol;
    std::string blanks = plain;
    std::string mixed = plain;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      for (std::size_t c = 0; c < rows[k].size(); ++c) {
        plain += (c ? "," : "") + rows[k][c];
        blanks += (c ? ", " : " ") + rows[k][c];
        mixed += (k < rows.size() / 2 ? (c ? ", " : " ") : (c ? "," : "")) + rows[k][c];
      }
      plain += eol;
      blanks += eol;
      mixed += eol;
      if (k % 100 == 7) plain += std::string("# comment") + eol;
    }
    const auto a = read(plain);
    EXPECT_LOG_OK(a);
    ASSERT_EQ(a.rows(), rows.size());
    for (const std::string* other : {&blanks, &mixed}) {
      const auto b = read(*other);
      EXPECT_LOG_OK(b);
      ASSERT_EQ(b.rows(), rows.size());
      for (Signal s : {Signal::kT, Signal::kPMi, Signal::kKp, Signal::kWm}) {
        ASSERT_EQ(std::memcmp(a.column(s).data(), b.column(s).data(), rows.size() * sizeof(double)), 0);
      }
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      double kp = 0.0;
      std::from_chars(rows[k][3].data(), rows[k][3].data() + rows[k][3].size(), kp);
      ASSERT_EQ(std::memcmp(&a.column(Signal::kKp)[k], &kp, sizeof kp), 0) << rows[k][3];
    }
  }
}

TEST(LogReader, IgnoredColumnsAreCheckedForBinaryJunkInEveryRow) {
  using namespace std::string_literals;
  const auto ok = read("t,comment,p_mi\n0,ok,1\n1,\xC3\x96l,2\n2,ok,3\n");
  EXPECT_LOG_OK(ok);
  EXPECT_EQ(ok.rows(), 3u);
  const auto bad = read("t,comment,p_mi\n0,ok,1\n1,ok,2\n2,a\xff,3\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error->to_string(), "mem.csv:4:4: error: invalid UTF-8 byte 0xFF (binary data, or text not in UTF-8)");
  const auto nul = read("t,comment,p_mi\n0,ok,1\n1,ok,2\n2,a\0b,3\n"s);
  ASSERT_FALSE(nul.ok());
  EXPECT_EQ(nul.error->to_string(), "mem.csv:4:4: error: NUL byte (binary data, not a text log)");
}

TEST(LogReader, ReadsFromDisk) {
  const std::string path = ::testing::TempDir() + "hstmon_host_read_test.csv";
  {
    std::ofstream f(path, std::ios::binary);
    f << "t[s];p_mi[bar]\r\n0;1,5\r\n1;2,5\r\n";
  }
  const auto d = hh::read_log(path);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.path, path);
  ASSERT_EQ(d.rows(), 2u);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 2.5e5);
  std::remove(path.c_str());
}

TEST(LogReader, MissingFileIsAnErrorWithoutPosition) {
  const auto d = hh::read_log("/nonexistent/dir/log.csv");
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->line, 0u);
  EXPECT_EQ(d.error->to_string(), "/nonexistent/dir/log.csv: error: cannot open: No such file or directory");
  const auto dir = hh::read_log("/");
  ASSERT_FALSE(dir.ok());
  EXPECT_EQ(dir.error->line, 0u);
}
