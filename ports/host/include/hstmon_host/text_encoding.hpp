#pragma once
/// @file text_encoding.hpp
/// The character encoding of a log's head: the lines above its first data row (names,
/// units, metadata). Instruments and spreadsheets on Windows write those in a code page,
/// not UTF-8; the readers work in UTF-8, so such a head is converted first. Data rows are
/// ASCII numbers in every encoding and are never touched.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace hstmon::host {

/// Encoding of a log's head. kDetect: UTF-8 when it is valid UTF-8 (with or without BOM);
/// otherwise Windows-1250 when that reads its non-ASCII bytes as Polish or Czech letters,
/// else Windows-1252; left as it is (so the reader reports the byte) when it is not
/// text in either (NUL, control or undefined bytes, or valid UTF-8 mixed with invalid).
enum class TextEncoding { kDetect, kUtf8, kWindows1250, kWindows1252, kLatin1 };

/// The encoding named `utf-8`, `windows-1250`, `windows-1252` or `latin-1` (ASCII case
/// ignored; also cp1250, cp1252, iso-8859-1, utf8); nothing for any other name.
std::optional<TextEncoding> text_encoding_from_name(std::string_view name) noexcept;

/// The name of `e` as text_encoding_from_name takes it ("detect" for kDetect).
const char* text_encoding_name(TextEncoding e) noexcept;

/// Bytes of `text` before its first data row (log_layout.hpp looks_like_data_row, or a
/// line that starts with a number); the whole text when no line looks like one.
std::size_t log_head_size(std::string_view text) noexcept;

/// The single-byte encoding `head` is in, or kUtf8 for text to leave as it is (see
/// TextEncoding::kDetect).
TextEncoding detect_head_encoding(std::string_view head) noexcept;

/// `bytes` in the single-byte encoding `e` (kWindows1250, kWindows1252, kLatin1) as
/// UTF-8. Every byte gives one code point, so lines and character columns stay where
/// they were; a byte the code page leaves undefined gives U+FFFD.
std::string single_byte_to_utf8(std::string_view bytes, TextEncoding e);

/// `text` with its head in UTF-8: `text` itself when nothing is to convert, else
/// `storage`, filled with the converted head and the rest of `text` unchanged.
/// @param e  the encoding option (kDetect: detect_head_encoding)
std::string_view log_text_in_utf8(std::string_view text, TextEncoding e, std::string& storage);

}  // namespace hstmon::host
