#include "hstmon_host/log_options.hpp"

#include <charconv>
#include <cstdio>
#include <cmath>
#include <optional>

#include "text_util.hpp"

namespace hstmon::host {

bool column_name_matches(std::string_view key, std::string_view name) noexcept {
  key = detail::trim(key);
  std::size_t i = 0, j = 0;
  while (i < key.size() && j < name.size()) {
    if (detail::is_blank(key[i]) && detail::is_blank(name[j])) {
      while (i < key.size() && detail::is_blank(key[i])) ++i;
      while (j < name.size() && detail::is_blank(name[j])) ++j;
      continue;
    }
    if (!detail::iequals(key.substr(i, 1), name.substr(j, 1))) return false;
    ++i;
    ++j;
  }
  return i == key.size() && j == name.size();
}

std::string add_column_map(ReadOptions& options, std::string_view entry) {
  std::string usage = "takes COLUMN=SIGNAL or '#N=SIGNAL' (e.g. Druck_A=p_mi, '#8=p_pp'), got '" +
                      std::string(entry.substr(0, 60)) + (entry.size() > 60 ? "...'" : "'");
  // The last '=': a Spider8 name such as "p CH=8" holds one itself.
  const std::size_t eq = entry.rfind('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == entry.size()) return usage;
  const std::string_view key = entry.substr(0, eq);
  const std::string target(entry.substr(eq + 1));
  if (key.front() == '#') {
    std::size_t n = 0;
    const std::string_view digits = key.substr(1);
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (digits.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size() || n == 0) {
      return "column number in '" + std::string(key.substr(0, 20)) + "' must be 1 or more (#1 is the first column)";
    }
    options.column_number_map[n] = target;
    return {};
  }
  options.column_map[std::string(key)] = target;
  return {};
}

std::string set_separator(ReadOptions& options, std::string_view text) {
  if (text == "tab" || text == "\\t" || text == "\t") {
    options.separator = '\t';
  } else if (text == "," || text == ";") {
    options.separator = text[0];
  } else {
    return "must be ',', ';' or 'tab', got '" + std::string(text.substr(0, 20)) + "'";
  }
  return {};
}

std::string set_rate(ReadOptions& options, double rate_hz) {
  if (!std::isfinite(rate_hz) || !(rate_hz > 0.0)) return "must be a sample rate in Hz above 0";
  options.rate = rate_hz;
  return {};
}

std::string set_encoding(ReadOptions& options, std::string_view text) {
  const std::optional<TextEncoding> e = text_encoding_from_name(text);
  if (!e) return "must be utf-8, windows-1250, windows-1252 or latin-1, got '" + std::string(text.substr(0, 20)) + "'";
  options.encoding = *e;
  return {};
}

std::string listed_columns(const std::vector<std::string_view>& columns) {
  // A wide export has hundreds of columns: the first few make the point.
  constexpr std::size_t kListed = 24;
  std::string list = "the columns are ";
  for (std::size_t i = 0; i < columns.size() && i < kListed; ++i) {
    list += (i == 0 ? "'" : ", '") + detail::printable(columns[i]) + "'";
  }
  if (columns.size() > kListed) list += ", … (" + std::to_string(columns.size()) + " in all)";
  return list;
}

std::string unmatched_map_message(std::string_view key, const std::vector<std::string_view>& columns) {
  return "column map entry '" + detail::printable(key) + "' matches no column; " + listed_columns(columns);
}

bool lenient_skips_too_many(std::size_t skipped, std::size_t total) noexcept {
  return skipped > LogNoteRules::kFreeSkips && skipped * 100 > LogNoteRules::kMaxSkipPercent * total;
}

std::string lenient_refusal_message(std::size_t skipped, std::size_t total) {
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "time not strictly increasing in %zu of %zu rows (%.0f %%); a lenient read skips at most %zu %% "
                "(a time column rounded coarser than the sample period repeats timestamps: rebuild time from the "
                "row index with --rate HZ)",
                skipped, total, 100.0 * static_cast<double>(skipped) / static_cast<double>(total),
                LogNoteRules::kMaxSkipPercent);
  return msg;
}

std::string skipped_rows_note(std::size_t skipped) {
  return std::to_string(skipped) +
         " rows skipped in all for time not strictly increasing (this is the last; only the "
         "first " +
         std::to_string(LogNoteRules::kMaxSkipNotes) + " have a note of their own)";
}

std::string ignored_columns_note(std::size_t ignored, std::string_view what) {
  return std::to_string(ignored) + " columns in all are not " + std::string(what) + " and ignored (only the first " +
         std::to_string(LogNoteRules::kMaxColumnNotes) + " have a note of their own)";
}

std::string bad_number_message(std::string_view text, std::string_view column, bool out_of_range) {
  const std::string what = out_of_range   ? "number out of range '" + detail::printable(text) + "'"
                           : text.empty() ? std::string("empty field")
                                          : "bad number '" + detail::printable(text) + "'";
  return what + " in column '" + detail::printable(column) + "'";
}

std::string non_finite_message(std::string_view text, std::string_view column, bool written_finite) {
  return (written_finite ? "value out of range after unit conversion '" : "non-finite value '") +
         detail::printable(text) + "' in column '" + detail::printable(column) + "'";
}

}  // namespace hstmon::host
