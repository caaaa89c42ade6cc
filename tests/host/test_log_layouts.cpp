// Instrument exports as the instruments write them (issue 16): an HBM Spider8 export
// (units row above the names, "CH=n" names, time rounded to 1 ms at 4800 Hz) and a
// HYDAC HMG-style export (metadata block above the header); the options that load them
// (column map by number or by a name holding '=', sample rate); a lenient read that
// would drop most of a file; and messages that stay short on wide files.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "../support/instrument_exports.hpp"
#include "../support/mem_log.hpp"
#include "hstmon_host/log_options.hpp"
#include "hstmon_host/log_reader.hpp"

namespace hh = hstmon::host;
using hh::Signal;

namespace {

using hstmon_test::kRpm;
using hstmon_test::read;

hh::ReadOptions spider8_options() {
  hh::ReadOptions o;
  EXPECT_EQ(hh::set_rate(o, 4800.0), "");
  for (const char* m : {"#1=t", "n CH=2=w_m", "p1 CH=4=p_mi", "p2 CH=5=p_mo", "p CH=8=p_pp"}) {
    EXPECT_EQ(hh::add_column_map(o, m), "") << m;
  }
  return o;
}

#define EXPECT_LOG_OK(d) ASSERT_TRUE((d).ok()) << (d).error->to_string()

}  // namespace

// The file as the Spider8 writes it. Most of its timestamps repeat: the 1 ms clock
// ticks once per 4.8 samples.
TEST(InstrumentExports, Spider8TimeColumnRepeatsMostTimestamps) {
  const std::string text = hstmon_test::spider8_export();
  std::size_t repeats = 0;
  for (std::size_t i = 1; i < 3000; ++i) {
    repeats += std::round(1000.0 * static_cast<double>(i) / 4800.0) ==
               std::round(1000.0 * static_cast<double>(i - 1) / 4800.0);
  }
  EXPECT_GT(repeats, 2000u);
  EXPECT_NE(text.find("\r\n"), std::string::npos);
  EXPECT_EQ(text.find('.'), std::string::npos) << "decimal commas only";
}

// One command: --rate 4800 plus --map for the CH=n names (by name with its own '=', and
// the time column by number).
TEST(InstrumentExports, Spider8LoadsWithRateAndMap) {
  const auto d = read(hstmon_test::spider8_export(), spider8_options());
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 3000u);
  EXPECT_EQ(d.header_line, 2u) << "the names are on line 2, under the units";
  for (std::size_t i = 0; i < d.rows(); ++i) ASSERT_EQ(d.t[i], static_cast<double>(i) / 4800.0) << i;
  const hstmon_test::RigRow r0 = hstmon_test::rig_row(0), r2999 = hstmon_test::rig_row(2999);
  EXPECT_NEAR(d.column(Signal::kWm)[0], r0.w_m * kRpm, 1e-2 * kRpm);
  EXPECT_NEAR(d.column(Signal::kPMi)[0], r0.p_mi * 1e5, 1.0);
  EXPECT_NEAR(d.column(Signal::kPMo)[2999], r2999.p_mo * 1e5, 1.0);
  EXPECT_NEAR(d.column(Signal::kPPp)[2999], r2999.p_pp * 1e5, 50.0);  // written to 1 mbar
  EXPECT_EQ(d.source_units[hh::index(Signal::kPPp)], "bar");
  EXPECT_EQ(d.source_units[hh::index(Signal::kWm)], "1/min");
  EXPECT_EQ(d.source_columns[hh::index(Signal::kPPp)], 8u);
  // The three channels left in volts are noted and ignored; the rate agrees with the
  // logged time span, so no note about it.
  ASSERT_EQ(d.notes.size(), 3u);
  EXPECT_EQ(d.notes[0], "mem.csv:2:29: note: column 'T CH=3' is not a known signal; ignored");
  for (const auto& n : d.notes) EXPECT_EQ(n.find("sample rate"), std::string::npos) << n;
}

// Without --rate: no misleading "duplicate column name 'V'" (the units row is found
// above the names), and the time error names --rate as the fix.
TEST(InstrumentExports, Spider8WithoutRateNamesTheFix) {
  hh::ReadOptions o = spider8_options();
  o.rate = 0.0;
  const std::string text = hstmon_test::spider8_export();
  const auto d = read(text, o);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error->line, 4u) << d.error->to_string();  // the second sample: 0 ms again
  EXPECT_EQ(d.error->column, 1u);
  EXPECT_NE(d.error->message.find("--rate HZ"), std::string::npos) << d.error->message;
  EXPECT_EQ(d.error->message.find("duplicate"), std::string::npos) << d.error->message;
  EXPECT_LT(d.error->to_string().size(), 300u);
  // Lenient: 2374 of 3000 rows would go; it refuses and says why.
  o.lenient = true;
  const auto l = read(text, o);
  ASSERT_FALSE(l.ok());
  EXPECT_EQ(l.rows(), 0u);
  EXPECT_NE(l.error->message.find("of 3000 rows"), std::string::npos) << l.error->message;
  EXPECT_NE(l.error->message.find("--rate HZ"), std::string::npos) << l.error->message;
  EXPECT_TRUE(l.notes.size() <= 3u) << "no list of skipped rows";
  // No map at all: the names are still read as names (no time column: the message
  // names --map and --rate).
  const auto bare = read(text);
  ASSERT_FALSE(bare.ok());
  EXPECT_EQ(bare.error->line, 2u);
  EXPECT_NE(bare.error->message.find("no time column"), std::string::npos) << bare.error->message;
  EXPECT_NE(bare.error->message.find("--rate"), std::string::npos) << bare.error->message;
}

