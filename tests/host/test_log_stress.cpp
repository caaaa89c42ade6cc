// Robustness: thousands of random mutations of valid logs and parameter files never
// crash and always give either a consistent result or a positioned error
// (HSTMON_FUZZ_ITERATIONS per base text, default 4000; worth raising under ASan). Parse rate:
// times read_log_from_memory on a generated log (HSTMON_PARSE_ROWS rows, default 1e5;
// use 3600000 in a Release build for a one-hour 1 kHz log).
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "../support/instrument_exports.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_writer.hpp"
#include "hstmon_host/params_file.hpp"

namespace hh = hstmon::host;
using hh::Signal;

namespace {

const char kPalette[] = {',', ';', '\t', '\n', '\r', '\0', '\xff', '\xc3', '\x80', '.', '-', 'e', 'E', '+', 'n',
                         'a', 'i', 'f', '#', ' ', '[', ']', '(', ')', '"', '0', '1', '9', 'x', '{', '}', ':'};

std::string mutate(std::string s, std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 9);
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < edits && !s.empty(); ++k) {
    const std::size_t pos = rng() % s.size();
    const char c = (rng() % 4 == 0) ? static_cast<char>(rng() & 0xFF) : kPalette[rng() % sizeof kPalette];
    switch (kind(rng)) {
      case 0: s.erase(pos, 1 + rng() % 3); break;
      case 1: s.insert(pos, 1, c); break;
      case 2: s.resize(pos); break;
      case 3: s.insert(pos, s.substr(rng() % s.size(), 1 + rng() % 20)); break;
      default: s[pos] = c; break;
    }
  }
  return s;
}

std::size_t count_lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')) + 1; }

void check_log_result(const hh::LogData& d, const std::string& text, bool lenient) {
  if (!d.ok()) {
    ASSERT_GE(d.error->line, 1u) << d.error->to_string();
    ASSERT_LE(d.error->line, count_lines(text) + 1) << d.error->to_string();
    ASSERT_GE(d.error->column, 1u) << d.error->to_string();
    ASSERT_FALSE(d.error->message.empty());
    if (!lenient) {
      ASSERT_EQ(d.rows(), 0u);
    }
  } else {
    ASSERT_GE(d.rows(), 1u);
    ASSERT_TRUE(d.has(Signal::kT));
  }
  for (std::size_t k = 1; k < hh::kSignalCount; ++k) {
    if (d.present[k]) {
      ASSERT_EQ(d.values[k].size(), d.rows());
    } else {
      ASSERT_TRUE(d.values[k].empty());
    }
    for (double v : d.values[k]) ASSERT_TRUE(std::isfinite(v));
  }
  for (std::size_t i = 1; i < d.rows(); ++i) ASSERT_LT(d.t[i - 1], d.t[i]);
}

std::size_t env_count(const char* name, std::size_t fallback) {
  const char* s = std::getenv(name);
  if (s == nullptr) return fallback;
  const long n = std::atol(s);
  return n > 0 ? static_cast<std::size_t>(n) : fallback;
}

}  // namespace

TEST(LogStress, RandomMutationsNeverCrash) {
  const std::string bases[] = {
      "t[s],p_sup[bar],kp,p_mi[bar],p_mo[bar],p_pp[bar],w_m[rpm]\n"
      "0,35,4.41e-8,33.1,1.88,171.1,1677\n0.001,35,4.41e-8,33.2,1.89,171.2,1678\n"
      "0.002,35,4.41e-8,33.3,1.90,171.3,1679\n0.003,35,4.41e-8,33.4,1.91,171.4,1680\n",
      "\xEF\xBB\xBF# catman\r\nt\tp_mi\tp_mo\tComment\tw_m\r\ns\tbar\tbar\t\t1/min\r\n"
      "0\t33,12\t1,879\tok\t1677,7\r\n0,001\t33,13\t1,880\tok\t1677,9\r\n0,002\t33,14\t1,881\t\t1678,1\r\n",
      "t;p_pump[MPa];a_dcv[mm2];a_prv[mm2]\n0;5,1;5;3,5\n1;5,2;5;3,5\n2;5,3;5;3,5\n",
  };
  std::mt19937 rng(20240601u);
  hh::ReadOptions strict;
  hh::ReadOptions lenient;
  lenient.lenient = true;
  lenient.column_map = {{"Comment", ""}};
  int errors = 0;
  const std::size_t iterations = env_count("HSTMON_FUZZ_ITERATIONS", 4000);
  for (const std::string& base : bases) {
    for (std::size_t i = 0; i < iterations; ++i) {
      const std::string text = mutate(base, rng);
      const auto a = hh::read_log_from_memory(text, "fuzz", strict);
      check_log_result(a, text, false);
      const auto b = hh::read_log_from_memory(text, "fuzz", lenient);
      check_log_result(b, text, true);
      if (!a.ok()) ++errors;
      if (HasFatalFailure()) {
        ADD_FAILURE() << "input: " << testing::PrintToString(text);
        return;
      }
    }
  }
  EXPECT_GT(errors, 1000);  // the mutations do break most files
}

