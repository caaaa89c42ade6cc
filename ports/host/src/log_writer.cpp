#include "hstmon_host/log_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <system_error>
#include <utility>

#include "text_util.hpp"

namespace hstmon::host {

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;  // write in 1 MiB blocks
constexpr const char* kMemoryName = "<memory>";

}  // namespace

CsvColumn column_for(Signal s, std::string unit) {
  const SignalInfo& info = signal_info(s);
  return CsvColumn{std::string(info.name), info.quantity, std::move(unit)};
}

CsvWriter::~CsvWriter() { close(); }

CsvWriter::CsvWriter(CsvWriter&& other) noexcept
    : path_(std::move(other.path_)),
      file_(std::exchange(other.file_, nullptr)),
      memory_(other.memory_),
      open_(std::exchange(other.open_, false)),
      buffer_(std::move(other.buffer_)),
      conv_(std::move(other.conv_)),
      options_(std::move(other.options_)),
      rows_(other.rows_),
      error_(std::move(other.error_)) {}

CsvWriter& CsvWriter::operator=(CsvWriter&& other) noexcept {
  if (this != &other) {
    close();
    path_ = std::move(other.path_);
    file_ = std::exchange(other.file_, nullptr);
    memory_ = other.memory_;
    open_ = std::exchange(other.open_, false);
    buffer_ = std::move(other.buffer_);
    conv_ = std::move(other.conv_);
    options_ = std::move(other.options_);
    rows_ = other.rows_;
    error_ = std::move(other.error_);
  }
  return *this;
}

void CsvWriter::set_error(std::string message) {
  if (!error_) error_ = SourceError{path_, 0, 0, std::move(message)};
}

std::optional<SourceError> CsvWriter::open(const std::string& path, std::vector<CsvColumn> columns,
                                           const WriteOptions& options) {
  close();
  path_ = path;
  memory_ = false;
  if (auto e = start(std::move(columns), options)) return e;
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) {
    const int err = errno;
    buffer_.clear();
    return SourceError{path_, 0, 0, "cannot create: " + std::generic_category().message(err)};
  }
  open_ = true;
  if (buffer_.size() >= kFlushBytes) flush_buffer();
  return error_;
}

std::optional<SourceError> CsvWriter::open_memory(std::vector<CsvColumn> columns, const WriteOptions& options) {
  close();
  path_ = kMemoryName;
  memory_ = true;
  if (auto e = start(std::move(columns), options)) return e;
  open_ = true;
  return std::nullopt;
}

std::optional<SourceError> CsvWriter::start(std::vector<CsvColumn> columns, const WriteOptions& options) {
  buffer_.clear();
  conv_.clear();
  rows_ = 0;
  error_.reset();
  options_ = options;
  const char sep = options.separator;
  const auto refuse = [this](std::string msg) { return SourceError{path_, 0, 0, std::move(msg)}; };
  if (sep != ',' && sep != ';' && sep != '\t') return refuse("separator must be ',', ';' or tab");
  if (options.decimal_comma && sep == ',') return refuse("a decimal comma needs ';' or tab as separator");
  if (options.precision < 0 || options.precision > 17) return refuse("precision must be 0 (shortest) to 17");
  if (columns.empty()) return refuse("no columns");
  for (const std::string& c : options.comments) {
    if (c.find_first_of("\r\n") != std::string::npos) return refuse("comment lines must not contain line breaks");
    buffer_ += "# ";
    buffer_ += c;
    buffer_ += '\n';
  }
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const CsvColumn& c = columns[i];
    const auto bad_char = [sep](char ch) { return ch == sep || ch == '\n' || ch == '\r' || ch == '"'; };
    if (c.name.empty() || std::any_of(c.name.begin(), c.name.end(), bad_char) ||
        c.name.find_first_of("[]()") != std::string::npos) {
      buffer_.clear();
      return refuse("column name '" + detail::printable(c.name) +
                    "' is empty or holds a separator, quote, bracket or line break");
    }
    const UnitResult u = parse_unit(c.quantity, c.unit);
    if (!u.ok()) {
      buffer_.clear();
      return refuse(u.error + " in column '" + detail::printable(c.name) + "'");
    }
    if (std::any_of(c.unit.begin(), c.unit.end(), bad_char)) {
      buffer_.clear();
      return refuse("unit of column '" + detail::printable(c.name) + "' holds a separator or line break");
    }
    conv_.push_back(u.conversion);
    if (i != 0) buffer_ += sep;
    buffer_ += c.name;
    if (!c.unit.empty()) {
      buffer_ += '[';
      buffer_ += c.unit;
      buffer_ += ']';
    }
  }
  buffer_ += '\n';
  return std::nullopt;
}