// With the sample rate alone and no column giving t, time starts at 0.
TEST(InstrumentExports, Spider8WithRateOnly) {
  hh::ReadOptions o;
  o.rate = 4800.0;
  const auto d = read(hstmon_test::spider8_export(), o);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.rows(), 3000u);
  EXPECT_TRUE(d.has(Signal::kT));
  EXPECT_EQ(d.t[0], 0.0);
  EXPECT_EQ(d.t[4800 / 2], 0.5);
  EXPECT_EQ(d.notes.size(), 8u) << "eight unknown columns, one note each";
}

TEST(InstrumentExports, HmgExportWithMetadataBlock) {
  hh::ReadOptions o;
  for (const char* m : {"Time=t", "P1=p_mi", "P2=p_mo", "P3=p_pp", "n=w_m"}) ASSERT_EQ(hh::add_column_map(o, m), "");
  for (const bool units_below : {false, true}) {
    const auto d = read(hstmon_test::hmg_export(200, units_below), o);
    EXPECT_LOG_OK(d);
    EXPECT_EQ(d.header_line, 8u);
    ASSERT_EQ(d.rows(), 200u);
    EXPECT_EQ(d.t[1], 0.001);
    EXPECT_NEAR(d.column(Signal::kPPp)[0], hstmon_test::rig_row(0).p_pp * 1e5, 1e3);
    EXPECT_NEAR(d.column(Signal::kWm)[199], hstmon_test::rig_row(199).w_m * kRpm, 0.1 * kRpm);
    EXPECT_EQ(d.source_units[hh::index(Signal::kPMi)], "bar");
    ASSERT_EQ(d.notes.size(), 1u);
    EXPECT_EQ(d.notes[0], "mem.csv:1:1: note: lines 1-6 above the column names taken as metadata, not columns");
  }
}

// A units row above the names with canonical names, in a comma file.
TEST(InstrumentExports, UnitsRowAboveCanonicalNames) {
  const auto d = read("s,bar,rpm\nt,p_mi,w_m\n0,1,60\n0.5,2,120\n");
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPMi)[1], 2e5);
  EXPECT_NEAR(d.column(Signal::kWm)[1], 120 * kRpm, 1e-12);
  // The usual order still reads as before.
  const auto usual = read("t,p_mi,w_m\ns,bar,rpm\n0,1,60\n0.5,2,120\n");
  EXPECT_LOG_OK(usual);
  EXPECT_EQ(usual.column(Signal::kPMi)[1], 2e5);
}

TEST(LogOptions, ColumnMapSplitsAtTheLastEquals) {
  hh::ReadOptions o;
  EXPECT_EQ(hh::add_column_map(o, "p CH=8=p_pp"), "");
  EXPECT_EQ(o.column_map.at("p CH=8"), "p_pp");
  EXPECT_EQ(hh::add_column_map(o, "#8=p_pp"), "");
  EXPECT_EQ(o.column_number_map.at(8), "p_pp");
  for (const char* bad : {"p_pp", "=p_pp", "x=", "#0=t", "#=t", "#x=t", "#8a=t", "#-1=t"}) {
    EXPECT_NE(hh::add_column_map(o, bad), "") << bad;
  }
  EXPECT_LT(hh::add_column_map(o, std::string(5000, 'x')).size(), 200u) << "a long entry is not echoed whole";
}

// A name is matched ignoring case and the width of blank runs: one typed space finds
// the Spider8's two.
TEST(LogOptions, MapNameIgnoresBlankWidth) {
  hh::ReadOptions o;
  ASSERT_EQ(hh::add_column_map(o, "time spider8_1 ch=1=t"), "");
  o.rate = 4800.0;
  const auto d = read(hstmon_test::spider8_export(10), o);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.source_columns[hh::index(Signal::kT)], 1u);
  EXPECT_EQ(d.notes.size(), 7u) << "the other seven columns";
  o.column_map = {{"time spider8_1 ch=", "t"}};
  const auto partial = read(hstmon_test::spider8_export(10), o);
  EXPECT_EQ(partial.source_columns[hh::index(Signal::kT)], 0u) << "no prefix match";
}

