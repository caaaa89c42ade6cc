#include "hstmon_host/text_source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <zlib.h>

namespace hstmon::host {

namespace {

gzFile as_gz(void* p) noexcept { return static_cast<gzFile>(p); }

/// Bytes zlib asks the file for at a time (its default, 8 KiB, costs more calls).
constexpr unsigned kGzBuffer = 1u << 17;

}  // namespace

TextSource::~TextSource() {
  if (gz_ != nullptr) gzclose_r(as_gz(gz_));
}

std::optional<SourceError> TextSource::open(const std::string& path) {
  path_ = path;
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::is_directory(st)) {
    return SourceError{path, 0, 0, "cannot read: " + std::generic_category().message(EISDIR)};
  }
  if (!ec && std::filesystem::is_regular_file(st)) {
    const std::uintmax_t n = std::filesystem::file_size(path, ec);
    file_size_ = ec ? 0 : static_cast<std::uint64_t>(n);
  }
  errno = 0;
  gz_ = gzopen(path.c_str(), "rb");
  if (gz_ == nullptr) {
    return SourceError{path, 0, 0, "cannot open: " + std::generic_category().message(errno != 0 ? errno : ENOMEM)};
  }
  gzbuffer(as_gz(gz_), kGzBuffer);
  // gzdirect() only knows after the first read looked at the magic bytes.
  if (gzungetc(gzgetc(as_gz(gz_)), as_gz(gz_)) < 0) eof_ = gzeof(as_gz(gz_)) != 0;
  compressed_ = gzdirect(as_gz(gz_)) == 0;
  return std::nullopt;
}

std::size_t TextSource::read(char* dst, std::size_t n) {
  if (gz_ == nullptr || eof_ || error_ || n == 0) return 0;
  const unsigned ask = n > (1u << 30) ? (1u << 30) : static_cast<unsigned>(n);
  const int got = gzread(as_gz(gz_), dst, ask);
  int code = Z_OK;
  const char* what = got <= 0 ? gzerror(as_gz(gz_), &code) : "";
  // A truncated stream ends like a whole one, with Z_BUF_ERROR left behind.
  if (got < 0 || code != Z_OK) {
    const std::string why = code == Z_ERRNO ? std::generic_category().message(errno) : std::string(what);
    error_ = SourceError{path_, line_, column_,
                         (compressed_ ? "cannot decompress (gzip): " : "cannot read: ") + why};
    return 0;
  }
  if (got == 0) eof_ = true;
  track_position(dst, static_cast<std::size_t>(got));
  return static_cast<std::size_t>(got);
}

void TextSource::track_position(const char* text, std::size_t n) noexcept {
  // Line breaks by memchr (vectorised in libc; a byte loop costs as much as the read);
  // the column only from the last line break on.
  const char* const end = text + n;
  const char* from = text;
  for (const char* p = text; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)))) != nullptr;) {
    ++line_;
    from = ++p;
  }
  if (from != text) column_ = 1;
  column_ += static_cast<std::size_t>(
      std::count_if(from, end, [](char c) { return (static_cast<unsigned char>(c) & 0xC0u) != 0x80u; }));
}

std::uint64_t TextSource::file_offset() const noexcept {
  if (gz_ == nullptr) return 0;
  const z_off_t off = gzoffset(as_gz(gz_));
  return off < 0 ? 0 : static_cast<std::uint64_t>(off);
}

std::optional<SourceError> read_log_text(const std::string& path, std::string& text) {
  TextSource src;
  if (auto e = src.open(path)) return e;
  text.clear();
  // A plain file's size, plus one byte so its end needs no regrowth; gzip grows by doubling.
  std::size_t cap = src.compressed() || src.file_size() == 0 ? std::size_t{1} << 16
                                                             : static_cast<std::size_t>(src.file_size()) + 1;
  for (;;) {
    if (text.size() == cap) cap *= 2;
    const std::size_t have = text.size();
    text.resize(cap);
    const std::size_t got = src.read(text.data() + have, cap - have);
    text.resize(have + got);
    if (got == 0) break;
  }
  return src.error();
}

}  // namespace hstmon::host
