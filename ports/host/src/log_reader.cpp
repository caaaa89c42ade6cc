#include "hstmon_host/log_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <new>
#include <memory>
#include <system_error>

#include <string.h>  // memrchr

#include "delimiter_scan.hpp"
#include "hstmon_host/log_layout.hpp"
#include "hstmon_host/log_options.hpp"
#include "hstmon_host/log_text.hpp"
#include "hstmon_host/text_encoding.hpp"
#include "hstmon_host/text_source.hpp"
#include "fast_decimal.hpp"
#include "row_estimate.hpp"
#include "text_util.hpp"
#include "utf8_check.hpp"

namespace hstmon::host {

namespace {

using detail::char_column;
using detail::printable;
using detail::trim;

/// One physical line: [begin, end) without the line break (and a trailing '\r').
struct Line {
  const char* begin = nullptr;
  const char* end = nullptr;
  const char* next = nullptr;  ///< first byte of the following line
  std::size_t number = 0;      ///< 1-based
};

/// One field of the header or units row (log_layout.hpp).
using Field = LogField;

/// A header cell split into name and unit.
struct HeaderCell {
  std::string_view name;
  const char* name_pos = nullptr;
  std::string_view unit;
  const char* unit_pos = nullptr;  ///< null when the header gives no unit
};

/// How one log column is stored.
struct ColumnSpec {
  std::vector<double>* dst = nullptr;  ///< null: column ignored
  double factor = 1.0;
  double offset = 0.0;
  bool is_time = false;
  bool must_be_empty = false;          ///< the unnamed column a trailing separator leaves
  std::string_view name;               ///< name as in the log, for messages
};

/// Largest field the decimal-comma path copies (longer fields are refused as bad numbers).
constexpr std::size_t kMaxCommaField = 64;

/// Splits [begin, end) at `sep`; each field trimmed and unquoted (log_layout.hpp).
std::vector<Field> split_fields(const char* begin, const char* end, char sep) {
  return split_log_fields(std::string_view(begin, static_cast<std::size_t>(end - begin)), sep);
}

/// The text of a line, without its line break.
std::string_view text_of(const Line& line) noexcept {
  return {line.begin, static_cast<std::size_t>(line.end - line.begin)};
}

/// The file behind a streamed read (LogStream): one buffer refilled from the text
/// source (plain or gzip), so the memory does not grow with the file.
struct StreamSource {
  TextSource text;
  std::unique_ptr<char[]> buf;
  std::size_t cap = 0;         ///< buffer size [bytes]
  std::size_t fill = 0;        ///< bytes in the buffer
  std::uint64_t total = 0;     ///< bytes of text read so far
  bool eof = false;

  /// Reads until the buffer is full or the text ends; false on a read error (text.error()).
  bool read_more() {
    while (fill < cap && !eof) {
      const std::size_t n = text.read(buf.get() + fill, cap - fill);
      if (text.error()) return false;
      if (n == 0) eof = true;
      fill += n;
      total += n;
    }
    return true;
  }
};

class Parser {
 public:
  /// A streamed read: text is the buffer's complete lines; more come through refill().
  Parser(std::string_view text, const ReadOptions& options, LogData& out, StreamSource* src, std::size_t chunk_rows)
      : Parser(text, options, out) {
    src_ = src;
    chunk_rows_ = chunk_rows;
  }

  Parser(std::string_view text, const ReadOptions& options, LogData& out)
      : opt_(options), out_(out) {
    const bool bom = text.substr(0, 3) == "\xEF\xBB\xBF";
    text_ = bom ? text.substr(3) : text;
    cur_ = text_.data();
    end_ = text_.data() + text_.size();
  }

  void run() {
    if (opt_.separator != 0 && opt_.separator != ',' && opt_.separator != ';' && opt_.separator != '\t') {
      out_.error = LogError{out_.path, 0, 0, "separator option must be ',', ';', tab or 0 (detect)"};
      return;
    }
    if (!std::isfinite(opt_.rate) || opt_.rate < 0.0 || (opt_.rate > 0.0 && opt_.rate < kMinRate)) {
      out_.error = LogError{out_.path, 0, 0, "sample rate option must be a finite rate in Hz (at least 1e-6), or 0"};
      return;
    }
    Line header;
    if (!next_content_line(header)) {
      if (out_.error) return;
      if (only_blank_lines()) {
        fail_at(1, 1, "empty file");
      } else {
        fail_eof("no header line (the file has only comments)");
      }
      return;
    }
    if (preamble_layout(header)) return;
    out_.header_line = header.number;
    sep_ = opt_.separator != 0 ? opt_.separator : detect_log_separator(text_of(header));
    decimal_comma_ = sep_ != ',';
    if (!parse_header(header)) return;
    Line first;
    const bool have_first = next_content_line(first);
    if (out_.error) return;
    if (have_first && is_units_row(first)) {
      if (!apply_units_row(first)) return;
      if (!resolve_columns()) return;
      if (!next_content_line(first)) {
        if (!out_.error) fail_eof("no data rows");
        return;
      }
    } else {
      if (!resolve_columns()) return;
      if (!have_first) {
        fail_eof("no data rows");
        return;
      }
    }
    parse_rows(first);
  }

 private:
  // ---- lines ---------------------------------------------------------------------------