TEST(LogOptions, ColumnNumberWinsAndMustExist) {
  hh::ReadOptions o;
  o.column_number_map = {{2, "p_mo"}};
  o.column_map = {{"A", "p_mi"}};
  const auto d = read("t;A;B\n0;1;2\n1;3;4\n", o);
  EXPECT_LOG_OK(d);
  EXPECT_EQ(d.column(Signal::kPMo)[1], 3.0) << "#2 is column A";
  EXPECT_FALSE(d.has(Signal::kPMi));
  o.column_number_map = {{4, "p_mo"}};
  const auto e = read("t;A;B\n0;1;2\n", o);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error->message.find("'#4' names column 4, the header has 3"), std::string::npos) << e.error->message;
}

TEST(LogOptions, SeparatorAndRate) {
  hh::ReadOptions o;
  EXPECT_EQ(hh::set_separator(o, "tab"), "");
  EXPECT_EQ(o.separator, '\t');
  EXPECT_EQ(hh::set_separator(o, ";"), "");
  EXPECT_EQ(o.separator, ';');
  EXPECT_NE(hh::set_separator(o, "|"), "");
  EXPECT_NE(hh::set_rate(o, 0.0), "");
  EXPECT_NE(hh::set_rate(o, -4800.0), "");
  EXPECT_NE(hh::set_rate(o, NAN), "");
  EXPECT_EQ(hh::set_rate(o, 4800.0), "");
  o = {};
  o.rate = -1.0;
  const auto bad = read("t,p_mi\n0,1\n", o);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error->line, 0u);
}

TEST(LogRate, TimeFromTheRowIndexStartsAtTheLoggedTime) {
  hh::ReadOptions o;
  o.rate = 10.0;
  const auto d = read("t,p_mi\n5,1\n5,2\n5.1,3\n5.2,4\n", o);
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.rows(), 4u);
  EXPECT_EQ(d.t[0], 5.0);
  EXPECT_EQ(d.t[3], 5.0 + 3.0 / 10.0);
  EXPECT_TRUE(d.notes.empty()) << d.notes[0];
  // A rate that does not fit the logged span is noted (and used).
  o.rate = 100.0;
  const auto off = read("t,p_mi\n0,1\n1,1\n2,1\n", o);
  EXPECT_LOG_OK(off);
  EXPECT_EQ(off.t[2], 0.02);
  ASSERT_EQ(off.notes.size(), 1u);
  EXPECT_NE(off.notes[0].find("is the sample rate right?"), std::string::npos) << off.notes[0];
  // No time column: from 0.
  o.rate = 2.0;
  const auto none = read("p_mi\n1\n2\n", o);
  EXPECT_LOG_OK(none);
  EXPECT_EQ(none.t, (std::vector<double>{0.0, 0.5}));
  // A start time so large that steps of 1/rate vanish is an error, not equal times.
  o.rate = 1000.0;
  const auto huge = read("t,p_mi\n1e20,1\n1e20,2\n", o);
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error->message.find("too large for steps"), std::string::npos) << huge.error->message;
  EXPECT_EQ(huge.rows(), 0u);
  // A lenient read with a rate keeps the rows before a bad one, timed by the rate.
  o.rate = 2.0;
  o.lenient = true;
  const auto part = read("p_mi\n1\n2\nx\n", o);
  ASSERT_FALSE(part.ok());
  EXPECT_EQ(part.t, (std::vector<double>{0.0, 0.5}));
}

// No message fills a screen: a 5000-column export gives nine notes, each one line.
TEST(LogMessages, WideExportGivesFewShortNotes) {
  std::string header = "t";
  std::string row = "0";
  for (int k = 0; k < 5000; ++k) {
    header += ",channel_" + std::to_string(k) + "_with_a_long_descriptive_name";
    row += ",1";
  }
  const auto d = read(header + "\n" + row + "\n");
  EXPECT_LOG_OK(d);
  ASSERT_EQ(d.notes.size(), 9u);
  for (const auto& n : d.notes) EXPECT_LT(n.size(), 200u) << n;
  EXPECT_NE(d.notes[8].find("5000 columns in all"), std::string::npos) << d.notes[8];
  // A field that swallowed a whole line (wrong separator) is quoted to 40 bytes.
  const auto e = read(header + "\n" + std::string(80000, '7') + "x\n");
  ASSERT_FALSE(e.ok());
  EXPECT_LT(e.error->to_string().size(), 300u);
}

// A units row with no names row next to it is still refused, but the message says what
// the line looks like instead of only "duplicate column name 'V'".
TEST(InstrumentExports, UnitsRowWithoutNamesSaysSo) {
  const auto d = read("s\tV\tV\tbar\r\n0\t1\t2\t3\r\n");
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error->message.find("duplicate column name 'V'"), std::string::npos) << d.error->message;
  EXPECT_NE(d.error->message.find("reads as a units row"), std::string::npos) << d.error->message;
}
