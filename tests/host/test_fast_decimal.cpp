// The log reader's fast number path (ports/host/src/fast_decimal.hpp) against
// std::from_chars: whatever it accepts must be exactly what from_chars gives — same value
// bit for bit, same end — over every short string of a number-ish alphabet and many
// random ones, at every distance from the end of the text (its 8- and 16-byte loads).
// And it must accept what loggers write, or the reader quietly gets slow again.
#include <gtest/gtest.h>

#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include "fast_decimal.hpp"

namespace {

using hstmon::host::detail::fast_decimal;

/// Checks one case: `text` parsed from the start of a buffer that holds `tail` after
/// it, first with the text's end as the end, then with the tail readable.
void check(const std::string& text, const std::string& tail, bool comma_point) {
  const std::string buffer = text + tail;
  std::string dotted = buffer;  // what from_chars sees: decimal commas as points
  if (comma_point) {
    for (char& c : dotted) {
      if (c == ',') c = '.';
    }
  }
  for (const std::size_t len : {text.size(), buffer.size()}) {
    double v = 0.0;
    const char* stop = nullptr;
    if (!fast_decimal(buffer.data(), buffer.data() + len, v, stop, comma_point)) continue;
    double expect = 0.0;
    const auto r = std::from_chars(dotted.data(), dotted.data() + len, expect);
    ASSERT_EQ(r.ec, std::errc()) << '"' << buffer.substr(0, len) << "\" comma " << comma_point;
    ASSERT_EQ(r.ptr - dotted.data(), stop - buffer.data())
        << '"' << buffer.substr(0, len) << "\" comma " << comma_point;
    ASSERT_EQ(std::memcmp(&v, &expect, sizeof v), 0)
        << '"' << buffer.substr(0, len) << "\": " << v << " vs " << expect;
  }
}

bool accepts(const std::string& s, bool comma_point = false, std::size_t* used = nullptr) {
  const std::string buffer = s + ",0.0,0.0,0.0\n";  // a row goes on after the field
  double v;
  const char* stop = nullptr;
  const bool ok = fast_decimal(buffer.data(), buffer.data() + buffer.size(), v, stop, comma_point);
  if (ok && used != nullptr) *used = static_cast<std::size_t>(stop - buffer.data());
  return ok;
}

}  // namespace

TEST(FastDecimal, EveryShortStringMatchesFromChars) {
  // All strings of up to 6 characters over 8 symbols (300 000 cases), each followed by
  // nothing, a separator, or more digits; the long tails make the 16-byte path run.
  const char alphabet[] = {'0', '1', '9', '.', ',', '-', '+', 'e'};
  std::string s;
  for (int len = 1; len <= 6; ++len) {
    std::vector<int> idx(static_cast<std::size_t>(len), 0);
    for (;;) {
      s.clear();
      for (int k : idx) s += alphabet[k];
      for (const char* tail : {"", ";", "5", ";;;;;;;;;;;;;;;;", "12345678901234567"}) {
        check(s, tail, false);
        check(s, tail, true);
        if (testing::Test::HasFatalFailure()) return;
      }
      std::size_t k = 0;
      while (k < idx.size() && ++idx[k] == static_cast<int>(sizeof alphabet)) idx[k++] = 0;
      if (k == idx.size()) break;
    }
  }
}

TEST(FastDecimal, RandomNumbersMatchFromChars) {
  std::mt19937_64 rng(20240611u);
  const auto digits = [&rng](int n) {
    std::string d;
    for (int k = 0; k < n; ++k) d += static_cast<char>('0' + rng() % 10);
    return d;
  };
  const char* tails[] = {"", ",", "\n", "12345678901234567890", ";1.5;2", " ", "e", "e+", ".5"};
  for (int i = 0; i < 400000; ++i) {
    std::string s;
    if (rng() % 3 == 0) s += '-';
    s += digits(static_cast<int>(rng() % 12));
    if (rng() % 4 != 0) s += (rng() % 5 == 0) ? ',' : '.';
    s += digits(static_cast<int>(rng() % 14));
    if (rng() % 3 == 0) {
      s += (rng() % 2) ? 'e' : 'E';
      if (rng() % 2) s += (rng() % 2) ? '-' : '+';
      s += digits(static_cast<int>(rng() % 6));
    }
    if (rng() % 40 == 0) s = std::to_string(rng());  // up to 20 digits
    const char* tail = tails[rng() % (sizeof tails / sizeof tails[0])];
    check(s, tail, false);
    check(s, tail, true);
    if (HasFatalFailure()) return;
  }
}

TEST(FastDecimal, ExactRangeEdges) {
  // 2^53 and its neighbours, the 10^±22 limits, and just beyond them.
  for (const char* s : {"9007199254740992", "9007199254740993", "9007199254740991", "900719925474099.3",
                        "1e22", "1e23", "1e-22", "1e-23", "9007199254740991e22", "9007199254740991e-22",
                        "0.0000000000000000000001", "0.00000000000000000000001", "1234567890123456789",
                        "12345678901234567890", "-0", "-0.0e5", "0e-400", "1e0000", "1e00000", "5.e3", ".5e-3"}) {
    check(s, "", false);
    check(s, ",1", true);
    if (HasFatalFailure()) return;
  }
}

TEST(FastDecimal, TakesWhatLoggersWrite) {
  // hstmon-sim (to_chars, general, 10 digits), the benchmark's log, catman exports.
  for (const char* s : {"0", "35", "4.41e-08", "33.18532082", "1.956206607", "171.1451896", "1678", "0.001",
                        "3599.999", "4.4100e-08", "33.12079", "-0.00042", "1677.69", "1.5E+3", "7.056e-08"}) {
    std::size_t used = 0;
    EXPECT_TRUE(accepts(s, false, &used)) << s;
    EXPECT_EQ(used, std::strlen(s)) << s;
  }
  std::size_t used = 0;
  EXPECT_TRUE(accepts("33,12", true, &used));
  EXPECT_EQ(used, 5u);
  EXPECT_TRUE(accepts("33,12", false, &used));  // ',' ends the number when it is the separator
  EXPECT_EQ(used, 2u);
}

TEST(FastDecimal, LeavesTheRestToFromChars) {
  for (const char* s : {"", "-", ".", "-.", "+1", "nan", "inf", "-Infinity", "e5", "1e", "1e+", "1e99999",
                        "1e400", "1e-400", "12345678901234567890", "0x1p3"}) {
    std::size_t used = 0;
    if (accepts(s, false, &used)) {
      // Only a prefix may be taken, and only where from_chars takes the same prefix.
      double expect = 0.0;
      const auto r = std::from_chars(s, s + std::strlen(s), expect);
      EXPECT_EQ(r.ec, std::errc()) << s;
      EXPECT_EQ(static_cast<std::size_t>(r.ptr - s), used) << s;
    }
  }
  EXPECT_FALSE(accepts("1e400"));
  EXPECT_FALSE(accepts("12345678901234567890"));
  EXPECT_FALSE(accepts("nan"));
}
