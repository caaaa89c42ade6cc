// CSV writer: header with units, "%.9g" numbers, separators, decimal comma, round trip
// through the reader, refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_writer.hpp"

namespace hh = hstmon::host;
using hh::Quantity;
using hh::Signal;

TEST(LogWriter, HeaderUnitsAndPrecision) {
  hh::CsvWriter w;
  ASSERT_FALSE(w.open_memory({hh::column_for(Signal::kT, "s"), hh::column_for(Signal::kPMi, "bar"),
                              hh::column_for(Signal::kWm, "rpm"), {"r_p_mi", Quantity::kPressure, ""}}));
  ASSERT_TRUE(w.write_row({0.0, 3.3e6, 2.0 * 3.14159265358979323846, -1.5}));
  ASSERT_TRUE(w.write_row({0.001, 3312079.123456789, 0.0, 123456789012.0}));
  EXPECT_EQ(w.rows_written(), 2u);
  EXPECT_FALSE(w.close());
  EXPECT_EQ(w.str(),
            "t[s],p_mi[bar],w_m[rpm],r_p_mi\n"
            "0,33,60,-1.5\n"
            "0.001,33.1207912,0,1.23456789e+11\n");
}

TEST(LogWriter, CommentsSemicolonAndDecimalComma) {
  hh::WriteOptions opt;
  opt.separator = ';';
  opt.decimal_comma = true;
  opt.comments = {"scenario: step", "seed 1"};
  hh::CsvWriter w;
  ASSERT_FALSE(w.open_memory({hh::column_for(Signal::kT), hh::column_for(Signal::kPPp, "MPa")}, opt));
  ASSERT_TRUE(w.write_row({0.5, 1.7108e7}));
  w.close();
  EXPECT_EQ(w.str(), "# scenario: step\n# seed 1\nt;p_pp[MPa]\n0,5;17,108\n");
  const auto d = hh::read_log_from_memory(w.str(), "w", {});
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.t[0], 0.5);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPPp)[0], 1.7108e7);
}

TEST(LogWriter, TabSeparatedShortestRoundTrip) {
  hh::WriteOptions opt;
  opt.separator = '\t';
  opt.precision = 0;
  hh::CsvWriter w;
  ASSERT_FALSE(w.open_memory({hh::column_for(Signal::kT), hh::column_for(Signal::kKp)}, opt));
  const double kp = 4.4100000000000003e-8;
  const double t = 0.1 + 0.2;
  ASSERT_TRUE(w.write_row({t, kp}));
  w.close();
  const auto d = hh::read_log_from_memory(w.str(), "w", {});
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.t[0], t);
  EXPECT_EQ(d.column(Signal::kKp)[0], kp);
}

TEST(LogWriter, Refusals) {
  hh::CsvWriter w;
  auto e = w.open_memory({hh::column_for(Signal::kPMi, "bars")});
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("unknown pressure unit 'bars' (use Pa"), std::string::npos) << e->message;
  EXPECT_FALSE(w.is_open());
  EXPECT_FALSE(w.write_row({1.0}));

  hh::WriteOptions opt;
  opt.decimal_comma = true;  // with ',' separator
  EXPECT_TRUE(w.open_memory({hh::column_for(Signal::kT)}, opt));
  opt = {};
  opt.separator = '|';
  EXPECT_TRUE(w.open_memory({hh::column_for(Signal::kT)}, opt));
  EXPECT_TRUE(w.open_memory({}));
  EXPECT_TRUE(w.open_memory({{"a,b", Quantity::kNone, ""}}));
  EXPECT_TRUE(w.open_memory({{"a[b]", Quantity::kNone, ""}}));

  ASSERT_FALSE(w.open_memory({hh::column_for(Signal::kT), hh::column_for(Signal::kPMi)}));
  EXPECT_FALSE(w.write_row({1.0}));
  ASSERT_TRUE(w.error());
  EXPECT_NE(w.error()->message.find("write_row got 1 values for 2 columns"), std::string::npos);
  const auto closed = w.close();
  ASSERT_TRUE(closed);
  EXPECT_EQ(w.str(), "t,p_mi\n");

  const auto bad_path = w.open("/nonexistent/dir/out.csv", {hh::column_for(Signal::kT)});
  ASSERT_TRUE(bad_path);
  EXPECT_EQ(bad_path->to_string(), "/nonexistent/dir/out.csv: error: cannot create: No such file or directory");
}

