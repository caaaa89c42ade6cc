#pragma once
/// @file fast_decimal.hpp
/// Internal: exact fast path for the decimals loggers write ("33.1207", "-0.001",
/// "4.41e-08"). Clinger's observation: when the decimal significand m is at most 2^53
/// and the power of ten e (exponent minus fraction digits) lies in [-22, 22], both m and
/// 10^|e| are exact doubles, so m·10^e or m/10^-e is a single correctly rounded
/// operation — bit-identical to std::from_chars. Anything else (long significands, big
/// exponents, nan/inf) is left to std::from_chars. Digits are read eight at a time.

#include <cstdint>
#include <cstring>

namespace hstmon::host::detail {

// Inlined into the row loop, the constants below stay in registers across fields.
#if defined(__GNUC__)
#define HSTMON_FAST_DECIMAL_INLINE inline __attribute__((always_inline))
#else
#define HSTMON_FAST_DECIMAL_INLINE inline
#endif

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
/// Eight bytes at p, as a little-endian word XOR '0' in every byte: digit bytes become
/// 0–9, every other byte something above 9.
inline std::uint64_t load_digits8(const char* p) noexcept {
  std::uint64_t w;
  std::memcpy(&w, p, 8);
  return w ^ 0x3030303030303030ull;
}

/// How many of the leading bytes of `a` (from load_digits8) are digits: 0–8. Per byte,
/// (a & 0x7F) + 0x76 sets the top bit when a ≥ 10 and never carries into the next byte.
inline int leading_digit_count(std::uint64_t a) noexcept {
  const std::uint64_t non_digit = (((a & 0x7F7F7F7F7F7F7F7Full) + 0x7676767676767676ull) | a) & 0x8080808080808080ull;
  return non_digit == 0 ? 8 : __builtin_ctzll(non_digit) >> 3;
}

/// Value of the first n (1–8) digit bytes of `a`: shifted to the top so the bytes below
/// read as leading zeros, then the usual three multiply-and-add steps.
inline std::uint64_t digits8_value(std::uint64_t a, int n) noexcept {
  a <<= 8 * (8 - n);
  a = a * 10 + (a >> 8);
  constexpr std::uint64_t kMask = 0x000000FF000000FFull;
  constexpr std::uint64_t kMul1 = 100 + (1000000ull << 32);
  constexpr std::uint64_t kMul2 = 1 + (10000ull << 32);
  return (((a & kMask) * kMul1) + (((a >> 16) & kMask) * kMul2)) >> 32;
}
#define HSTMON_FAST_DECIMAL_SWAR 1
#endif

/// 10^n as integers, n = 0–8.
inline constexpr std::uint64_t kPow10Int[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000};

/// Appends the digits at s to m and moves s past them; returns how many there were (m
/// wraps beyond 19 digits, which the caller refuses). Usually one 8-byte step.
inline int read_digits(const char*& s, const char* end, std::uint64_t& m) noexcept {
  int count = 0;
#if defined(HSTMON_FAST_DECIMAL_SWAR)
  while (end - s >= 8) {
    const std::uint64_t a = load_digits8(s);
    const int n = leading_digit_count(a);
    if (n == 0) return count;
    m = m * kPow10Int[n] + digits8_value(a, n);
    s += n;
    count += n;
    if (n != 8) return count;
  }
#endif
  while (s < end && static_cast<unsigned char>(*s - '0') < 10u) {
    m = m * 10u + static_cast<unsigned char>(*s - '0');
    ++s;
    ++count;
  }
  return count;
}

/// Reads digits[.digits] at s into the significand m (all digits, the point ignored),
/// moving s past it; `fraction` = digits after the point. False when there are no digits
/// or more than 19 (m would wrap). Loggers' numbers (at most 7 integer and 15 fraction
/// digits) are read from 8-byte loads: one conversion up to 8 digits, two or three above.
HSTMON_FAST_DECIMAL_INLINE bool read_significand(const char*& s, const char* end, bool comma_point, std::uint64_t& m,
                                                 int& fraction) noexcept {
#if defined(HSTMON_FAST_DECIMAL_SWAR)
  if (end - s >= 24) {
    const std::uint64_t a0 = load_digits8(s);
    const int n0 = leading_digit_count(a0);
    const char after = s[n0 < 8 ? n0 : 7];
    if (n0 < 8 && (after == '.' || (comma_point && after == ','))) {
      const std::uint64_t a1 = load_digits8(s + n0 + 1);
      const int n1 = leading_digit_count(a1);
      if (n1 < 8) {
        const int n = n0 + n1;
        if (n == 0) return false;  // "." alone
        if (n <= 8) {
          // Integer digits in the low n0 bytes, fraction digits above them: one conversion.
          m = digits8_value((a0 & ((std::uint64_t{1} << (8 * n0)) - 1)) | (a1 << (8 * n0)), n);
        } else {
          m = digits8_value(a0, n0) * kPow10Int[n1] + digits8_value(a1, n1);  // n0 ≥ 2 here
        }
        fraction = n1;
        s += n + 1;
        return true;
      }
      // Eight fraction digits and perhaps more ("33.18532082").
      const std::uint64_t a2 = load_digits8(s + n0 + 9);
      const int n2 = leading_digit_count(a2);
      if (n2 < 8 && n0 + 8 + n2 <= 19) {
        m = (n0 != 0 ? digits8_value(a0, n0) * 100000000u : 0u) + digits8_value(a1, 8);
        if (n2 != 0) m = m * kPow10Int[n2] + digits8_value(a2, n2);
        fraction = 8 + n2;
        s += n0 + 9 + n2;
        return true;
      }
    } else if (n0 < 8) {
      if (n0 == 0) return false;  // no digits, no point
      m = digits8_value(a0, n0);  // an integer
      fraction = 0;
      s += n0;
      return true;
    }
  }
#endif
  m = 0;
  int digits = read_digits(s, end, m);
  fraction = 0;
  if (s < end && (*s == '.' || (comma_point && *s == ','))) {
    ++s;
    fraction = read_digits(s, end, m);
    digits += fraction;
  }
  return digits != 0 && digits <= 19;
}

/// Parses [-]digits[.digits][(e|E)[+|-]digits] at [p, end) (digits on at least one side
/// of the point); with `comma_point` a ',' is accepted as the decimal point too. On
/// success stores the value, sets `stop` to the first byte after the number and returns
/// true. Returns false (nothing stored) when the text is not such a number or is outside
/// the exact range; the caller then falls back to std::from_chars, which gives the same
/// value and stop for everything accepted here.
HSTMON_FAST_DECIMAL_INLINE bool fast_decimal(const char* p, const char* end, double& value, const char*& stop,
                         bool comma_point = false) noexcept {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr std::uint64_t kMaxExact = std::uint64_t{1} << 53;
  const char* s = p;
  const bool negative = s < end && *s == '-';
  if (negative) ++s;
  std::uint64_t m;
  int fraction;
  if (!read_significand(s, end, comma_point, m, fraction) || m > kMaxExact) return false;
  int e10 = -fraction;
  if (s < end && (*s | 0x20) == 'e') {
    const char* x = s + 1;
    const bool exp_negative = x < end && *x == '-';
    if (x < end && (*x == '-' || *x == '+')) ++x;
    int exponent = 0;
    int exp_digits = 0;
    while (x < end && static_cast<unsigned char>(*x - '0') < 10u) {
      if (++exp_digits > 4) return false;  // keeps the sum small; from_chars decides
      exponent = exponent * 10 + (*x - '0');
      ++x;
    }
    if (exp_digits == 0) return false;  // "1e", "1e+": from_chars stops before the 'e'
    e10 += exp_negative ? -exponent : exponent;
    s = x;
  }
  // m ≤ 2^53 fits a signed 64-bit integer: one conversion instruction.
  double v = static_cast<double>(static_cast<std::int64_t>(m));
  if (e10 < 0) {
    if (e10 < -22) return false;
    v /= kPow10[-e10];
  } else if (e10 > 0) {
    if (e10 > 22) return false;
    v *= kPow10[e10];
  }
  value = negative ? -v : v;
  stop = s;
  return true;
}

}  // namespace hstmon::host::detail
