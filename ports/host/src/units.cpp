#include "hstmon_host/units.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "text_util.hpp"

namespace hstmon::host {

namespace {

constexpr double kRpm = 0.10471975511965977;  // 2π/60 rad/s per rev/min
constexpr double kPsi = 6894.757293168;       // Pa per psi

/// One accepted spelling; `exact` spellings must match byte for byte.
struct Spelling {
  std::string_view text;
  double factor;
  bool exact;
};

constexpr Spelling kPressure[] = {
    {"Pa", 1.0, false},   {"hPa", 1e2, false},   {"kPa", 1e3, false},     {"bar", 1e5, false},
    {"psi", kPsi, false}, {"N/m2", 1.0, false},  {"N/m^2", 1.0, false},   {"N/m\xC2\xB2", 1.0, true},
    {"MPa", 1e6, true},   {"mbar", 1e2, true},
};
constexpr Spelling kSpeed[] = {
    {"rad/s", 1.0, false},  {"rpm", kRpm, false},    {"1/min", kRpm, false},
    {"U/min", kRpm, false}, {"r/min", kRpm, false},  {"rev/min", kRpm, false},
    {"min-1", kRpm, false}, {"min^-1", kRpm, false}, {"min\xE2\x81\xBB\xC2\xB9", kRpm, true},
};
constexpr Spelling kTime[] = {
    {"s", 1.0, false}, {"sec", 1.0, false}, {"min", 60.0, false}, {"h", 3600.0, false}, {"ms", 1e-3, true},
};
constexpr Spelling kKpUnits[] = {
    {"m3/(s*Pa^0.5)", 1.0, true},     {"m^3/(s*Pa^0.5)", 1.0, true},
    {"m3/(s*sqrt(Pa))", 1.0, true},   {"m^3/(s*sqrt(Pa))", 1.0, true},
    {"m\xC2\xB3/(s\xC2\xB7\xE2\x88\x9APa)", 1.0, true},  // m³/(s·√Pa)
    {"m\xC2\xB3/(s*\xE2\x88\x9APa)", 1.0, true},          // m³/(s*√Pa)
    {"-", 1.0, true},
};
constexpr Spelling kArea[] = {
    {"m2", 1.0, true},   {"m^2", 1.0, true},   {"m\xC2\xB2", 1.0, true},
    {"mm2", 1e-6, true}, {"mm^2", 1e-6, true}, {"mm\xC2\xB2", 1e-6, true},
};
constexpr Spelling kNoneUnits[] = {{"-", 1.0, true}};

/// What a quantity accepts and how messages name it.
struct Table {
  const Spelling* begin;
  const Spelling* end;
  const char* name;  ///< quantity_name
  const char* si;    ///< si_unit
  const char* hint;  ///< the spellings an error suggests
};

Table table_for(Quantity q) noexcept {
  switch (q) {
    case Quantity::kPressure:
      return {std::begin(kPressure), std::end(kPressure), "pressure", "Pa", "Pa, hPa, kPa, MPa, bar, mbar, psi, N/m2"};
    case Quantity::kSpeed:
      return {std::begin(kSpeed), std::end(kSpeed), "speed", "rad/s", "rad/s, rpm, 1/min, U/min, min-1"};
    case Quantity::kTime:
      return {std::begin(kTime), std::end(kTime), "time", "s", "s, ms, min, h"};
    case Quantity::kKp:
      return {std::begin(kKpUnits), std::end(kKpUnits), "orifice coefficient", "m3/(s*Pa^0.5)",
              "m3/(s*Pa^0.5) or no unit"};
    case Quantity::kArea:
      return {std::begin(kArea), std::end(kArea), "area", "m2", "m2, mm2"};
    case Quantity::kNone:
      break;
  }
  return {std::begin(kNoneUnits), std::end(kNoneUnits), "dimensionless", "", "no unit"};
}

/// `s` without any blanks (so "rad / s" matches "rad/s").
std::string squeeze(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    if (!detail::is_blank(c)) out += c;
  }
  return out;
}

}  // namespace

const char* quantity_name(Quantity q) noexcept { return table_for(q).name; }

const char* si_unit(Quantity q) noexcept { return table_for(q).si; }

UnitResult parse_unit(Quantity q, std::string_view unit) {
  unit = detail::trim(unit);
  UnitResult r;
  const std::string u = squeeze(unit);
  if (u.empty()) return r;
  const Table t = table_for(q);
  for (const Spelling* s = t.begin; s != t.end; ++s) {
    if (s->text == u) {
      r.conversion.factor = s->factor;
      return r;
    }
  }
  bool ambiguous = false;
  for (const Spelling* s = t.begin; s != t.end; ++s) {
    if (!detail::iequals(s->text, u)) continue;
    if (!s->exact) {
      r.conversion.factor = s->factor;
      return r;
    }
    ambiguous = true;
  }
  const std::string lower = detail::ascii_lower(u);
  if (q == Quantity::kPressure && (ambiguous || lower == "mpa" || lower == "mbar")) {
    r.error = "ambiguous pressure unit '" + detail::printable(unit) +
              "': write 'MPa' for megapascal or 'mbar' for millibar";
  } else if (ambiguous) {
    r.error = std::string("ambiguous ") + quantity_name(q) + " unit '" + detail::printable(unit) +
              "' (case matters; use " + t.hint + ")";
  } else {
    r.error = std::string("unknown ") + quantity_name(q) + " unit '" + detail::printable(unit) +
              "' (use " + t.hint + ")";
  }
  return r;
}

ValueResult parse_value_with_unit(Quantity q, std::string_view text) {
  ValueResult r;
  std::string_view s = detail::trim(text);
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc::result_out_of_range) {
    r.error = "number out of range in '" + detail::printable(text) + "'";
    return r;
  }
  if (ec != std::errc()) {
    r.error = "expected a number, optionally followed by a unit, got '" + detail::printable(text) + "'";
    return r;
  }
  const std::string_view unit(ptr, static_cast<std::size_t>(last - ptr));
  const UnitResult u = parse_unit(q, unit);
  if (!u.ok()) {
    r.error = u.error;
    return r;
  }
  r.value = u.conversion.to_si(v);
  if (!std::isfinite(r.value)) {
    r.error = "value is not finite: '" + detail::printable(text) + "'";
    return r;
  }
  return r;
}

}  // namespace hstmon::host