  /// Next line that is neither blank nor a '#' comment; false at end of text or when the
  /// line holds binary junk (then error is set). Every line passed over is checked for
  /// NUL and invalid UTF-8 here; fast_row checks its own lines (it takes ASCII only), so
  /// the text is checked once, in order, and the first bad byte is the one reported.
  bool next_content_line(Line& line) {
    while (cur_ < end_ || refill()) {
      const auto* nl = static_cast<const char*>(std::memchr(cur_, '\n', static_cast<std::size_t>(end_ - cur_)));
      line.begin = cur_;
      line.next = nl != nullptr ? nl + 1 : end_;
      line.end = nl != nullptr ? nl : end_;
      line.number = ++line_no_;
      cur_ = line.next;
      if (line.end > line.begin && line.end[-1] == '\r') --line.end;
      const std::size_t bad =
          detail::find_invalid_utf8(std::string_view(line.begin, static_cast<std::size_t>(line.next - line.begin)));
      if (bad != std::string_view::npos) {
        bad_ = line.begin + bad;
        fail_binary(line);
        return false;
      }
      if (line.begin == line.end) continue;
      const char c0 = *line.begin;
      if (c0 == '#') continue;
      if (detail::is_blank(c0)) {
        const char* p = line.begin;
        while (p < line.end && detail::is_blank(*p)) ++p;
        if (p == line.end || *p == '#') continue;
      }
      return true;
    }
    return false;
  }

  bool only_blank_lines() const noexcept {
    return std::all_of(text_.begin(), text_.end(),
                       [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; });
  }

  // ---- errors and notes ----------------------------------------------------------------

  void fail_at(std::size_t line, std::size_t column, std::string message) {
    out_.error = LogError{out_.path, line, column, std::move(message)};
  }

  void fail(const Line& line, const char* pos, std::string message) {
    fail_at(line.number, char_column(line.begin, pos), std::move(message));
  }

  void fail_eof(std::string message) {
    const detail::LineCol lc = detail::locate(text_, text_.size());
    fail_at(lc.line, lc.column, std::move(message));
  }

  void fail_binary(const Line& line) {
    const auto byte = static_cast<unsigned>(static_cast<unsigned char>(*bad_));
    char msg[96];
    if (byte == 0) {
      std::snprintf(msg, sizeof msg, "NUL byte (binary data, not a text log)");
    } else {
      std::snprintf(msg, sizeof msg, "invalid UTF-8 byte 0x%02X (binary data, or text not in UTF-8)", byte);
    }
    fail(line, bad_, msg);
  }

  void note(const Line& line, const char* pos, const std::string& message) {
    out_.notes.push_back(out_.path + ':' + std::to_string(line.number) + ':' +
                         std::to_string(char_column(line.begin, pos)) + ": note: " + message);
  }

  // ---- layout --------------------------------------------------------------------------

  /// Layouts whose column names are not on the first line: a units row above the names
  /// (HBM catman/Spider8 exports) or a block of metadata lines above the header (HYDAC
  /// HMG exports, "key;value" lines). Looks at the lines before the first data row; when
  /// neither layout fits, rewinds and returns false, and the first line is the header as
  /// before (with a units row below it, or not). True when it read the log, ok or not.
  bool preamble_layout(const Line& first) {
    const char* const rewind_cur = cur_;
    const std::size_t rewind_line = line_no_;
    const auto rewind = [&] {
      cur_ = rewind_cur;
      line_no_ = rewind_line;
      out_.error.reset();  // the normal path reports it again, in order
      bad_ = nullptr;
      return false;
    };
    std::vector<Line> block{first};
    Line data;
    bool found = false;
    while (block.size() <= kMaxPreambleLines && next_content_line(data)) {
      if (looks_like_data_row(text_of(data))) {
        found = true;
        break;
      }
      block.push_back(data);
    }
    if (!found) return rewind();
    std::vector<std::string_view> texts;
    texts.reserve(block.size());
    for (const Line& l : block) texts.push_back(text_of(l));
    const std::optional<PreambleLayout> layout = detect_preamble_layout(texts, text_of(data), opt_.separator);
    if (!layout) return rewind();
    const std::size_t names = layout->names;
    const std::optional<std::size_t> units = layout->units;
    sep_ = layout->sep;
    decimal_comma_ = layout->decimal_comma;
    const std::size_t top = layout->metadata();
    if (top > 0) {
      const std::string lines = top == 1 ? "line " + std::to_string(block[0].number)
                                         : "lines " + std::to_string(block[0].number) + "-" +
                                               std::to_string(block[top - 1].number);
      note(block[0], block[0].begin, lines + " above the column names taken as metadata, not columns");
    }
    out_.header_line = block[names].number;
    if (!parse_header(block[names])) return true;
    if (units && !apply_units_row(block[*units])) return true;
    if (!resolve_columns()) return true;
    parse_rows(data);
    return true;
  }

  // ---- header --------------------------------------------------------------------------