// Issue 16's layouts (units row above the names, a metadata block) mutated: the layout
// detection and the sample-rate time keep the reader's guarantees.
TEST(LogStress, RandomMutationsOfInstrumentExportsNeverCrash) {
  const std::string bases[] = {hstmon_test::spider8_export(12), hstmon_test::hmg_export(8),
                               hstmon_test::hmg_export(8, true)};
  std::mt19937 rng(16u);
  hh::ReadOptions rate;
  rate.rate = 4800.0;
  rate.column_map = {{"n CH=2", "w_m"}, {"P1", "p_mi"}, {"Time", "t"}};
  rate.column_number_map = {{8, "p_pp"}};
  hh::ReadOptions lenient;
  lenient.lenient = true;
  lenient.column_number_map = {{1, "t"}};
  const std::size_t iterations = env_count("HSTMON_FUZZ_ITERATIONS", 4000) / 2;
  for (const std::string& base : bases) {
    for (std::size_t i = 0; i < iterations; ++i) {
      const std::string text = mutate(base, rng);
      check_log_result(hh::read_log_from_memory(text, "fuzz", rate), text, false);
      check_log_result(hh::read_log_from_memory(text, "fuzz", lenient), text, true);
      if (HasFatalFailure()) {
        ADD_FAILURE() << "input: " << testing::PrintToString(text);
        return;
      }
    }
  }
}

TEST(LogStress, RandomMutationsOfParamsNeverCrash) {
  const std::string base = hh::format_params_json({}, {}, "fuzz base");
  std::mt19937 rng(7u);
  const std::size_t iterations = env_count("HSTMON_FUZZ_ITERATIONS", 4000);
  for (std::size_t i = 0; i < iterations; ++i) {
    const std::string text = mutate(base, rng);
    const auto r = hh::parse_params_json(text, "fuzz.json");
    if (r.ok()) {
      ASSERT_TRUE(r.params.has_value());
      ASSERT_TRUE(r.inputs.has_value());
    } else {
      ASSERT_GE(r.error->line, 1u) << r.error->to_string();
      ASSERT_LE(r.error->line, count_lines(text) + 1) << r.error->to_string();
      ASSERT_GE(r.error->column, 1u) << r.error->to_string();
      ASSERT_FALSE(r.params.has_value());
    }
  }
}

TEST(LogStress, DecimalsMatchFromCharsBitForBit) {
  // The reader's fast path for plain decimals must give exactly what std::from_chars gives.
  std::mt19937_64 rng(99u);
  std::vector<std::string> numbers;
  std::string text = "t,p_mi\n";
  for (int i = 0; i < 200000; ++i) {
    std::string num;
    if (rng() % 3 == 0) num += '-';
    const int int_digits = static_cast<int>(rng() % 12);
    const int frac_digits = static_cast<int>(rng() % 14);
    for (int k = 0; k < int_digits; ++k) num += static_cast<char>('0' + rng() % 10);
    if (frac_digits > 0 || int_digits == 0) {
      num += '.';
      for (int k = 0; k < std::max(frac_digits, int_digits == 0 ? 1 : 0); ++k) num += static_cast<char>('0' + rng() % 10);
    }
    if (rng() % 8 == 0) num += "e" + std::to_string(static_cast<int>(rng() % 40) - 20);
    if (rng() % 50 == 0) num = std::to_string(rng());  // 20-digit integers
    numbers.push_back(num);
    text += std::to_string(i) + "," + num + "\n";
  }
  // The same numbers with decimal commas in a semicolon file (the copy-to-buffer path).
  std::string comma_text = text;
  std::replace(comma_text.begin(), comma_text.end(), ',', ';');
  std::replace(comma_text.begin(), comma_text.end(), '.', ',');
  for (const std::string* t : {&text, &comma_text}) {
    const auto d = hh::read_log_from_memory(*t, "decimals", {});
    ASSERT_TRUE(d.ok()) << d.error->to_string();
    ASSERT_EQ(d.rows(), numbers.size());
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      double expect = 0.0;
      const std::string& n = numbers[i];
      const auto r = std::from_chars(n.data(), n.data() + n.size(), expect);
      ASSERT_EQ(r.ptr, n.data() + n.size()) << n;
      const double got = d.column(Signal::kPMi)[i];
      ASSERT_EQ(std::memcmp(&got, &expect, sizeof got), 0) << n << ": " << got << " vs " << expect;
    }
  }
}

