#include "hstmon_circuit/circuit_log.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "hstmon_host/circuit_units.hpp"
#include "hstmon_host/log_layout.hpp"
#include "hstmon_host/log_options.hpp"
#include "hstmon_host/log_text.hpp"
#include "hstmon_host/number_text.hpp"
#include "hstmon_host/text_encoding.hpp"
#include "hstmon_host/units.hpp"
#include "fast_decimal.hpp"  // ports/host's exact fast path for the numbers loggers write
#include "row_estimate.hpp"  // and its row count for reserving the columns

namespace hstmon::circuit_tools {

namespace {

using host::SourceError;

// What one header column feeds.
struct Target {
  enum Kind { kIgnored, kTime, kInput, kSensor, kUnnamed } kind = kIgnored;  // kUnnamed: a trailing separator's
  int index = -1;
  host::UnitConversion conv;
  std::string name;  ///< the column's name as the header writes it (for messages)
  /// An input's or sensor's column of the log, once it exists (attach_columns): the log's
  /// vectors of columns are never resized, so the pointer stays valid.
  std::vector<double>* dst = nullptr;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

// 1-based character (code point) column of byte offset `off` within `line`.
std::size_t char_column(std::string_view line, std::size_t off) {
  std::size_t col = 1;
  for (std::size_t i = 0; i < off && i < line.size(); ++i) {
    if ((static_cast<unsigned char>(line[i]) & 0xC0u) != 0x80u) ++col;
  }
  return col;
}

// Fields of a line split at sep, with each field's byte offset.
void split(std::string_view line, char sep, std::vector<std::string_view>& fields, std::vector<std::size_t>& offs) {
  fields.clear();
  offs.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t p = line.find(sep, start);
    const std::size_t end = p == std::string_view::npos ? line.size() : p;
    fields.push_back(line.substr(start, end - start));
    offs.push_back(start);
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
}

// "name[unit]", "name (unit)" or "name" (quotes around the whole stripped).
void name_and_unit(std::string_view f, std::string_view& name, std::string_view& unit, bool& has_unit) {
  f = trim(f);
  if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = trim(f.substr(1, f.size() - 2));
  has_unit = false;
  unit = {};
  name = f;
  if (f.empty()) return;
  const char close = f.back();
  const char open = close == ']' ? '[' : (close == ')' ? '(' : '\0');
  if (open == '\0') return;
  const std::size_t p = f.rfind(open);
  if (p == std::string_view::npos || p == 0) return;
  name = trim(f.substr(0, p));
  unit = trim(f.substr(p + 1, f.size() - p - 2));
  has_unit = true;
}

// A number field: blanks around, optional '+', a decimal comma when allowed. errc() when
// it is one, result_out_of_range for a number beyond a double, else invalid_argument.
std::errc parse_number(std::string_view f, bool decimal_comma, double& v) {
  f = trim(f);
  if (!f.empty() && f.front() == '+') f.remove_prefix(1);
  if (f.empty() || f.size() > 64) return std::errc::invalid_argument;
  char buf[65];
  for (std::size_t i = 0; i < f.size(); ++i) buf[i] = (decimal_comma && f[i] == ',') ? '.' : f[i];
  const char* end = buf + f.size();
  const auto r = std::from_chars(buf, end, v);
  if (r.ec == std::errc() && r.ptr != end) return std::errc::invalid_argument;
  return r.ec;
}

// A time: "%.9g" when that is within a nanosecond of it and no exponent (below 1e9 s), else
// the shortest text that reads back as the same number (a logger's Unix time,
// 1700000022.51, not 1.70000002e+09).
std::string format_time(double t) {
  std::string s = host::number_text(t, 9);
  if (std::fabs(t) < 1e9 && std::fabs(std::strtod(s.c_str(), nullptr) - t) <= 1e-9) return s;
  char b[40];
  for (int digits = 10; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, t);
    if (std::strtod(b, nullptr) == t) break;
  }
  return b;
}

bool is_si(const std::string& unit) { return unit.empty() || unit == "-"; }

/// Which lines hold the names and the units, and the separator.
struct Layout {
  std::size_t header_line = 0;  ///< 1-based; 0: not found
  std::size_t units_line = 0;   ///< 0: no units row
  std::vector<host::LogField> unit_fields;
  std::string_view units_text;  ///< the units row, for the columns of its messages
  char sep = ',';
};

// Where the names (and units) are: the first content line, or an instrument's layout
// (log_layout.hpp, the thesis reader's rules): a units row above or below the names, a
// metadata block above them.
Layout find_layout(std::string_view text, const host::ReadOptions& o, CircuitLog& log) {
  Layout lay;
  struct Content {
    std::size_t number;
    std::string_view text;
  };
  std::vector<Content> block;
  std::optional<Content> data;
  std::size_t n = 0, at = 0;
  while (at <= text.size() && block.size() <= host::kMaxPreambleLines) {
    const std::size_t nl = text.find('\n', at);
    std::string_view l = text.substr(at, (nl == std::string_view::npos ? text.size() : nl) - at);
    at = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++n;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    const std::string_view b = trim(l);
    if (b.empty() || b.front() == '#') continue;
    if (host::looks_like_data_row(l)) {
      data = Content{n, l};
      break;
    }
    block.push_back({n, l});
  }
  if (!block.empty()) {
    std::vector<std::string_view> texts;
    for (const Content& line : block) texts.push_back(line.text);
    const std::optional<host::PreambleLayout> layout =
        data ? host::detect_preamble_layout(texts, data->text, o.separator) : std::nullopt;
    std::optional<std::size_t> units;
    std::size_t names = 0;
    if (layout) {
      lay.sep = layout->sep;
      names = layout->names;
      units = layout->units;
      const std::size_t top = layout->metadata();
      if (top > 0) {
        log.notes.push_back(
            log.path + ":" + std::to_string(block[0].number) + ":1: note: " +
            (top == 1 ? "line " + std::to_string(block[0].number)
                      : "lines " + std::to_string(block[0].number) + "-" + std::to_string(block[top - 1].number)) +
            " above the column names taken as metadata, not columns");
      }
    } else {
      lay.sep = o.separator != 0 ? o.separator : host::detect_log_separator(block[0].text);
      // The usual layout with a units row right below the names.
      if (block.size() >= 2 &&
          host::split_log_fields(block[1].text, lay.sep).size() ==
              host::split_log_fields(block[0].text, lay.sep).size() &&
          host::is_text_row(block[1].text, lay.sep, lay.sep != ',')) {
        units = 1;
      }
    }
    lay.header_line = block[names].number;
    if (units) {
      lay.units_line = block[*units].number;
      lay.units_text = block[*units].text;
      lay.unit_fields = host::split_log_fields(lay.units_text, lay.sep);
    }
  }
  return lay;
}

/// The header row: what each column feeds, in which unit; notes for the columns the
/// circuit does not know.
std::optional<SourceError> read_header(std::string_view line, std::size_t line_no, const Layout& lay,
                                       const host::CircuitFile& c, const host::ReadOptions& o, CircuitLog& log,
                                       std::vector<Target>& targets) {
  const std::size_t units_line = lay.units_line;
  const std::vector<host::LogField>& unit_fields = lay.unit_fields;
  const std::string_view units_text = lay.units_text;
  std::vector<std::string_view> fields;
  std::vector<std::size_t> offs;
  split(line, lay.sep, fields, offs);
  if (units_line != 0 && unit_fields.size() != fields.size()) {
    return SourceError{
        log.path, units_line, 1,
        "units row has " + std::to_string(unit_fields.size()) + " fields, the header " + std::to_string(fields.size())};
  }
  for (const auto& [number, to] : o.column_number_map) {
    if (number < 1 || number > fields.size()) {
      return SourceError{
          log.path, line_no, 1,
          "--map #" + std::to_string(number) + ": the header has " + std::to_string(fields.size()) + " columns"};
    }
  }
  targets.assign(fields.size(), Target{});
  std::vector<std::string_view> names;  // for messages about a missing column
  std::vector<bool> map_used(o.column_map.size(), false);
  bool time_seen = false;
  std::size_t ignored = 0, last_ignored_col = 0;  // columns of no input or sensor, noted so far
  std::vector<bool> in_seen(c.inputs.size(), false), s_seen(c.sensors.size(), false);
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (host::is_trailing_empty_column(k, fields.size(), trim(fields[k]))) {
      targets[k].kind = Target::kUnnamed;
      continue;
    }
    std::string_view name, unit;
    bool has_unit = false;
    name_and_unit(fields[k], name, unit, has_unit);
    if (!name.empty()) names.push_back(name);
    const std::string_view header_name = name;  // before a --map renames it
    const std::size_t lead = fields[k].find_first_not_of(" \t");
    const std::size_t col = char_column(line, offs[k] + (lead == std::string_view::npos ? 0 : lead));
    // Where a unit error points: at the unit in the header cell (or in the units row).
    std::size_t unit_line_no = line_no;
    std::size_t unit_col =
        has_unit && !unit.empty() ? char_column(line, static_cast<std::size_t>(unit.data() - line.data())) : col;
    if (units_line != 0) {
      std::string_view u = unit_fields[k].text;
      if (u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')'))) {
        u = trim(u.substr(1, u.size() - 2));
      }
      if (has_unit && !u.empty() && u != unit) {
        return SourceError{log.path, units_line,
                           char_column(units_text, static_cast<std::size_t>(u.data() - units_text.data())),
                           "unit '" + std::string(u) + "' of column '" + std::string(name) + "' differs from '" +
                               std::string(unit) + "' in the header"};
      }
      if (!has_unit && !u.empty()) {
        unit = u;
        has_unit = true;
        unit_line_no = units_line;
        unit_col = char_column(units_text, static_cast<std::size_t>(u.data() - units_text.data()));
      }
    }
    // --map: by column number first, then by name; the target keeps the column's unit.
    std::string mapped;
    bool is_mapped = false;
    if (const auto it = o.column_number_map.find(k + 1); it != o.column_number_map.end()) {
      mapped = it->second;
      is_mapped = true;
    }
    std::size_t m = 0;
    for (const auto& [key, to] : o.column_map) {
      if (host::column_name_matches(key, name)) {
        map_used[m] = true;  // names a column, even where a number entry wins
        if (!is_mapped) mapped = to;
        is_mapped = true;
      }
      ++m;
    }
    if (is_mapped && mapped.empty()) continue;  // dropped on purpose, no note
    if (is_mapped) name = mapped;
    if (name.empty()) return SourceError{log.path, line_no, col, "empty column name in the header"};
    Target& tg = targets[k];
    std::string err;
    if (same_name(name, "t") || same_name(name, "time")) {
      if (time_seen) return SourceError{log.path, line_no, col, "duplicated time column '" + std::string(name) + "'"};
      time_seen = true;
      tg.kind = Target::kTime;
      tg.name = std::string(header_name);
      const host::UnitResult u = host::parse_unit(host::Quantity::kTime, has_unit ? unit : std::string_view("s"));
      if (!u.ok()) return SourceError{log.path, unit_line_no, unit_col, u.error};
      tg.conv = u.conversion;
      continue;
    }
    // The first of channels (c's inputs or sensors, targets of `kind`) whose column this is;
    // seen: the channels that have theirs already.
    auto take_channel = [&](const auto& channels, std::vector<bool>& seen,
                            Target::Kind kind) -> std::optional<SourceError> {
      for (std::size_t i = 0; i < channels.size() && tg.kind == Target::kIgnored; ++i) {
        if (!same_name(name, channels[i].column)) continue;
        if (seen[i]) return SourceError{log.path, line_no, col, "duplicated column '" + std::string(name) + "'"};
        seen[i] = true;
        const host::UnitResult u =
            host::parse_circuit_unit(channels[i].quantity, has_unit ? unit : std::string_view(channels[i].unit));
        if (!u.ok()) {
          return SourceError{log.path, unit_line_no, unit_col,
                             u.error + " in column '" + std::string(header_name) + "'"};
        }
        tg = Target{kind, static_cast<int>(i), u.conversion, std::string(header_name)};
      }
      return std::nullopt;
    };
    if (auto bad = take_channel(c.inputs, in_seen, Target::kInput)) return bad;
    if (auto bad = take_channel(c.sensors, s_seen, Target::kSensor)) return bad;
    // A wide export would list every column: the first few, then a count.
    if (tg.kind == Target::kIgnored && ++ignored <= host::LogNoteRules::kMaxColumnNotes) {
      log.notes.push_back(log.path + ":" + std::to_string(line_no) + ":" + std::to_string(col) + ": note: column '" +
                          std::string(name) + "' is no input or sensor of circuit " + c.name + ": ignored");
    }
    if (tg.kind == Target::kIgnored) last_ignored_col = col;
  }
  if (ignored > host::LogNoteRules::kMaxColumnNotes) {
    log.notes.push_back(log.path + ":" + std::to_string(line_no) + ":" + std::to_string(last_ignored_col) +
                        ": note: " + host::ignored_columns_note(ignored, "inputs or sensors of circuit " + c.name));
  }
  if (!time_seen && !(o.rate > 0.0)) {
    return SourceError{
        log.path, line_no, 1,
        "no time column (t[s]) in the header (or give the sample rate: --rate HZ); " + host::listed_columns(names)};
  }
  std::size_t m = 0;
  for (const auto& entry : o.column_map) {
    if (!map_used[m++]) return SourceError{log.path, line_no, 1, host::unmatched_map_message(entry.first, names)};
  }
  return std::nullopt;
}