  bool parse_header(const Line& header) {
    header_ = header;
    const std::vector<Field> fields = split_fields(header.begin, header.end, sep_);
    cells_.reserve(fields.size());
    for (const Field& f : fields) {
      HeaderCell cell;
      std::string_view s = f.text;
      if (is_trailing_empty_column(cells_.size(), fields.size(), s)) {
        cell.name_pos = f.pos;
        cells_.push_back(cell);  // kept, so rows have as many fields as the header
        break;
      }
      const std::size_t open_b = s.find('[');
      const std::size_t open_p = s.find('(');
      const std::size_t open = std::min(open_b, open_p);
      if (open != std::string_view::npos) {
        const char close = s[open] == '[' ? ']' : ')';
        if (s.back() != close) {
          fail(header, s.data() + open, std::string("unit in column header '") + printable(s) +
                                            "' must end with '" + close + "'");
          return false;
        }
        cell.name = trim(s.substr(0, open));
        cell.unit = trim(s.substr(open + 1, s.size() - open - 2));
        cell.unit_pos = s.data() + open + 1;
      } else {
        cell.name = s;
      }
      cell.name_pos = cell.name.empty() ? f.pos : cell.name.data();
      if (cell.name.empty()) {
        fail(header, f.pos, "empty column name");
        return false;
      }
      cells_.push_back(cell);
    }
    // Duplicated names (ignoring case) are refused even for columns that would be ignored.
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (!cells_[i].name.empty() && detail::iequals(cells_[i].name, cells_[j].name)) {
          // Units taken for names ("V" twice): say so rather than only "duplicate".
          const bool unit = unit_score(text_of(header), sep_) * 2 > cells_.size();
          fail(header, cells_[i].name_pos, "duplicate column name '" + printable(cells_[i].name) +
                                               "' (also field " + std::to_string(j + 1) + ")" +
                                               (unit ? "; this line reads as a units row: the column names "
                                                       "must be on the line right above or below it"
                                                     : ""));
          return false;
        }
      }
    }
    return true;
  }

  /// A units row: same line after the header, all fields non-numeric or empty, at least
  /// one non-empty.
  bool is_units_row(const Line& line) const { return is_text_row(text_of(line), sep_, decimal_comma_); }

