#include "hstmon_host/text_encoding.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

#include "hstmon_host/log_layout.hpp"
#include "text_util.hpp"
#include "utf8_check.hpp"

namespace hstmon::host {

namespace {

using CodePage = std::array<std::uint16_t, 128>;  // bytes 0x80–0xFF; 0 = undefined

constexpr CodePage kWindows1250 = {
    0x20AC, 0, 0x201A, 0, 0x201E, 0x2026, 0x2020, 0x2021, 0, 0x2030, 0x0160, 0x2039, 0x015A, 0x0164, 0x017D, 0x0179,
    0, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014, 0, 0x2122, 0x0161, 0x203A, 0x015B, 0x0165, 0x017E, 0x017A,
    0x00A0, 0x02C7, 0x02D8, 0x0141, 0x00A4, 0x0104, 0x00A6, 0x00A7, 0x00A8, 0x00A9, 0x015E, 0x00AB, 0x00AC, 0x00AD, 0x00AE, 0x017B,
    0x00B0, 0x00B1, 0x02DB, 0x0142, 0x00B4, 0x00B5, 0x00B6, 0x00B7, 0x00B8, 0x0105, 0x015F, 0x00BB, 0x013D, 0x02DD, 0x013E, 0x017C,
    0x0154, 0x00C1, 0x00C2, 0x0102, 0x00C4, 0x0139, 0x0106, 0x00C7, 0x010C, 0x00C9, 0x0118, 0x00CB, 0x011A, 0x00CD, 0x00CE, 0x010E,
    0x0110, 0x0143, 0x0147, 0x00D3, 0x00D4, 0x0150, 0x00D6, 0x00D7, 0x0158, 0x016E, 0x00DA, 0x0170, 0x00DC, 0x00DD, 0x0162, 0x00DF,
    0x0155, 0x00E1, 0x00E2, 0x0103, 0x00E4, 0x013A, 0x0107, 0x00E7, 0x010D, 0x00E9, 0x0119, 0x00EB, 0x011B, 0x00ED, 0x00EE, 0x010F,
    0x0111, 0x0144, 0x0148, 0x00F3, 0x00F4, 0x0151, 0x00F6, 0x00F7, 0x0159, 0x016F, 0x00FA, 0x0171, 0x00FC, 0x00FD, 0x0163, 0x02D9,
};

// 0x80–0x9F; from 0xA0 on, Windows-1252 is Latin-1.
constexpr std::array<std::uint16_t, 32> kWindows1252Low = {
    0x20AC, 0, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0, 0x017D, 0,
    0, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0, 0x017E, 0x0178,
};

/// Code point of byte `b` in the single-byte encoding `e`; 0 when undefined.
std::uint32_t code_point(unsigned char b, TextEncoding e) noexcept {
  if (b < 0x80) return b;
  switch (e) {
    case TextEncoding::kWindows1250: return kWindows1250[b - 0x80u];
    case TextEncoding::kWindows1252: return b < 0xA0 ? kWindows1252Low[b - 0x80u] : b;
    default: return b;  // Latin-1
  }
}

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

/// Letters of Polish and Czech that Windows-1250 and -1252 put on different bytes.
bool is_polish_or_czech(std::uint32_t cp) noexcept {
  static constexpr std::uint16_t kLetters[] = {
      0x0104, 0x0105, 0x0106, 0x0107, 0x010C, 0x010D, 0x010E, 0x010F, 0x0118, 0x0119, 0x011A, 0x011B,
      0x0141, 0x0142, 0x0143, 0x0144, 0x0147, 0x0148, 0x0158, 0x0159, 0x015A, 0x015B, 0x0164, 0x0165,
      0x016E, 0x016F, 0x0179, 0x017A, 0x017B, 0x017C};
  return std::find(std::begin(kLetters), std::end(kLetters), cp) != std::end(kLetters);
}

bool is_letter_byte(char c) noexcept {
  const auto u = static_cast<unsigned char>(c);
  return u >= 0x80 || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z');
}

/// Length of the valid UTF-8 sequence of two or more bytes at `i`, else 0.
std::size_t utf8_sequence(std::string_view s, std::size_t i) noexcept {
  const auto b = static_cast<unsigned char>(s[i]);
  const std::size_t n = b >= 0xC2 && b <= 0xDF ? 2 : b >= 0xE0 && b <= 0xEF ? 3 : b >= 0xF0 && b <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0u) != 0x80u) return 0;
  }
  return n;
}