// The rows a lenient read skipped (time not strictly increasing): the first few noted,
// then a count (host::LogNoteRules, the rule of every log reader).
struct Skips {
  std::size_t count = 0;
  std::size_t first_line = 0, first_column = 0, last_line = 0, last_column = 0;
  std::size_t notes_before = 0;  // the log's notes before the first skip

  void add(CircuitLog& log, std::size_t line, std::size_t column, const std::string& msg) {
    if (count++ == 0) {
      first_line = line;
      first_column = column;
      notes_before = log.notes.size();
    }
    last_line = line;
    last_column = column;
    if (count > host::LogNoteRules::kMaxSkipNotes) return;
    log.notes.push_back(log.path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": note: " + msg +
                        ": row skipped");
  }

  /// At the end of a read of `total` rows: the error when too many were skipped (set, and
  /// their notes taken back), else the closing count when not every skip had a note.
  std::optional<SourceError> finish(CircuitLog& log, std::size_t total) const {
    if (host::lenient_skips_too_many(count, total)) {
      log.notes.resize(notes_before);  // the error says it; no list of rows
      return SourceError{log.path, first_line, first_column, host::lenient_refusal_message(count, total)};
    }
    if (count > host::LogNoteRules::kMaxSkipNotes) {
      log.notes.push_back(log.path + ":" + std::to_string(last_line) + ":" + std::to_string(last_column) +
                          ": note: " + host::skipped_rows_note(count));
    }
    return std::nullopt;
  }
};