  bool apply_units_row(const Line& line) {
    const std::vector<Field> fields = split_fields(line.begin, line.end, sep_);
    if (fields.size() != cells_.size()) {
      const char* pos = fields.size() < cells_.size() ? line.end : fields[cells_.size()].pos;
      fail(line, pos, "units row has " + std::to_string(fields.size()) + " fields, header has " +
                          std::to_string(cells_.size()));
      return false;
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      std::string_view u = fields[i].text;
      if (u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')'))) {
        u = trim(u.substr(1, u.size() - 2));
      }
      HeaderCell& cell = cells_[i];
      if (cell.unit_pos != nullptr && !cell.unit.empty()) {
        if (!u.empty() && u != cell.unit) {
          fail(line, fields[i].pos, "unit '" + printable(u) + "' of column '" + printable(cell.name) +
                                        "' differs from '" + printable(cell.unit) + "' in the header");
          return false;
        }
        continue;
      }
      cell.unit = u;
      cell.unit_pos = u.empty() ? fields[i].pos : u.data();
      unit_line_[i] = line;
    }
    return true;
  }

  /// Maps header cells to signals and units; fills cols_ and out_.present.
  bool resolve_columns() {
    struct MapEntry {
      std::string key;
      std::string target;
      bool used = false;
    };
    std::vector<MapEntry> map;
    map.reserve(opt_.column_map.size());
    for (const auto& [k, v] : opt_.column_map) map.push_back({k, v, false});

    for (const auto& [number, target] : opt_.column_number_map) {
      if (number == 0 || number > cells_.size()) {
        fail(header_, header_.begin, "column map entry '#" + std::to_string(number) + "' names column " +
                                         std::to_string(number) + ", the header has " +
                                         std::to_string(cells_.size()) + " (numbered from 1)");
        return false;
      }
    }

    std::array<std::size_t, kSignalCount> field_of{};  // 1-based field giving each signal
    std::size_t ignored = 0;                             // unknown columns noted so far
    const HeaderCell* last_ignored = nullptr;
    cols_.resize(cells_.size());
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      const HeaderCell& cell = cells_[i];
      std::string_view target = cell.name;
      bool mapped = false;
      // A column number names one column whatever its name; it wins over a name entry.
      const auto by_number = opt_.column_number_map.find(i + 1);
      if (by_number != opt_.column_number_map.end()) {
        target = by_number->second;
        mapped = true;
      }
      for (MapEntry& e : map) {
        if (!column_name_matches(e.key, cell.name)) continue;
        e.used = true;  // names a column, even where a number entry wins
        if (!mapped) {
          target = e.target;
          mapped = true;
        }
      }
      cols_[i].name = cell.name;
      if (cell.name.empty()) {  // the unnamed column of a trailing separator
        cols_[i].must_be_empty = true;
        continue;
      }
      if (mapped && target.empty()) continue;  // dropped on request
      const std::optional<Signal> sig = signal_from_name(target);
      if (!sig) {
        if (mapped) {
          fail(header_, cell.name_pos, "column map sends '" + printable(cell.name) + "' to '" +
                                           printable(target) + "', which is not a known signal");
          return false;
        }
        // A wide export would list every column: the first few, then a count.
        if (++ignored <= kMaxColumnNotes) {
          note(header_, cell.name_pos, "column '" + printable(cell.name) + "' is not a known signal; ignored");
        }
        last_ignored = &cell;
        continue;
      }
      const std::size_t k = index(*sig);
      if (field_of[k] != 0) {
        fail(header_, cell.name_pos, "column '" + printable(cell.name) + "' gives signal '" +
                                         std::string(signal_name(*sig)) + "', already given by field " +
                                         std::to_string(field_of[k]));
        return false;
      }
      field_of[k] = i + 1;
      const SignalInfo& info = signal_info(*sig);
      const UnitResult unit = parse_unit(info.quantity, cell.unit);
      if (!unit.ok()) {
        const auto it = unit_line_.find(i);
        const Line& where = it != unit_line_.end() ? it->second : header_;
        fail(where, cell.unit_pos, unit.error + " in column '" + printable(cell.name) + "'");
        return false;
      }
      ColumnSpec& c = cols_[i];
      c.factor = unit.conversion.factor;
      c.offset = unit.conversion.offset;
      // With a sample rate the time column only gives the start; its values need not increase.
      c.is_time = *sig == Signal::kT && opt_.rate == 0.0;
      c.dst = *sig == Signal::kT ? &out_.t : &out_.values[k];
      if (*sig == Signal::kT) time_column_ = true;
      out_.present[k] = true;
      out_.source_units[k] = std::string(cell.unit);
      out_.source_columns[k] = i + 1;
    }
    if (ignored > kMaxColumnNotes) {
      note(header_, last_ignored->name_pos, ignored_columns_note(ignored, "known signals"));
    }
    if (field_of[index(Signal::kT)] == 0) {
      if (opt_.rate == 0.0) {
        fail(header_, header_.begin,
             "no time column 't' (name one 't', map one with --map COLUMN=t or '#N=t', or give the sample rate "
             "with --rate HZ); " + listed_columns(column_names()));
        return false;
      }
      out_.present[index(Signal::kT)] = true;  // time from the rate alone, starting at 0
    }
    for (const MapEntry& e : map) {
      if (!e.used) {
        fail(header_, header_.begin, unmatched_map_message(e.key, column_names()));
        return false;
      }
    }
    return true;
  }

  /// The header's column names, for messages about a column that is not there.
  std::vector<std::string_view> column_names() const {
    std::vector<std::string_view> names;
    for (const HeaderCell& c : cells_) {
      if (!c.name.empty()) names.push_back(c.name);
    }
    return names;
  }

  // ---- data ----------------------------------------------------------------------------

  /// What became of one data row.
  enum class RowResult { kKept, kSkipped, kFailed };

  /// Trims every column to the rows kept so far (drops a partly stored row).
  void trim_to_kept_rows() {
    const std::size_t kept = rows_ - chunk_base_;  // rows of this chunk
    for (ColumnSpec& c : cols_) {
      if (c.dst != nullptr && c.dst->size() > kept) c.dst->resize(kept);
    }
  }

  /// Trims every column to the rows kept (lenient) or to none (strict).
  void drop_rows_after_error() {
    if (!opt_.lenient) rows_ = chunk_base_;
    trim_to_kept_rows();
  }

  /// True when [q, le) starts with "," or "-," (a decimal comma without integer digits).
  static bool starts_with_comma(const char* q, const char* le) noexcept {
    if (q < le && *q == '-') ++q;
    return q < le && *q == ',';
  }

  bool blank_in_field(char c) const noexcept { return c == ' ' || (c == '\t' && sep_ != '\t'); }

  /// Text of the field starting at f (trimmed, as written), for messages.
  std::string_view field_text(const char* f, const char* le) const {
    const auto* s = static_cast<const char*>(std::memchr(f, sep_, static_cast<std::size_t>(le - f)));
    return trim(std::string_view(f, static_cast<std::size_t>((s != nullptr ? s : le) - f)));
  }

  /// A line fast_row may take: not blank, not a comment (those need next_content_line).
  static bool may_be_fast(char c) noexcept { return c != '#' && c != ' ' && c != '\t' && c != '\r' && c != '\n'; }

  /// The common row, in two quick passes: the field boundaries first (16 bytes at a
  /// time, delimiter_scan.hpp), then every field from its known start, so the fields'
  /// parses do not wait for each other. Taken when every stored field is a number
  /// fast_decimal takes whole, with no blanks or '+', finite after conversion, time above
  /// the last kept time; ignored fields plain ASCII. Such a row is stored exactly as
  /// parse_row would store it, and the first byte of the next line is returned.
  /// Anything else returns null with nothing stored, and parse_row takes the row (errors
  /// and notes included). Only ASCII other than NUL gets through here, so these lines
  /// need no UTF-8 check.
  const char* fast_row(const char* p) {
    const char* const end = end_;
    const char sep = sep_;
    const std::size_t ncols = cols_.size();
    // delims[c]: the byte ending field c (a separator, or the line end for the last).
    const char** const delims = delims_.data();
    std::size_t found = 0;
    const char* line_end = nullptr;
    for (const char* q = p; line_end == nullptr; q += 16) {
      const auto left = static_cast<std::size_t>(end - q);
      detail::DelimiterMasks m =
          left >= 16 ? detail::delimiter_masks16(q, sep) : detail::delimiter_masks_tail(q, left, sep);
      if (m.newline != 0) {
        const unsigned nl = static_cast<unsigned>(__builtin_ctz(m.newline));
        m.sep &= (1u << nl) - 1;  // separators on this line only
        line_end = nl < left ? q + nl : end;
      }
      for (; m.sep != 0; m.sep &= m.sep - 1) {
        if (found + 1 == ncols) return nullptr;  // more fields than the header
        delims[found++] = q + __builtin_ctz(m.sep);
      }
    }
    if (found + 1 != ncols) return nullptr;  // fewer fields than the header
    // As next_content_line: a '\r' before the line break is not part of the last field.
    delims[found] = line_end[-1] == '\r' ? line_end - 1 : line_end;
    const char* next = line_end < end ? line_end + 1 : end;

    const bool comma_point = decimal_comma_;
    const ColumnSpec* const cols = cols_.data();
    double t = last_t_;
    const char* f = p;
    for (std::size_t c = 0; c < ncols; ++c) {
      const ColumnSpec& col = cols[c];
      const char* const fe = delims[c];
      if (col.dst == nullptr) {
        if (col.must_be_empty && fe != f) return undo_fast_row();
        for (const char* x = f; x < fe; ++x) {
          const auto u = static_cast<unsigned char>(*x);
          if (u == 0 || u >= 0x80) return undo_fast_row();
        }
      } else {
        double v;
        const char* stop = f;
        if (!detail::fast_decimal(f, end, v, stop, comma_point) || stop != fe) return undo_fast_row();
        double si = v * col.factor;
        if (col.offset != 0.0) si += col.offset;  // (adding +0 would turn -0 into +0)
        if (!std::isfinite(si)) return undo_fast_row();
        if (col.is_time) {
          if (!(si > t)) return undo_fast_row();
          t = si;
        }
        col.dst->push_back(si);
      }
      f = fe + 1;
    }
    last_t_ = t;
    ++rows_;
    ++line_no_;
    return next;
  }

  const char* undo_fast_row() {
    trim_to_kept_rows();
    return nullptr;
  }

  /// Notes a row skipped by a lenient read for time not strictly increasing (the first
  /// kMaxSkipNotes of them; the rest are counted in a closing note).
  void skip_row(const Line& line, const char* pos, double t) {
    trim_to_kept_rows();
    if (skipped_++ == 0) {
      first_skip_line_ = line.number;
      first_skip_column_ = char_column(line.begin, pos);
      notes_before_skips_ = out_.notes.size();
    }
    last_skip_line_ = line.number;
    last_skip_column_ = char_column(line.begin, pos);
    if (skipped_ > kMaxSkipNotes) return;
    char msg[160];
    std::snprintf(msg, sizeof msg, "time not strictly increasing: %.9g s after %.9g s; row skipped (lenient)", t,
                  last_t_);
    note(line, pos, msg);
  }

  /// Any content row: blanks, '+', decimal commas of every form, and every error with
  /// its position. Time not above the last kept time fails the read, or with `lenient`
  /// skips the row with a note once the rest of the row has been checked.
  RowResult parse_row(const Line& line) {
    const std::size_t ncols = cols_.size();
    const char sep = sep_;
    const char* const le = line.end;
    const char* f = line.begin;
    double row_t = last_t_;
    const char* stale_pos = nullptr;  // time field of a row to skip (lenient)
    double stale_t = 0.0;
    for (std::size_t c = 0; c < ncols; ++c) {
      if (c != 0) {
        if (f == le) {
          fail(line, le, "row has " + std::to_string(c) + " fields, header has " + std::to_string(ncols));
          return RowResult::kFailed;
        }
        ++f;  // f was on the separator
      }
      const ColumnSpec& col = cols_[c];
      if (col.dst == nullptr) {
        const auto* s = static_cast<const char*>(std::memchr(f, sep, static_cast<std::size_t>(le - f)));
        const char* fe = s != nullptr ? s : le;
        if (col.must_be_empty && !trim(std::string_view(f, static_cast<std::size_t>(fe - f))).empty()) {
          fail(line, f, kUnnamedValueMessage);
          return RowResult::kFailed;
        }
        f = fe;
        continue;
      }
      const char* q = f;
      while (q < le && blank_in_field(*q)) ++q;
      if (q < le && *q == '+') ++q;
      double v;
      std::from_chars_result r{q, std::errc()};
      if (!detail::fast_decimal(q, le, v, r.ptr, decimal_comma_)) r = std::from_chars(q, le, v);
      const char* e = r.ptr;
      // Decimal commas the fast path did not take (long significands, big exponents) stop
      // from_chars at ',' (or, for ",5" / "-,5", make it refuse the field).
      const bool comma = decimal_comma_ && ((r.ec == std::errc() && e < le && *e == ',') ||
                                            (r.ec == std::errc::invalid_argument && starts_with_comma(q, le)));
      if (comma) {
        // Copy the field to a stack buffer with '.' and parse again.
        const auto* s = static_cast<const char*>(std::memchr(q, sep, static_cast<std::size_t>(le - q)));
        const char* fe = s != nullptr ? s : le;
        while (fe > q && blank_in_field(fe[-1])) --fe;
        const auto n = static_cast<std::size_t>(fe - q);
        char buf[kMaxCommaField];
        e = q;
        r.ec = std::errc::invalid_argument;
        if (n <= kMaxCommaField) {
          std::memcpy(buf, q, n);
          std::replace(buf, buf + n, ',', '.');
          const char* stop = nullptr;
          if (detail::fast_decimal(buf, buf + n, v, stop) && stop == buf + n) {
            r = {stop, std::errc()};
          } else {
            r = std::from_chars(buf, buf + n, v);
          }
          if (r.ec == std::errc() && r.ptr == buf + n) {
            e = fe;
          } else if (r.ec == std::errc()) {
            r.ec = std::errc::invalid_argument;  // only part of the field is a number
          }
        }
      }
      if (r.ec == std::errc()) {
        while (e < le && blank_in_field(*e)) ++e;
      }
      if (r.ec != std::errc() || (e < le && *e != sep)) {
        fail(line, f, bad_number_message(field_text(f, le), col.name, r.ec == std::errc::result_out_of_range));
        return RowResult::kFailed;
      }
      double si = v * col.factor;
      if (col.offset != 0.0) si += col.offset;  // (adding +0 would turn -0 into +0)
      if (!std::isfinite(si)) {
        fail(line, f, non_finite_message(field_text(f, le), col.name, std::isfinite(v)));
        return RowResult::kFailed;
      }
      if (col.is_time) {
        if (!(si > last_t_)) {
          if (!opt_.lenient) {
            char msg[128];
            std::snprintf(msg, sizeof msg, "time not strictly increasing: %.9g s after %.9g s", si, last_t_);
            fail(line, f, std::string(msg) + kRateHint);
            return RowResult::kFailed;
          }
          stale_pos = f;
          stale_t = si;
        }
        row_t = si;
      }
      col.dst->push_back(si);
      f = e;
    }
    if (f != le) {
      std::string msg = "row has more than " + std::to_string(ncols) + " fields";
      if (sep == ',') msg += " (a decimal comma needs ';' or tab as separator)";
      fail(line, f + 1, msg);
      return RowResult::kFailed;
    }
    if (stale_pos != nullptr) {
      skip_row(line, stale_pos, stale_t);
      return RowResult::kSkipped;
    }
    last_t_ = row_t;
    ++rows_;
    return RowResult::kKept;
  }

  void parse_rows(Line line) {
    delims_.resize(cols_.size());
    const std::size_t max_rows = src_ != nullptr ? chunk_rows_ : detail::estimate_rows(line.begin, end_);
    for (ColumnSpec& c : cols_) {
      if (c.dst != nullptr) c.dst->reserve(max_rows);
    }
    first_ = line;
    have_first_ = true;
    if (src_ != nullptr) {
      // Streamed: LogStream pulls the rows chunk by chunk. Everything above the first data
      // row (header, units row: the column names the messages quote) stays put in the buffer.
      pin_ = const_cast<char*>(line.begin);
      return;
    }
    parse_rows_until(static_cast<std::size_t>(-1));
    finish_rows();
  }

 public:
  /// Parses data rows until the text ends, a row fails, or `stop_at` rows are kept in all;
  /// true when it stopped at stop_at (more rows may follow).
  bool parse_rows_until(std::size_t stop_at) {
    Line line;
    for (;;) {
      if (have_first_) {
        line = first_;
        have_first_ = false;
      } else if (!next_content_line(line)) {
        return false;
      }
      if (parse_row(line) == RowResult::kFailed) return false;
      // A log fast_row never takes (blanks after separators, '+' signs) would pay for a
      // failed attempt on every row: after 8 misses, try every 256th row only.
      if (fast_misses_ < 8 || (++general_rows_ & 255u) == 0) {
        ++fast_misses_;
        while (rows_ < stop_at && (cur_ < end_ || refill()) && may_be_fast(*cur_)) {
          const char* next = fast_row(cur_);
          if (next == nullptr) break;
          fast_misses_ = 0;
          cur_ = next;
        }
      }
      if (rows_ >= stop_at) return true;
    }
  }

  /// Starts a new chunk of a streamed read: the columns drop the rows handed out.
  void start_chunk() {
    chunk_base_ = rows_;
    for (ColumnSpec& c : cols_) {
      if (c.dst != nullptr) c.dst->clear();
    }
  }

  std::size_t rows_kept() const noexcept { return rows_; }
  std::size_t chunk_rows() const noexcept { return chunk_rows_; }
  /// Header read, rows to come through parse_rows_until (streamed reads).
  bool rows_pending() const noexcept { return pin_ != nullptr && !out_.error; }
  /// The header phase reached the end of the first buffer with more of the file to come.
  bool ran_out() const noexcept { return ran_out_; }
  /// Bytes of the file parsed so far (streamed reads).
  std::uint64_t consumed() const noexcept {
    return src_ == nullptr ? 0 : src_->total - static_cast<std::uint64_t>(src_->buf.get() + src_->fill - cur_);
  }

  /// The checks at the end of the rows (lenient skips, --rate), then the rows kept.
  void finish_rows() {
    if (!out_.error && lenient_skips_too_many(skipped_, rows_ + skipped_)) {
      refuse_lenient_skips();
      return;
    }
    if (skipped_ > kMaxSkipNotes) {
      out_.notes.push_back(out_.path + ':' + std::to_string(last_skip_line_) + ':' + std::to_string(last_skip_column_) +
                           ": note: " + skipped_rows_note(skipped_));
    }
    out_.skipped_rows = skipped_;
    if (out_.error) drop_rows_after_error();
    if (opt_.rate > 0.0) rebuild_time();
  }

 private:
  /// Streamed reads: moves the unparsed tail of the buffer down to the pinned header,
  /// reads on, and makes end_ the end of the last complete line (a row is never split).
  /// False at the end of the file, on an error (set), and before the header is read
  /// (then ran_out_ tells LogStream to read the file whole instead).
  bool refill() {
    if (src_ == nullptr || src_->eof || out_.error) return false;
    if (pin_ == nullptr) {
      ran_out_ = true;
      return false;
    }
    char* const buf = src_->buf.get();
    const auto keep = static_cast<std::size_t>(buf + src_->fill - cur_);
    std::memmove(pin_, cur_, keep);
    src_->fill = static_cast<std::size_t>(pin_ - buf) + keep;
    cur_ = pin_;
    end_ = pin_;  // nothing to parse until a complete line is in
    for (;;) {
      if (!src_->read_more()) {
        out_.error = src_->text.error();
        return false;
      }
      const char* const fill_end = buf + src_->fill;
      if (src_->eof) {
        end_ = fill_end;
        break;
      }
      const void* nl = ::memrchr(cur_, '\n', static_cast<std::size_t>(fill_end - cur_));
      if (nl != nullptr) {
        end_ = static_cast<const char*>(nl) + 1;
        break;
      }
      if (src_->fill == src_->cap) {
        const std::size_t room = src_->cap - static_cast<std::size_t>(pin_ - buf);
        fail_at(line_no_ + 1, 1,
                "line longer than " + (room >= (std::size_t{1} << 20) ? std::to_string(room >> 20) + " MiB"
                                                                      : std::to_string(room) + " bytes") +
                    " (not a log row)");
        return false;
      }
    }
    return cur_ < end_;
  }

  /// A lenient read that would drop more than a few per cent of the rows: no glitch but
  /// a time column that cannot be used (rounded coarser than the sample period, or a
  /// clock reset). It fails at the first such row instead of losing most of the file.
  void refuse_lenient_skips() {
    out_.notes.resize(notes_before_skips_);  // the error says it; no list of rows
    fail_at(first_skip_line_, first_skip_column_, lenient_refusal_message(skipped_, rows_ + skipped_));
    out_.skipped_rows = skipped_;
    rows_ = 0;
    trim_to_kept_rows();
  }

  /// Time from the sample rate: t0 + i/rate, t0 the first row's logged time (0 without a
  /// time column). A logged time span that disagrees with the rate gets a note.
  void rebuild_time() {
    std::vector<double>& t = out_.t;
    const double t0 = time_column_ && !t.empty() ? t.front() : 0.0;
    const double rate = opt_.rate;
    if (time_column_ && rows_ >= 2 && t.size() == rows_) {
      const double logged = t.back() - t.front();
      const double rebuilt = static_cast<double>(rows_ - 1) / rate;
      // Rounding of the logged time (1 ms on a Spider8) and a few samples are no disagreement.
      if (std::fabs(logged - rebuilt) > 0.02 * rebuilt + 2.0 / rate + 1e-3) {
        char msg[200];
        std::snprintf(msg, sizeof msg,
                      "the time column spans %.6g s, %zu rows at %.6g Hz span %.6g s: is the sample rate right?",
                      logged, rows_, rate, rebuilt);
        note(header_, header_.begin, msg);
      }
    }
    t.resize(rows_);
    for (std::size_t i = 0; i < rows_; ++i) {
      t[i] = t0 + static_cast<double>(i) / rate;
      // A huge start time swallows steps of 1/rate (1e20 s + 1 ms = 1e20 s).
      if (i > 0 && !(t[i] > t[i - 1])) {
        char msg[160];
        std::snprintf(msg, sizeof msg, "time from the sample rate does not increase: start time %.9g s is too large for steps of %.3g s",
                      t0, 1.0 / rate);
        if (!out_.error) fail_at(out_.header_line, 1, msg);
        rows_ = i;
        trim_to_kept_rows();
        t.resize(rows_);
        if (!opt_.lenient) rows_ = 0;
        return;
      }
    }
  }

  static constexpr std::size_t kMaxSkipNotes = LogNoteRules::kMaxSkipNotes;
  static constexpr std::size_t kMaxColumnNotes = LogNoteRules::kMaxColumnNotes;
  /// Lines looked at for a units row above the names or a metadata block.
  /// Lowest sample rate option [Hz] (a smaller one is a unit mistake).
  static constexpr double kMinRate = 1e-6;
  /// Appended to "time not strictly increasing": the fix for a rounded time column.
  static constexpr const char* kRateHint =
      " (a time column rounded coarser than the sample period repeats timestamps: rebuild time from the row "
      "index with --rate HZ)";

  const ReadOptions& opt_;
  LogData& out_;
  std::string_view text_;
  const char* cur_ = nullptr;
  const char* end_ = nullptr;
  const char* bad_ = nullptr;  ///< NUL / invalid UTF-8 byte found by next_content_line
  std::size_t line_no_ = 0;
  char sep_ = ',';
  bool decimal_comma_ = false;
  Line header_;
  std::vector<HeaderCell> cells_;
  std::map<std::size_t, Line> unit_line_;  ///< header cell → units row giving its unit
  std::vector<ColumnSpec> cols_;
  std::vector<const char*> delims_;  ///< fast_row: where each field ends
  std::size_t rows_ = 0;         ///< data rows kept
  double last_t_ = -HUGE_VAL;    ///< time of the last kept row [s]
  std::size_t skipped_ = 0;      ///< rows skipped (lenient, time not increasing)
  std::size_t last_skip_line_ = 0;
  std::size_t last_skip_column_ = 0;
  std::size_t first_skip_line_ = 0;     ///< where a refused lenient read fails
  std::size_t first_skip_column_ = 0;
  std::size_t notes_before_skips_ = 0;  ///< notes before the first skip note
  bool time_column_ = false;            ///< a column gives t (with a rate: its start)
  Line first_;                          ///< first data row, parsed by parse_rows_until
  bool have_first_ = false;
  std::size_t fast_misses_ = 0;         ///< consecutive rows fast_row refused
  std::size_t general_rows_ = 0;
  // Streamed reads (LogStream).
  StreamSource* src_ = nullptr;
  std::size_t chunk_rows_ = 0;          ///< rows per chunk
  std::size_t chunk_base_ = 0;          ///< rows kept before this chunk
  char* pin_ = nullptr;                 ///< first data row: the buffer above it never moves
  bool ran_out_ = false;
};

}  // namespace

