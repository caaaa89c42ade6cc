#include "utf8_check.hpp"

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hstmon::host::detail {

namespace {

constexpr std::uint64_t kOnes = 0x0101010101010101ull;
constexpr std::uint64_t kHighs = 0x8080808080808080ull;

/// True when the 8 bytes in w are all ASCII and none is NUL.
inline bool clean_ascii_word(std::uint64_t w) noexcept {
  const std::uint64_t has_zero = (w - kOnes) & ~w & kHighs;
  return ((w & kHighs) | has_zero) == 0;
}

/// True when the 32 bytes at p are all ASCII and none is NUL (SSE2 where available:
/// twice the speed of the 64-bit word version).
inline bool clean_ascii_32(const unsigned char* p) noexcept {
#if defined(__SSE2__)
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16));
  const __m128i zero = _mm_setzero_si128();
  const __m128i nul = _mm_or_si128(_mm_cmpeq_epi8(a, zero), _mm_cmpeq_epi8(b, zero));
  return _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(a, b), nul)) == 0;
#else
  std::uint64_t w[4];
  std::memcpy(w, p, 32);
  const std::uint64_t bad = ((w[0] - kOnes) & ~w[0]) | ((w[1] - kOnes) & ~w[1]) | ((w[2] - kOnes) & ~w[2]) |
                            ((w[3] - kOnes) & ~w[3]) | w[0] | w[1] | w[2] | w[3];
  return (bad & kHighs) == 0;
#endif
}

/// Length of the valid UTF-8 sequence starting with lead byte at p (p < end, *p ≥ 0x80),
/// or 0 if invalid.
std::size_t sequence_length(const unsigned char* p, const unsigned char* end) noexcept {
  const unsigned char c = p[0];
  std::size_t n;
  unsigned char lo = 0x80;
  unsigned char hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;        // overlong
    if (c == 0xED) hi = 0x9F;        // surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;        // overlong
    if (c == 0xF4) hi = 0x8F;        // above U+10FFFF
  } else {
    return 0;
  }
  if (static_cast<std::size_t>(end - p) < n) return 0;
  if (p[1] < lo || p[1] > hi) return 0;
  for (std::size_t i = 2; i < n; ++i) {
    if (p[i] < 0x80 || p[i] > 0xBF) return 0;
  }
  return n;
}

}  // namespace

std::size_t find_invalid_utf8(std::string_view text) noexcept {
  const auto* const begin = reinterpret_cast<const unsigned char*>(text.data());
  const auto* const end = begin + text.size();
  const unsigned char* p = begin;
  while (p < end) {
    // 32 clean bytes at a time (the common case), then 8, then byte by byte.
    while (end - p >= 32 && clean_ascii_32(p)) p += 32;
    if (p == end) break;  // text need not be NUL-terminated: never read *end
    if (end - p >= 8) {
      std::uint64_t w;
      std::memcpy(&w, p, 8);
      if (clean_ascii_word(w)) {
        p += 8;
        continue;
      }
    }
    const unsigned char c = *p;
    if (c == 0) return static_cast<std::size_t>(p - begin);
    if (c < 0x80) {
      ++p;
      continue;
    }
    const std::size_t n = sequence_length(p, end);
    if (n == 0) return static_cast<std::size_t>(p - begin);
    p += n;
  }
  return std::string_view::npos;
}

}  // namespace hstmon::host::detail