// What becomes of a data row for its time: kept, skipped (a lenient read, the time not
// above the last kept row's: noted) or an error (msg). With o.rate the time is the row
// index's (t0 the first row's logged time). The one rule of the text and column readers.
enum class RowTime { kKeep, kSkip, kFail };

// row_time's rare case, out of the row loop: the time does not rise (t_col: its column).
RowTime time_not_rising(const host::ReadOptions& o, CircuitLog& log, double t, std::size_t line_no, std::size_t t_col,
                        Skips& skipped, std::string& msg) {
  msg = "time not strictly increasing: " + host::number_text(t, 9) + " s after " + host::number_text(log.t.back(), 9) +
        " s (a logger that rounds its time: give the sample rate, --rate HZ)";
  if (!o.lenient) return RowTime::kFail;
  skipped.add(log, line_no, t_col, msg);
  return RowTime::kSkip;
}

// `t_col()` is the time field's column, counted only when the time does not rise
// (counting a text row's characters costs more than the rest of the row).
template <class TimeColumn>
RowTime row_time(const host::ReadOptions& o, CircuitLog& log, double& t, double& t0, std::size_t line_no,
                 const TimeColumn& t_col, Skips& skipped, std::string& msg) {
  if (o.rate > 0.0) {
    // Time from the row index: a rounded or missing time column no longer matters.
    if (log.t.empty() && std::isfinite(t)) t0 = t;
    t = t0 + static_cast<double>(log.t.size()) / o.rate;
    return RowTime::kKeep;
  }
  if (log.t.empty() || t > log.t.back()) return RowTime::kKeep;
  return time_not_rising(o, log, t, line_no, t_col(), skipped, msg);
}