LogData read_log_from_memory(std::string_view text, std::string path_for_messages, const ReadOptions& options) {
  LogData out;
  out.path = std::move(path_for_messages);
  try {
    std::string converted;  // the text with its head in UTF-8, when it was not
    text = log_text_in_utf8(text, options.encoding, converted);
    Parser parser(text, options, out);
    parser.run();
  } catch (const std::bad_alloc&) {
    out.error = LogError{out.path, 0, 0, "out of memory"};
  }
  if (out.error && (!options.lenient || out.error->line == 0)) {
    out.t.clear();
    for (auto& v : out.values) v.clear();
  }
  return out;
}

LogData read_log(const std::string& path, const ReadOptions& options) {
  LogText text;
  if (std::optional<SourceError> error = load_log_text(path, text)) {
    LogData out;
    out.path = path;
    out.error = std::move(error);
    return out;
  }
  return read_log_from_memory(text.view(), path, options);
}

}  // namespace hstmon::host

// ---- LogStream (log_stream.hpp) -----------------------------------------------------------

#include "hstmon_host/log_stream.hpp"

namespace hstmon::host {

struct LogStream::Impl {
  ReadOptions options;  // the parser keeps a reference
  StreamSource src;
  std::uint64_t size = 0;  // file size [bytes], 0 if unknown
  std::unique_ptr<Parser> parser;

