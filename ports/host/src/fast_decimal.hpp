#pragma once
/// @file fast_decimal.hpp
/// Internal: exact fast path for the plain decimals loggers write ("33.1207", "-0.001").
/// Clinger's observation: when the decimal significand m is at most 2^53 and the number
/// of fraction digits k at most 22, both m and 10^k are exact doubles, so m / 10^k is a
/// single correctly rounded operation — bit-identical to std::from_chars. Anything else
/// (exponents, long significands, nan/inf) is left to std::from_chars.

#include <cstdint>

namespace hstmon::host::detail {

/// Parses [-]digits[.digits] at [p, end); with `comma_point` a ',' is accepted as the
/// decimal point too. On success stores the value, sets `stop` to the first byte after
/// the number and returns true. Returns false (nothing stored) when the text is not such
/// a number or is outside the exact range; the caller then falls back to
/// std::from_chars, which gives the same result for everything accepted here.
inline bool fast_decimal(const char* p, const char* end, double& value, const char*& stop,
                         bool comma_point = false) noexcept {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr std::uint64_t kMaxExact = std::uint64_t{1} << 53;
  const char* s = p;
  const bool negative = s < end && *s == '-';
  if (negative) ++s;
  std::uint64_t m = 0;
  int digits = 0;
  while (s < end && static_cast<unsigned>(*s - '0') < 10u) {
    m = m * 10u + static_cast<unsigned>(*s - '0');
    ++s;
    ++digits;
  }
  int fraction = 0;
  if (s < end && (*s == '.' || (comma_point && *s == ','))) {
    ++s;
    while (s < end && static_cast<unsigned>(*s - '0') < 10u) {
      m = m * 10u + static_cast<unsigned>(*s - '0');
      ++s;
      ++fraction;
    }
    digits += fraction;
  }
  // 19 digits cannot overflow 64 bits; an exponent goes to from_chars.
  if (digits == 0 || digits > 19 || m > kMaxExact || fraction > 22) return false;
  if (s < end && (*s == 'e' || *s == 'E')) return false;
  double v = static_cast<double>(m);
  if (fraction != 0) v /= kPow10[fraction];
  value = negative ? -v : v;
  stop = s;
  return true;
}

}  // namespace hstmon::host::detail