// Each input's and sensor's target given its column of the log, so that a kept row's
// values go straight there.
void attach_columns(std::vector<Target>& targets, CircuitLog& log) {
  for (Target& tg : targets) {
    if (tg.kind == Target::kInput) tg.dst = &log.inputs[static_cast<std::size_t>(tg.index)];
    if (tg.kind == Target::kSensor) tg.dst = &log.sensors[static_cast<std::size_t>(tg.index)];
  }
}

// Room for `rows` rows in the log's time column and the header's input and sensor columns.
void reserve_rows(CircuitLog& log, const std::vector<Target>& targets, std::size_t rows) {
  log.t.reserve(rows);
  for (const Target& tg : targets) {
    if (tg.dst != nullptr) tg.dst->reserve(rows);
  }
}

// A kept row's values (by header column, SI) into the log's columns.
void keep_row(CircuitLog& log, const std::vector<Target>& targets, const std::vector<double>& values, double t) {
  log.t.push_back(t);
  for (std::size_t k = 0; k < targets.size(); ++k) {
    if (targets[k].dst != nullptr) targets[k].dst->push_back(values[k]);
  }
}

// The values of a row that is not kept, taken back (quick_row and row_values append an
// input's or sensor's value as they read it): every such column as long as the time
// column again.
void drop_unkept(CircuitLog& log, const std::vector<Target>& targets) {
  for (const Target& tg : targets) {
    if (tg.dst != nullptr) tg.dst->resize(log.t.size());
  }
}

// A log of circuit c with no rows yet, named `path` in messages.
CircuitLog empty_log(std::string path, const host::CircuitFile& c) {
  CircuitLog log;
  log.path = std::move(path);
  log.inputs.assign(c.inputs.size(), {});
  log.sensors.assign(c.sensors.size(), {});
  return log;
}

