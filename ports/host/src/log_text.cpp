#include "hstmon_host/log_text.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <new>
#include <system_error>

#include "hstmon_host/text_source.hpp"

namespace hstmon::host {

namespace {

// The gzip magic bytes: such a file is decompressed, not mapped.
bool gzip_magic(const void* p, std::size_t n) noexcept {
  const auto* b = static_cast<const unsigned char*>(p);
  return n >= 2 && b[0] == 0x1f && b[1] == 0x8b;
}

// The mapping of a plain regular file at path, or nullptr (then the caller reads it).
void* map_plain_file(const std::string& path, std::size_t& size) noexcept {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return nullptr;
  struct stat st {};
  void* p = nullptr;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    size = static_cast<std::size_t>(st.st_size);
    // MAP_POPULATE: the page tables filled in one go, not one fault per page as the parse moves on.
    p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p == MAP_FAILED) p = nullptr;
  }
  ::close(fd);  // the mapping keeps the file
  if (p != nullptr && gzip_magic(p, size)) {
    ::munmap(p, size);
    p = nullptr;
  }
  return p;
}

}  // namespace

LogText::~LogText() { release(); }

void LogText::release() noexcept {
  if (map_ != nullptr) ::munmap(map_, map_size_);
  map_ = nullptr;
  map_size_ = 0;
  owned_.clear();
}

std::optional<SourceError> load_log_text(const std::string& path, LogText& text) {
  text.release();
  std::size_t size = 0;
  if (void* p = map_plain_file(path, size)) {
    text.map_ = p;
    text.map_size_ = size;
    return std::nullopt;
  }
  try {
    return read_log_text(path, text.owned_);
  } catch (const std::bad_alloc&) {
    text.release();  // what was read so far
    return SourceError{path, 0, 0, "cannot read: " + std::generic_category().message(ENOMEM)};
  }
}

}  // namespace hstmon::host