namespace {

/// Parses `text` (best of 5), checks it, and prints the rate.
void time_parse(const std::string& text, std::size_t n, const char* label) {
  // CPU time (std::clock) as well as wall time, since the machine may be shared.
  double best = 1e30;
  double best_cpu = 1e30;
  hh::LogData d;
  for (int rep = 0; rep < 5; ++rep) {
    d = hh::LogData{};
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    d = hh::read_log_from_memory(text, "generated", {});
    const auto t1 = std::chrono::steady_clock::now();
    const std::clock_t c1 = std::clock();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
    best_cpu = std::min(best_cpu, static_cast<double>(c1 - c0) / CLOCKS_PER_SEC);
  }
  ASSERT_TRUE(d.ok()) << d.error->to_string();
  ASSERT_EQ(d.rows(), n);
  EXPECT_NEAR(d.column(Signal::kPMi)[n / 2], 3.312079e6, 5000.0);
  EXPECT_EQ(d.column(Signal::kKp)[n - 1], 4.41e-8);
  const double rate = static_cast<double>(n) / best;
  const double mb = static_cast<double>(text.size()) / 1e6;
  std::cout << "[ parse rate ] " << label << ": " << n << " rows, " << mb << " MB in " << best * 1e3
            << " ms wall (" << best_cpu * 1e3 << " ms CPU): " << rate / 1e6 << " M rows/s wall, "
            << static_cast<double>(n) / best_cpu / 1e6 << " M rows/s CPU, " << mb / best << " MB/s\n";
  ::testing::Test::RecordProperty(std::string("rows_per_second_") + label,
                                  std::to_string(static_cast<long long>(rate)));
}

}  // namespace

TEST(LogStress, ParseRate) {
  const std::size_t n = env_count("HSTMON_PARSE_ROWS", 100000);
  // One-hour-style rig log: 7 columns, sensor-like resolution (pressures 0.1 mbar, speed
  // 0.1 rpm), so about 50 bytes per row as a logger writes them. Written twice: as CSV,
  // and catman-style (tab, decimal comma).
  hh::WriteOptions catman;
  catman.separator = '\t';
  catman.decimal_comma = true;
  hh::CsvWriter w;
  hh::CsvWriter wc;
  ASSERT_FALSE(wc.open_memory({hh::column_for(Signal::kT, "s"), hh::column_for(Signal::kPSup, "bar"),
                               hh::column_for(Signal::kKp), hh::column_for(Signal::kPMi, "bar"),
                               hh::column_for(Signal::kPMo, "bar"), hh::column_for(Signal::kPPp, "bar"),
                               hh::column_for(Signal::kWm, "rpm")},
                              catman));
  ASSERT_FALSE(w.open_memory({hh::column_for(Signal::kT, "s"), hh::column_for(Signal::kPSup, "bar"),
                              hh::column_for(Signal::kKp), hh::column_for(Signal::kPMi, "bar"),
                              hh::column_for(Signal::kPMo, "bar"), hh::column_for(Signal::kPPp, "bar"),
                              hh::column_for(Signal::kWm, "rpm")}));
  std::mt19937 rng(1u);
  std::normal_distribution<double> noise(0.0, 1.0);
  const auto q = [](double v, double step) { return std::round(v / step) * step; };
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * 1e-3;
    const double row[] = {t, 3.5e6, 4.41e-8, q(3.312079e6 + 300.0 * noise(rng), 10.0),
                          q(1.879209e5 + 100.0 * noise(rng), 10.0), q(1.710822e7 + 1000.0 * noise(rng), 10.0),
                          q(175.6867 + 0.05 * noise(rng), 0.0104719755)};
    ASSERT_TRUE(w.write_row(row, 7));
    ASSERT_TRUE(wc.write_row(row, 7));
  }
  w.close();
  wc.close();
  time_parse(w.str(), n, "csv");
  time_parse(wc.str(), n, "tab_decimal_comma");
}