// The log failed at line:col: the error set, no rows kept.
CircuitLog failed(CircuitLog& log, std::size_t line, std::size_t col, std::string msg) {
  log.error = SourceError{log.path, line, col, std::move(msg)};
  log.t.clear();
  for (auto& v : log.inputs) v.clear();
  for (auto& v : log.sensors) v.clear();
  return log;
}

/// A data row's time, and where the time field starts (null: no time column) for the
/// messages. Its other values are appended to their columns of the log as they are read
/// (Target::dst), and taken back (drop_unkept) when the row is not kept.
struct RowTimeField {
  double t = NAN;
  const char* t_field = nullptr;
};

/// A bad data row: the 1-based character column of the field, and what is wrong.
struct RowError {
  std::size_t column;
  std::string message;
};

/// True when the separator can never be part of a number fast_decimal reads (a decimal
/// comma is read only where the separator is not ','), so a number that stops at it
/// ends the field there: quick_row may read the rows.
bool quick_rows_possible(char sep) { return sep == ',' || sep == ';' || sep == '\t'; }

/// The common data row in one pass; what it reads is what row_values would. Each number
/// field is one fast_decimal (bit-identical to the std::from_chars that parse_number
/// uses, which is why the fast path may decide alone) from the field's start to its
/// separator, with the blanks and '+' parse_number trims skipped around it; an ignored
/// field is passed over. A field fast_decimal leaves to from_chars (nan, 20 digits), a
/// ragged row, a non-finite value or text in the unnamed last column returns null:
/// nothing decided (what it appended is dropped: drop_unkept), and row_values reads the
/// row and words its message. Otherwise returns the line's end (its '\n', or the text's
/// end), the row's values read as row_values reads them. [p, end): the rest of the text,
/// so fast_decimal's 8-byte loads stay inside it.
const char* quick_row(const char* p, const char* end, const std::vector<Target>& targets, char sep, bool decimal_comma,
                      RowTimeField& row) {
  // trim()'s blanks, never the separator (a tab can be both).
  const auto lead_blank = [sep](char ch) { return (ch == ' ' || ch == '\t') && ch != sep; };
  const auto tail_blank = [sep](char ch) { return (ch == ' ' || ch == '\t' || ch == '\r') && ch != sep; };
  row.t = NAN;
  row.t_field = nullptr;
  // The header's columns through a local pointer: every push_back stores a pointer, which
  // the compiler would otherwise take to maybe change the vector's own.
  const Target* const last = targets.data() + targets.size() - 1;
  const char* f = p;  // the field's start
  for (const Target* tg = targets.data();; ++tg) {
    const char* q = f;  // where the field's text ends
    if (tg->kind == Target::kTime || tg->kind == Target::kInput || tg->kind == Target::kSensor) {
      double v;
      if (!host::detail::fast_decimal(f, end, v, q, decimal_comma)) {
        // Blanks or a '+' before the number: rare, so looked for only now.
        const char* s = f;
        while (s < end && lead_blank(*s)) ++s;
        if (s < end && *s == '+') ++s;
        if (s == f || !host::detail::fast_decimal(s, end, v, q, decimal_comma)) return nullptr;
      }
      v = tg->conv.to_si(v);
      if (!std::isfinite(v)) return nullptr;
      if (tg->kind == Target::kTime) {
        row.t = v;
        row.t_field = f;
      } else {
        tg->dst->push_back(v);
      }
    } else if (tg->kind == Target::kIgnored) {
      while (q < end && *q != sep && *q != '\n') ++q;
    }  // the unnamed column: blanks only, taken next
    if (q == end || *q != sep) {
      while (q < end && tail_blank(*q)) ++q;
      // The line's end after the last field; else fewer fields than the header, or a bad field.
      if (q == end || *q != sep) return tg == last && (q == end || *q == '\n') ? q : nullptr;
    }
    if (tg == last) return nullptr;  // more fields than the header
    f = q + 1;
  }
}

