#include "hstmon_host/log_layout.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <iterator>
#include <system_error>

#include "hstmon_host/units.hpp"
#include "text_util.hpp"

namespace hstmon::host {

namespace {

using detail::trim;

/// Largest field looked at as a number (longer fields are not numbers).
constexpr std::size_t kMaxNumberField = 64;

/// Strips surrounding double quotes from a trimmed field.
std::string_view unquote(std::string_view s) noexcept {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return trim(s.substr(1, s.size() - 2));
  return s;
}

}  // namespace

std::vector<LogField> split_log_fields(std::string_view line, char sep) {
  std::vector<LogField> out;
  const char* f = line.data();
  const char* const end = line.data() + line.size();
  for (;;) {
    const auto* s = static_cast<const char*>(std::memchr(f, sep, static_cast<std::size_t>(end - f)));
    const char* fe = s != nullptr ? s : end;
    out.push_back({unquote(trim(std::string_view(f, static_cast<std::size_t>(fe - f)))), f});
    if (s == nullptr) break;
    f = s + 1;
  }
  return out;
}

bool log_field_is_number(std::string_view s, bool decimal_comma) noexcept {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.size() > kMaxNumberField) return false;
  char buf[kMaxNumberField];
  std::memcpy(buf, s.data(), s.size());
  if (decimal_comma) std::replace(buf, buf + s.size(), ',', '.');
  double v;
  const auto r = std::from_chars(buf, buf + s.size(), v);
  return r.ec == std::errc() && r.ptr == buf + s.size();
}

char detect_log_separator(std::string_view header) noexcept {
  if (header.find('\t') != std::string_view::npos) return '\t';
  if (header.find(';') != std::string_view::npos) return ';';
  return ',';
}

bool is_trailing_empty_column(std::size_t index, std::size_t count, std::string_view cell) noexcept {
  return count >= 2 && index + 1 == count && cell.empty();
}

bool looks_like_data_row(std::string_view line) noexcept {
  bool digit = false;
  for (const char c : line) {
    if (c >= '0' && c <= '9') {
      digit = true;
    } else if (std::strchr(".,;+-eE \t", c) == nullptr || c == '\0') {
      return false;
    }
  }
  return digit;
}

bool is_text_row(std::string_view line, char sep, bool decimal_comma) {
  bool any = false;
  for (const LogField& f : split_log_fields(line, sep)) {
    if (f.text.empty()) continue;
    if (log_field_is_number(f.text, decimal_comma)) return false;
    any = true;
  }
  return any;
}

std::size_t unit_score(std::string_view line, char sep) {
  static constexpr std::string_view kOther[] = {"V", "mV", "A", "mA", "°C", "degC", "K", "l/min", "L/min",
                                                "N", "kN", "Nm", "mm", "m", "%", "Hz", "kg", "g"};
  std::size_t score = 0;
  for (const LogField& f : split_log_fields(line, sep)) {
    std::string_view u = f.text;
    if (u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')'))) {
      u = trim(u.substr(1, u.size() - 2));
    }
    if (u.empty() || u == "-") continue;
    bool known = std::find(std::begin(kOther), std::end(kOther), u) != std::end(kOther);
    for (Quantity q : {Quantity::kPressure, Quantity::kSpeed, Quantity::kTime, Quantity::kArea, Quantity::kKp}) {
      known = known || parse_unit(q, u).ok();
    }
    if (known) ++score;
  }
  return score;
}

std::optional<PreambleLayout> detect_preamble_layout(const std::vector<std::string_view>& block, std::string_view data,
                                                     char sep_option) {
  const std::size_t n = block.size();
  if (n < 2) return std::nullopt;
  PreambleLayout l;
  l.sep = sep_option != 0 ? sep_option : detect_log_separator(block.back());
  l.decimal_comma = l.sep != ',';
  const std::vector<LogField> data_fields = split_log_fields(data, l.sep);
  for (const LogField& f : data_fields) {
    if (!log_field_is_number(f.text, l.decimal_comma)) return std::nullopt;
  }
  // A names or units row: one field per data field, none of them a number.
  const auto fits = [&](std::string_view line) {
    return split_log_fields(line, l.sep).size() == data_fields.size() && is_text_row(line, l.sep, l.decimal_comma);
  };
  if (!fits(block[n - 1])) return std::nullopt;
  const bool pair = fits(block[n - 2]);
  const std::size_t score_last = unit_score(block[n - 1], l.sep);
  const std::size_t score_prev = pair ? unit_score(block[n - 2], l.sep) : 0;
  l.names = n - 1;
  if (pair && score_prev > score_last) {
    l.units = n - 2;  // units above the names
  } else if (n == 2) {
    return std::nullopt;  // names first: the usual layout
  } else if (pair && score_last > score_prev) {
    l.names = n - 2;
    l.units = n - 1;
  }
  return l;
}

}  // namespace hstmon::host