TEST(LogWriter, FileRoundTripThroughReader) {
  const std::string path = ::testing::TempDir() + "hstmon_host_writer_test.csv";
  hh::LogData log;
  const std::size_t n = 5000;  // several flush blocks are not needed; checks values
  for (std::size_t i = 0; i < n; ++i) {
    log.t.push_back(static_cast<double>(i) * 1e-3);
    log.values[hh::index(Signal::kPMi)].push_back(3.3e6 + 1234.5678 * std::sin(static_cast<double>(i)));
    log.values[hh::index(Signal::kWm)].push_back(175.6867 + std::cos(static_cast<double>(i)));
  }
  log.present[hh::index(Signal::kT)] = true;
  log.present[hh::index(Signal::kPMi)] = true;
  log.present[hh::index(Signal::kWm)] = true;
  const auto e = hh::write_log(path, log, {{Signal::kPMi, "bar"}, {Signal::kWm, "rpm"}});
  ASSERT_FALSE(e) << e->to_string();
  const auto d = hh::read_log(path);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  ASSERT_EQ(d.rows(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(d.t[i], log.t[i], 1e-12);
    EXPECT_NEAR(d.column(Signal::kPMi)[i], log.values[hh::index(Signal::kPMi)][i], 3.3e6 * 1e-8);
    EXPECT_NEAR(d.column(Signal::kWm)[i], log.values[hh::index(Signal::kWm)][i], 176 * 1e-8);
  }
  std::string text;
  ASSERT_FALSE(hh::write_log_to_string(text, d, {{Signal::kPMi, "bar"}, {Signal::kWm, "rpm"}}));
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  EXPECT_EQ(text, ss.str());  // read → write reproduces the file
  std::remove(path.c_str());
}

TEST(LogWriter, LargeOutputIsFlushedInBlocks) {
  const std::string path = ::testing::TempDir() + "hstmon_host_writer_big.csv";
  hh::CsvWriter w;
  ASSERT_FALSE(w.open(path, {hh::column_for(Signal::kT), hh::column_for(Signal::kPMi, "bar")}));
  const std::size_t n = 100000;  // ~2.5 MB: several 1 MiB blocks
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_TRUE(w.write_row({static_cast<double>(i) * 1e-3, 3.3e6 + static_cast<double>(i)}));
  }
  EXPECT_TRUE(w.str().size() < (std::size_t{1} << 21));  // buffer stays bounded
  ASSERT_FALSE(w.close());
  const auto d = hh::read_log(path);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.rows(), n);
  EXPECT_DOUBLE_EQ(d.column(Signal::kPMi).back(), 3.3e6 + static_cast<double>(n - 1));
  std::remove(path.c_str());
}

TEST(LogWriter, MismatchedColumnsAreRefused) {
  hh::LogData log;
  log.t = {0.0, 1.0};
  log.present[hh::index(Signal::kT)] = true;
  log.present[hh::index(Signal::kPMi)] = true;
  log.values[hh::index(Signal::kPMi)] = {1.0};
  std::string text;
  const auto e = hh::write_log_to_string(text, log);
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("column 'p_mi' has 1 values, time has 2"), std::string::npos);
}

TEST(LogWriter, MoveKeepsTheFileOpen) {
  const std::string path = ::testing::TempDir() + "hstmon_host_writer_move.csv";
  hh::CsvWriter a;
  ASSERT_FALSE(a.open(path, {hh::column_for(Signal::kT)}));
  hh::CsvWriter b(std::move(a));
  EXPECT_FALSE(a.is_open());
  ASSERT_TRUE(b.is_open());
  ASSERT_TRUE(b.write_row({1.0}));
  hh::CsvWriter c;
  c = std::move(b);
  ASSERT_TRUE(c.write_row({2.0}));
  ASSERT_FALSE(c.close());
  const auto d = hh::read_log(path);
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  EXPECT_EQ(d.rows(), 2u);
  std::remove(path.c_str());
}