/// Any data row (the line without its '\r'), split at the separator, every field
/// trimmed: its values read (the time into row, the others appended to their columns),
/// or the first bad field (a ragged row first) at its column.
std::optional<RowError> row_values(std::string_view line, const std::vector<Target>& targets, char sep,
                                   std::vector<std::string_view>& fields, std::vector<std::size_t>& offs,
                                   RowTimeField& row) {
  split(line, sep, fields, offs);
  if (fields.size() != targets.size()) {
    const std::size_t off = fields.size() > targets.size() ? offs[targets.size()] : line.size();
    return RowError{char_column(line, off),
                    "row has " + std::to_string(fields.size()) + " fields, the header " + std::to_string(targets.size())};
  }
  // A field's column is counted only for a message.
  const auto col = [&](std::size_t k) { return char_column(line, offs[k]); };
  row.t = NAN;
  row.t_field = nullptr;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const Target& tg = targets[k];
    if (tg.kind == Target::kIgnored) continue;
    if (tg.kind == Target::kUnnamed) {
      if (!trim(fields[k]).empty()) return RowError{col(k), host::kUnnamedValueMessage};
      continue;
    }
    double v = 0.0;
    if (const std::errc ec = parse_number(fields[k], sep != ',', v); ec != std::errc()) {
      return RowError{col(k), host::bad_number_message(trim(fields[k]), tg.name, ec == std::errc::result_out_of_range)};
    }
    const double written = v;
    v = tg.conv.to_si(v);
    if (!std::isfinite(v))
      return RowError{col(k), host::non_finite_message(trim(fields[k]), tg.name, std::isfinite(written))};
    if (tg.kind == Target::kTime) {
      row.t = v;
      row.t_field = line.data() + offs[k];
    } else {
      tg.dst->push_back(v);
    }
  }
  return std::nullopt;
}

// The text as the rows are read: its head in UTF-8 (converted into `storage` when it
// was not), without a BOM. A NUL byte is an error at its place: not a text log.
std::optional<SourceError> text_to_read(std::string_view& text, const host::ReadOptions& o, const std::string& path,
                                        std::string& storage) {
  text = host::log_text_in_utf8(text, o.encoding, storage);
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
      static_cast<unsigned char>(text[2]) == 0xBF) {
    text.remove_prefix(3);
  }
  const std::size_t z = text.find('\0');
  if (z == std::string_view::npos) return std::nullopt;
  std::size_t line = 1, start = 0;
  for (std::size_t i = 0; i < z; ++i) {
    if (text[i] == '\n') {
      ++line;
      start = i + 1;
    }
  }
  return SourceError{path, line, char_column(text.substr(start), z - start), "NUL byte: not a text log"};
}

}  // namespace

CircuitLog read_circuit_log(const std::string& path, const host::CircuitFile& c, const host::ReadOptions& o) {
  host::LogText text;
  if (auto err = host::load_log_text(path, text)) {
    CircuitLog log;
    log.path = path;
    log.error = *err;
    return log;
  }
  return parse_circuit_log(text.view(), path, c, o);
}

CircuitLog parse_circuit_log(std::string_view text, std::string path_for_messages, const host::CircuitFile& c,
                             const host::ReadOptions& o) {
  CircuitLog log = empty_log(std::move(path_for_messages), c);
  auto fail = [&](std::size_t line, std::size_t col, std::string msg) { return failed(log, line, col, std::move(msg)); };
  // A bad data row in a lenient read: reading stops there and the rows before it stay.
  auto stop = [&](std::size_t line, std::size_t col, std::string msg) {
    if (!o.lenient) return fail(line, col, std::move(msg));
    log.error = SourceError{log.path, line, col, std::move(msg)};
    return log;
  };
  Skips skipped;               // rows a lenient read skipped (time not increasing)
  std::size_t data_rows = 0;   // data rows met
  double t0 = 0.0;             // with a rate: the first row's logged time
  std::string converted;       // the text with its head in UTF-8, when it was not
  if (auto e = text_to_read(text, o, log.path, converted)) return fail(e->line, e->column, e->message);

  const Layout lay = find_layout(text, o, log);
  const std::size_t header_line = lay.header_line, units_line = lay.units_line;
  const char sep = lay.sep;

  std::vector<Target> targets;
  bool header_seen = false;
  const bool quick = quick_rows_possible(sep);
  const char* const text_end = text.data() + text.size();
  std::vector<std::string_view> fields;
  std::vector<std::size_t> offs;
  RowTimeField row;
  std::string msg;  // a time that does not rise
  std::size_t line_no = 0, pos = 0;
  while (pos <= text.size()) {
    ++line_no;
    const char* const p = text.data() + pos;
    // The common data row: after the header, not the units row, and starting with neither
    // a blank nor '#' (so neither blank nor a comment).
    const bool quick_line = quick && header_seen && line_no != units_line && p != text_end && *p != ' ' &&
                            *p != '\t' && *p != '#' && *p != '\r' && *p != '\n';
    const char* const eol = quick_line ? quick_row(p, text_end, targets, sep, sep != ',', row) : nullptr;
    if (quick_line && eol == nullptr) drop_unkept(log, targets);  // the general path reads the row again
    std::string_view line;
    if (eol != nullptr) {
      line = std::string_view(p, static_cast<std::size_t>(eol - p));
      pos = eol == text_end ? text.size() + 1 : static_cast<std::size_t>(eol - text.data()) + 1;
    } else {
      const std::size_t nl = text.find('\n', pos);
      line = text.substr(pos, (nl == std::string_view::npos ? text.size() : nl) - pos);
      pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      const std::string_view body = trim(line);
      if (body.empty() || body.front() == '#') continue;

      if (!header_seen && line_no < header_line) continue;  // metadata, or units above the names
      if (line_no == units_line) continue;                   // taken with the header
      if (!header_seen) {
        header_seen = true;
        log.header_line = line_no;
        if (auto e = read_header(line, line_no, lay, c, o, log, targets)) return fail(e->line, e->column, e->message);
        attach_columns(targets, log);
        reserve_rows(log, targets, host::detail::estimate_rows(text.data() + std::min(pos, text.size()), text_end));
        continue;
      }
      if (auto e = row_values(line, targets, sep, fields, offs, row)) {
        drop_unkept(log, targets);
        return stop(line_no, e->column, e->message);
      }
    }
    ++data_rows;
    const auto t_col = [&] {
      return row.t_field ? char_column(line, static_cast<std::size_t>(row.t_field - line.data())) : std::size_t{1};
    };
    const RowTime kept = row_time(o, log, row.t, t0, line_no, t_col, skipped, msg);
    if (kept == RowTime::kFail) return fail(line_no, t_col(), msg);
    if (kept == RowTime::kKeep) log.t.push_back(row.t);
    if (kept == RowTime::kSkip) drop_unkept(log, targets);
  }
  if (!header_seen) return fail(line_no, 1, "empty log: no header row");
  if (log.error) {
    if (log.t.empty()) return fail(log.error->line, log.error->column, log.error->message);
    return log;  // lenient: the rows before the bad one
  }
  if (auto e = skipped.finish(log, data_rows)) return fail(e->line, e->column, e->message);
  if (log.t.empty()) return fail(line_no, 1, "no data rows after the header");
  return log;
}