  /// Bytes of the first buffer's complete lines, its head converted to UTF-8 if need be
  /// (a longer head moves the rest of the buffer up; the buffer grows by as much).
  std::size_t first_lines() {
    const char* const buf = src.buf.get();
    std::size_t complete = src.fill;
    if (!src.eof) {
      const void* nl = ::memrchr(buf, '\n', src.fill);
      complete = nl != nullptr ? static_cast<std::size_t>(static_cast<const char*>(nl) - buf) + 1 : 0;
    }
    std::string converted;
    if (log_text_in_utf8(std::string_view(buf, complete), options.encoding, converted).data() != converted.data()) {
      return complete;
    }
    const std::size_t rest = src.fill - complete;
    src.cap += converted.size() - complete;
    std::unique_ptr<char[]> grown(new char[src.cap]);
    std::memcpy(grown.get(), converted.data(), converted.size());
    std::memcpy(grown.get() + converted.size(), buf + complete, rest);
    src.buf = std::move(grown);
    src.fill = converted.size() + rest;
    return converted.size();
  }
};

LogStream::LogStream() = default;
LogStream::~LogStream() = default;

bool LogStream::open(const std::string& path, const ReadOptions& options, std::size_t chunk_rows,
                     std::size_t buffer_bytes) {
  impl_ = std::make_unique<Impl>();
  data_ = LogData{};
  data_.path = path;
  rows_read_ = 0;
  whole_ = false;
  done_ = false;
  Impl& m = *impl_;
  m.options = options;
  const auto read_whole = [&] {
    whole_ = true;
    data_ = read_log(path, options);
    return data_.rows() > 0;
  };
  if (options.lenient || options.rate != 0.0) return read_whole();
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(st)) return read_whole();  // its messages for dirs, pipes, missing files
  if (m.src.text.open(path)) return read_whole();
  m.size = m.src.text.file_size();
  try {
    m.src.cap = std::max<std::size_t>(64, buffer_bytes);
    m.src.buf.reset(new char[m.src.cap]);
    if (!m.src.read_more()) return read_whole();
    const std::size_t complete = m.first_lines();
    m.parser = std::make_unique<Parser>(std::string_view(m.src.buf.get(), complete), m.options, data_, &m.src,
                                        std::max<std::size_t>(1, chunk_rows));
    m.parser->run();
    if (m.parser->ran_out()) {
      m.parser.reset();
      return read_whole();
    }
  } catch (const std::bad_alloc&) {
    data_.error = LogError{path, 0, 0, "out of memory"};
  }
  if (data_.error) {
    data_.t.clear();
    for (auto& v : data_.values) v.clear();
    done_ = true;
    return false;
  }
  return true;
}