/// The names of the encodings, lower case; each encoding's own name first.
struct EncodingName {
  const char* name;
  TextEncoding encoding;
};
constexpr EncodingName kEncodingNames[] = {
    {"utf-8", TextEncoding::kUtf8},
    {"utf8", TextEncoding::kUtf8},
    {"windows-1250", TextEncoding::kWindows1250},
    {"cp1250", TextEncoding::kWindows1250},
    {"windows-1252", TextEncoding::kWindows1252},
    {"cp1252", TextEncoding::kWindows1252},
    {"latin-1", TextEncoding::kLatin1},
    {"latin1", TextEncoding::kLatin1},
    {"iso-8859-1", TextEncoding::kLatin1},
};

}  // namespace

std::optional<TextEncoding> text_encoding_from_name(std::string_view name) noexcept {
  const std::string n = detail::ascii_lower(name);
  for (const EncodingName& e : kEncodingNames) {
    if (n == e.name) return e.encoding;
  }
  return std::nullopt;
}

const char* text_encoding_name(TextEncoding e) noexcept {
  for (const EncodingName& n : kEncodingNames) {
    if (n.encoding == e) return n.name;  // the first, the encoding's own name
  }
  return "detect";
}

std::size_t log_head_size(std::string_view text) noexcept {
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t nl = text.find('\n', at);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    const std::string_view line = text.substr(at, end - at);
    // A data row, or a line meant as one (a number first, junk after it: the reader says where).
    const std::size_t first = line.find_first_not_of(" \t");
    if (looks_like_data_row(line) ||
        (first != std::string_view::npos && std::string_view("0123456789+-.").find(line[first]) != std::string_view::npos)) {
      return at;
    }
    at = end + 1;
  }
  return text.size();
}

TextEncoding detect_head_encoding(std::string_view head) noexcept {
  if (head.substr(0, 3) == "\xEF\xBB\xBF" || detail::find_invalid_utf8(head) == std::string_view::npos) {
    return TextEncoding::kUtf8;
  }
  bool ok1250 = true, ok1252 = true;
  std::size_t votes1250 = 0, votes1252 = 0;
  for (std::size_t i = 0; i < head.size(); ++i) {
    const auto b = static_cast<unsigned char>(head[i]);
    if (b < 0x20 && b != '\t' && b != '\r' && b != '\n') return TextEncoding::kUtf8;  // binary, not a code page
    if (b < 0x80) continue;
    if (utf8_sequence(head, i) != 0) return TextEncoding::kUtf8;  // UTF-8 with junk: the reader says where
    const std::uint32_t a = code_point(b, TextEncoding::kWindows1250);
    const std::uint32_t w = code_point(b, TextEncoding::kWindows1252);
    ok1250 = ok1250 && a != 0;
    ok1252 = ok1252 && w != 0;
    if (a == w) continue;
    // ³ ² ¹ after a unit letter and before no letter ("m³/s") is 1252's, not 'ł' or 'ą'.
    const bool superscript = (b == 0xB2 || b == 0xB3 || b == 0xB9) && i > 0 && is_letter_byte(head[i - 1]) &&
                             (i + 1 == head.size() || !is_letter_byte(head[i + 1]));
    if (!superscript && is_polish_or_czech(a)) {
      ++votes1250;
    } else {
      ++votes1252;
    }
  }
  if (ok1250 && (!ok1252 || votes1250 > votes1252)) return TextEncoding::kWindows1250;
  return ok1252 ? TextEncoding::kWindows1252 : TextEncoding::kUtf8;
}

std::string single_byte_to_utf8(std::string_view bytes, TextEncoding e) {
  std::string out;
  out.reserve(bytes.size() + bytes.size() / 4);
  for (const char c : bytes) {
    const std::uint32_t cp = code_point(static_cast<unsigned char>(c), e);
    append_utf8(out, cp != 0 || c == '\0' ? cp : 0xFFFDu);
  }
  return out;
}

std::string_view log_text_in_utf8(std::string_view text, TextEncoding e, std::string& storage) {
  if (e == TextEncoding::kUtf8 || text.substr(0, 3) == "\xEF\xBB\xBF") return text;  // a BOM says UTF-8
  const std::size_t head = log_head_size(text);
  const std::string_view head_text = text.substr(0, head);
  if (std::all_of(head_text.begin(), head_text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; })) {
    return text;
  }
  const TextEncoding from = e == TextEncoding::kDetect ? detect_head_encoding(head_text) : e;
  if (from == TextEncoding::kUtf8) return text;
  storage = single_byte_to_utf8(head_text, from);
  storage.append(text.substr(head));
  return storage;
}

}  // namespace hstmon::host