std::string circuit_log_text(const host::CircuitFile& c, const CircuitLog& log, const std::vector<std::string>& comments) {
  struct Col {
    const std::vector<double>* v;
    host::UnitConversion conv;
  };
  std::vector<Col> cols;
  std::ostringstream os;
  for (const auto& s : comments) os << "# " << s << '\n';
  os << "t[s]";
  auto add = [&](const std::vector<double>& v, host::CircuitQuantity q, const std::string& name, const std::string& unit) {
    if (v.size() != log.t.size() || v.empty()) return;
    const host::UnitResult u = host::parse_circuit_unit(q, unit);
    cols.push_back({&v, u.ok() ? u.conversion : host::UnitConversion{}});
    os << ',' << name;
    if (u.ok() && !is_si(unit)) os << '[' << unit << ']';
  };
  for (std::size_t i = 0; i < c.inputs.size() && i < log.inputs.size(); ++i) {
    add(log.inputs[i], c.inputs[i].quantity, c.inputs[i].column, c.inputs[i].unit);
  }
  for (std::size_t i = 0; i < c.sensors.size() && i < log.sensors.size(); ++i) {
    add(log.sensors[i], c.sensors[i].quantity, c.sensors[i].column, c.sensors[i].unit);
  }
  os << '\n';
  for (std::size_t k = 0; k < log.t.size(); ++k) {
    os << format_time(log.t[k]);
    for (const Col& col : cols) os << ',' << host::number_text(col.conv.from_si((*col.v)[k]), 9);
    os << '\n';
  }
  return os.str();
}

}  // namespace hstmon::circuit_tools