bool LogStream::next() {
  if (done_ || impl_ == nullptr) return false;
  if (whole_) {
    done_ = true;
    rows_read_ = data_.rows();
    return data_.rows() > 0;
  }
  Parser& p = *impl_->parser;
  try {
    p.start_chunk();
    const bool more = p.parse_rows_until(p.rows_kept() + p.chunk_rows());
    if (!more) {
      p.finish_rows();
      done_ = true;
    }
  } catch (const std::bad_alloc&) {
    data_.error = LogError{data_.path, 0, 0, "out of memory"};
  }
  if (data_.error) {
    done_ = true;
    data_.t.clear();
    for (auto& v : data_.values) v.clear();
    return false;
  }
  rows_read_ += data_.rows();
  return data_.rows() > 0;
}

double LogStream::fraction() const noexcept {
  if (whole_) return done_ ? 1.0 : 0.0;
  if (impl_ == nullptr || impl_->parser == nullptr || impl_->size == 0) return 0.0;
  // A gzip file: how far into the compressed file (its text size is not known ahead).
  if (impl_->src.text.compressed()) {
    return std::min(1.0, static_cast<double>(impl_->src.text.file_offset()) / static_cast<double>(impl_->size));
  }
  return std::min(1.0, static_cast<double>(impl_->parser->consumed()) / static_cast<double>(impl_->size));
}

}  // namespace hstmon::host