bool CsvWriter::flush_buffer() {
  if (memory_ || file_ == nullptr || buffer_.empty()) return true;
  const std::size_t n = std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
  const bool ok = n == buffer_.size();
  buffer_.clear();
  if (!ok) {
    set_error("write failed: " + std::generic_category().message(errno));
  }
  return ok;
}

bool CsvWriter::write_row(const double* values, std::size_t count) {
  if (!open_) return false;
  if (count != conv_.size()) {
    set_error("write_row got " + std::to_string(count) + " values for " + std::to_string(conv_.size()) +
              " columns");
    return false;
  }
  if (error_) return false;
  char buf[64];
  const char sep = options_.separator;
  for (std::size_t i = 0; i < count; ++i) {
    const double v = conv_[i].from_si(values[i]);
    const std::to_chars_result r =
        options_.precision == 0
            ? std::to_chars(buf, buf + sizeof buf, v)
            : std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, options_.precision);
    if (options_.decimal_comma) std::replace(buf, r.ptr, '.', ',');
    if (i != 0) buffer_ += sep;
    buffer_.append(buf, r.ptr);
  }
  buffer_ += '\n';
  ++rows_;
  if (buffer_.size() >= kFlushBytes) return flush_buffer();
  return true;
}

std::optional<SourceError> CsvWriter::close() {
  if (!open_) return error_;
  open_ = false;
  if (!memory_) {
    flush_buffer();
    if (file_ != nullptr) {
      if (std::fclose(file_) != 0) set_error("close failed: " + std::generic_category().message(errno));
      file_ = nullptr;
    }
  }
  return error_;
}

namespace {

std::optional<SourceError> write_log_impl(CsvWriter& w, const std::string* path, const LogData& log,
                                          const std::map<Signal, std::string>& units,
                                          const WriteOptions& options) {
  std::vector<CsvColumn> cols;
  std::vector<const std::vector<double>*> data;
  const std::string name = path != nullptr ? *path : std::string(kMemoryName);
  for (std::size_t k = 0; k < kSignalCount; ++k) {
    const auto s = static_cast<Signal>(k);
    if (s != Signal::kT && !log.present[k]) continue;
    const auto u = units.find(s);
    cols.push_back(column_for(s, u != units.end() ? u->second : std::string()));
    data.push_back(&log.column(s));
    if (data.back()->size() != log.rows()) {
      return SourceError{name, 0, 0, "column '" + std::string(signal_name(s)) + "' has " +
                                         std::to_string(data.back()->size()) + " values, time has " +
                                         std::to_string(log.rows())};
    }
  }
  auto e = path != nullptr ? w.open(*path, cols, options) : w.open_memory(cols, options);
  if (e) return e;
  std::vector<double> row(cols.size());
  for (std::size_t r = 0; r < log.rows(); ++r) {
    for (std::size_t c = 0; c < cols.size(); ++c) row[c] = (*data[c])[r];
    if (!w.write_row(row)) break;
  }
  return w.close();
}

}  // namespace

std::optional<SourceError> write_log(const std::string& path, const LogData& log,
                                     const std::map<Signal, std::string>& units, const WriteOptions& options) {
  CsvWriter w;
  return write_log_impl(w, &path, log, units, options);
}

std::optional<SourceError> write_log_to_string(std::string& out, const LogData& log,
                                               const std::map<Signal, std::string>& units,
                                               const WriteOptions& options) {
  CsvWriter w;
  auto e = write_log_impl(w, nullptr, log, units, options);
  out = w.str();
  return e;
}

}  // namespace hstmon::host
