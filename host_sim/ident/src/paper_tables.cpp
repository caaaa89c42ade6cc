/// @file paper_tables.cpp
/// Reader of the paper-rig (kind, label, p, q) tables.
#include "hstmon_ident/paper_tables.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "hstmon_host/units.hpp"

namespace hstmon::ident {

namespace {

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  std::string r = s.substr(a, b - a);
  if (r.size() >= 2 && r.front() == '"' && r.back() == '"') r = r.substr(1, r.size() - 2);
  return r;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == sep) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(trim(cur));
  return out;
}

// "p[bar]" or "p (bar)" → name "p", unit "bar".
void name_unit(const std::string& field, std::string& name, std::string& unit) {
  const auto open = field.find_first_of("[(");
  if (open == std::string::npos) {
    name = lower(trim(field));
    unit.clear();
    return;
  }
  name = lower(trim(field.substr(0, open)));
  const auto close = field.find_first_of("])", open);
  unit = trim(field.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1));
}

}  // namespace

std::optional<double> flow_unit_factor(const std::string& unit) {
  const std::string u = lower(trim(unit));
  if (u.empty() || u == "m3/s" || u == "m^3/s" || u == "m³/s") return 1.0;
  if (u == "l/min" || u == "lpm") return 1e-3 / 60.0;
  if (u == "l/s") return 1e-3;
  if (u == "cm3/s" || u == "cm^3/s" || u == "cc/s" || u == "ml/s") return 1e-6;
  return std::nullopt;
}

PaperTables parse_paper_tables(const std::string& text, const std::string& path) {
  PaperTables t;
  auto fail = [&](std::size_t line, const std::string& msg) {
    t = PaperTables{};
    t.error = host::SourceError{path, line, line ? 1u : 0u, msg};
    return t;
  };
  std::istringstream in(text);
  std::string line;
  std::size_t lineno = 0;
  bool header = false;
  char sep = ',';
  int col_kind = -1, col_label = -1, col_p = -1, col_q = -1;
  double p_factor = 1.0, q_factor = 1.0;
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto hash = line.find('#');
    const std::string body = trim(hash == std::string::npos ? line : line.substr(0, hash));
    if (body.empty()) continue;
    if (!header) {
      sep = body.find('\t') != std::string::npos ? '\t' : body.find(';') != std::string::npos ? ';' : ',';
      const auto fields = split(body, sep);
      for (std::size_t i = 0; i < fields.size(); ++i) {
        std::string name, unit;
        name_unit(fields[i], name, unit);
        const int ci = static_cast<int>(i);
        if (name == "kind") {
          col_kind = ci;
        } else if (name == "label") {
          col_label = ci;
        } else if (name == "p" || name == "dp") {
          col_p = ci;
          const auto u = host::parse_unit(host::Quantity::kPressure, unit);
          if (!u.ok()) return fail(lineno, "column p: " + u.error);
          p_factor = u.conversion.factor;
        } else if (name == "q") {
          col_q = ci;
          const auto f = flow_unit_factor(unit);
          if (!f) return fail(lineno, "column q: unknown flow unit '" + unit + "' (m3/s, l/min, lpm, l/s, cm3/s)");
          q_factor = *f;
        } else {
          return fail(lineno, "unknown column '" + fields[i] + "' (expected kind, label, p, q)");
        }
      }
      if (col_kind < 0 || col_p < 0 || col_q < 0) return fail(lineno, "header must name the columns kind, label, p and q");
      header = true;
      continue;
    }
    const auto f = split(body, sep);
    const std::size_t need = static_cast<std::size_t>(std::max({col_kind, col_label, col_p, col_q})) + 1;
    if (f.size() < need) return fail(lineno, "row has " + std::to_string(f.size()) + " fields, " + std::to_string(need) + " expected");
    auto number = [&](int col, double factor, double& out) {
      const std::string& s = f[static_cast<std::size_t>(col)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || end == nullptr || *end != '\0' || !std::isfinite(v)) return false;
      out = v * factor;
      return true;
    };
    double p = 0.0, q = 0.0;
    if (!number(col_p, p_factor, p)) return fail(lineno, "p is not a finite number: '" + f[static_cast<std::size_t>(col_p)] + "'");
    if (!number(col_q, q_factor, q)) return fail(lineno, "q is not a finite number: '" + f[static_cast<std::size_t>(col_q)] + "'");
    const std::string kind = lower(f[static_cast<std::size_t>(col_kind)]);
    const std::string label = col_label >= 0 ? f[static_cast<std::size_t>(col_label)] : std::string();
    if (kind == "pump") {
      t.pump.push_back({p, q});
    } else if (kind == "dcv" || kind == "prv") {
      if (label.empty()) return fail(lineno, kind + " row without an opening label");
      (kind == "dcv" ? t.dcv : t.prv)[label].push_back({p, q});
    } else {
      return fail(lineno, "unknown kind '" + f[static_cast<std::size_t>(col_kind)] + "' (pump, dcv or prv)");
    }
    ++rows;
  }
  if (!header) return fail(0, "empty file (no header row)");
  if (rows == 0) return fail(0, "no data rows");
  return t;
}

PaperTables read_paper_tables(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    PaperTables t;
    t.error = host::SourceError{path, 0, 0, "cannot open file"};
    return t;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  return parse_paper_tables(ss.str(), path);
}

}  // namespace hstmon::ident