namespace hstmon::circuit_tools {

namespace {

// A header row of `names` for read_header: joined at a separator none of them holds; the
// 1-based character column where each starts (to turn the reader's columns into numbers).
bool header_of(const std::vector<std::string>& names, std::string& line, Layout& lay, std::vector<std::size_t>& starts) {
  for (const char sep : {',', ';', '\t'}) {
    bool clash = false;
    for (const std::string& n : names) clash = clash || n.find(sep) != std::string::npos || n.find('\n') != std::string::npos;
    if (clash) continue;
    lay = Layout{};
    lay.header_line = 1;
    lay.sep = sep;
    line.clear();
    starts.clear();
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (k > 0) line += sep;
      starts.push_back(char_column(line, line.size()));
      line += names[k];
    }
    return true;
  }
  return false;
}

// The 1-based column number of the field at character column `col` of the header row.
std::size_t field_number(const std::vector<std::size_t>& starts, std::size_t col) {
  std::size_t k = 0;
  while (k + 1 < starts.size() && starts[k + 1] <= col) ++k;
  return k + 1;
}

// The header's targets, with every position in its error and notes a column number.
std::optional<SourceError> column_targets(const std::vector<std::string>& names, const host::CircuitFile& c,
                                          const host::ReadOptions& o, CircuitLog& log, std::vector<Target>& targets) {
  std::string line;
  Layout lay;
  std::vector<std::size_t> starts;
  if (!header_of(names, line, lay, starts)) {
    return SourceError{log.path, 1, 1, "every separator (',', ';', tab) occurs in some column name"};
  }
  const std::size_t first_note = log.notes.size();
  std::optional<SourceError> err = read_header(line, 1, lay, c, o, log, targets);
  if (err && err->line == 1) err->column = field_number(starts, err->column);
  const std::string head = log.path + ":1:";
  for (std::size_t i = first_note; i < log.notes.size(); ++i) {
    std::string& n = log.notes[i];
    if (n.compare(0, head.size(), head) != 0) continue;
    const std::size_t colon = n.find(':', head.size());
    if (colon == std::string::npos) continue;
    const std::size_t col = static_cast<std::size_t>(std::strtoul(n.c_str() + head.size(), nullptr, 10));
    n = head + std::to_string(field_number(starts, col)) + n.substr(colon);
  }
  return err;
}

}  // namespace

std::vector<bool> circuit_log_columns_used(const std::vector<std::string>& names, const host::CircuitFile& c,
                                           const host::ReadOptions& o, std::optional<host::SourceError>& error) {
  CircuitLog log;
  std::vector<Target> targets;
  error = column_targets(names, c, o, log, targets);
  std::vector<bool> used;
  if (error) return used;
  for (const Target& tg : targets) {
    used.push_back(tg.kind == Target::kTime || tg.kind == Target::kInput || tg.kind == Target::kSensor);
  }
  return used;
}

CircuitLog circuit_log_from_columns(const std::vector<std::string>& names, const std::vector<const double*>& columns,
                                    std::size_t rows, std::string source, const host::CircuitFile& c,
                                    const host::ReadOptions& o) {
  CircuitLog log = empty_log(std::move(source), c);
  auto fail = [&](std::size_t line, std::size_t col, std::string msg) { return failed(log, line, col, std::move(msg)); };
  std::vector<Target> targets;
  if (auto e = column_targets(names, c, o, log, targets)) return fail(e->line, e->column, e->message);
  log.header_line = 1;  // as in a CSV file of these columns
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const bool used = targets[k].kind == Target::kTime || targets[k].kind == Target::kInput ||
                      targets[k].kind == Target::kSensor;
    if (used && (k >= columns.size() || columns[k] == nullptr)) {
      return fail(1, k + 1, "column '" + names[k] + "' has no values");
    }
  }
  if (rows == 0) return fail(1, 1, "no data rows after the header");
  attach_columns(targets, log);
  reserve_rows(log, targets, rows);
  Skips skipped;
  double t0 = 0.0;
  std::vector<double> values(targets.size(), 0.0);
  for (std::size_t i = 0; i < rows; ++i) {
    const std::size_t line_no = i + 2;  // as in a CSV file of these columns
    double t = NAN;
    std::size_t t_col = 1;
    bool bad = false;
    for (std::size_t k = 0; k < targets.size() && !bad; ++k) {
      const Target& tg = targets[k];
      if (tg.kind != Target::kTime && tg.kind != Target::kInput && tg.kind != Target::kSensor) continue;
      const double v = tg.conv.to_si(columns[k][i]);
      if (!std::isfinite(v)) {
        log.error = SourceError{
            log.path, line_no, k + 1,
            host::non_finite_message(host::number_text(columns[k][i], 9), names[k], std::isfinite(columns[k][i]))};
        bad = true;
        break;
      }
      values[k] = v;
      if (tg.kind == Target::kTime) {
        t = v;
        t_col = k + 1;
      }
    }
    if (bad) {
      if (!o.lenient || log.t.empty()) return fail(log.error->line, log.error->column, log.error->message);
      return log;  // lenient: the rows before the bad one
    }
    std::string msg;
    const RowTime kept = row_time(o, log, t, t0, line_no, [t_col] { return t_col; }, skipped, msg);
    if (kept == RowTime::kFail) return fail(line_no, t_col, msg);
    if (kept == RowTime::kSkip) continue;
    keep_row(log, targets, values, t);
  }
  if (auto e = skipped.finish(log, rows)) return fail(e->line, e->column, e->message);
  return log;
}

}  // namespace hstmon::circuit_tools
