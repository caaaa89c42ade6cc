#pragma once
/// @file delimiter_scan.hpp
/// Internal: where the separators and the line end are in 16 bytes of a log row. The log
/// reader finds a row's field boundaries this way before it parses any number, so each
/// field's parse starts from a known place instead of waiting for the previous field's
/// end, and the processor can work on several fields at once.

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hstmon::host::detail {

/// Bit i of `sep` / `newline` set when byte i of 16 is the separator / a '\n'.
struct DelimiterMasks {
  std::uint32_t sep;
  std::uint32_t newline;
};

/// The masks of the 16 bytes at p (p must have 16 readable bytes).
inline DelimiterMasks delimiter_masks16(const char* p, char sep) noexcept {
#if defined(__SSE2__)
  const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  return {static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8(sep)))),
          static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(v, _mm_set1_epi8('\n'))))};
#else
  DelimiterMasks m{0, 0};
  for (unsigned i = 0; i < 16; ++i) {
    m.sep |= static_cast<std::uint32_t>(p[i] == sep) << i;
    m.newline |= static_cast<std::uint32_t>(p[i] == '\n') << i;
  }
  return m;
#endif
}

/// As delimiter_masks16 for the n < 16 bytes left at the end of a text: bytes past the
/// end read as '\n', so a last line without a line break ends there.
inline DelimiterMasks delimiter_masks_tail(const char* p, std::size_t n, char sep) noexcept {
  char buf[16];
  std::memset(buf, '\n', sizeof buf);
  std::memcpy(buf, p, n);
  return delimiter_masks16(buf, sep);
}

}  // namespace hstmon::host::detail
