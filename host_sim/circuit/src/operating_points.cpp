#include "hstmon_circuit/operating_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

namespace hstmon::circuit_tools {

namespace {

// A ratio of two responses that changes by more than this between two points is a split.
constexpr double kScaleSplit = 1.25;

// Where one row stands at one point: its index in that point's table.
using RowIndex = std::map<std::string, std::size_t>;

RowIndex index_rows(const CircuitFaultTable& t) {
  RowIndex ix;
  for (std::size_t k = 0; k < t.names.size(); ++k) ix[t.names[k]] = k;
  return ix;
}

// One point's table with what the pair test reads: its own, or the caller's nominal one.
struct PointTable {
  std::string name;
  std::unique_ptr<const CircuitFaultTable> own;
  const CircuitFaultTable* table = nullptr;
  Isolability iso;
  RowIndex rows;
};

// The signed ratio of two parameter rows' responses (their 10 % steady residuals as
// lengths along their directions, of one sign when those agree); NaN when it is unknown
// (a sensor row, no gains, or a zero response).
double response_ratio(const PointTable& p, std::size_t a, std::size_t b) {
  const CircuitFaultTable& t = *p.table;
  if (t.rows[a].sensor || t.rows[b].sensor || t.gains.size() != t.rows.size()) return std::nan("");
  const double ga = t.gains[a], gb = t.gains[b];
  if (!(ga > 0.0) || !(gb > 0.0)) return std::nan("");
  double dot = 0.0;
  for (int i = 0; i < CircuitFaultTable::Row::kChannels; ++i) {
    dot += static_cast<double>(t.rows[a].direction[i]) * static_cast<double>(t.rows[b].direction[i]);
  }
  return (dot < 0.0 ? -1.0 : 1.0) * ga / gb;
}

// Does point p split the pair (a, b) that the nominal point n does not?
bool splits(const PointTable& n, const PointTable& p, const std::string& a, const std::string& b) {
  const auto pa = p.rows.find(a), pb = p.rows.find(b);
  // One shows there, the other cannot (undetectable at that point).
  auto silent = [&](const std::string& f) {
    return std::find(p.table->undetectable.begin(), p.table->undetectable.end(), f) != p.table->undetectable.end();
  };
  if ((pa != p.rows.end() && silent(b)) || (pb != p.rows.end() && silent(a))) return true;
  if (pa == p.rows.end() || pb == p.rows.end()) return false;
  if (p.iso.isolable[pa->second][pb->second] == 1) return true;
  const double r0 = response_ratio(n, n.rows.at(a), n.rows.at(b));
  const double r1 = response_ratio(p, pa->second, pb->second);
  if (!std::isfinite(r0) || !std::isfinite(r1)) return false;
  const double q = r1 / r0;
  return q <= 0.0 || q > kScaleSplit || q < 1.0 / kScaleSplit;
}

}  // namespace

std::vector<OperatingPoint> operating_points(const LoadedCircuit& c) {
  std::vector<OperatingPoint> out;
  out.push_back({"nominal", c.values.inputs});
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    const double u = c.values.inputs.v[i];
    if (u == 0.0) continue;
    const host::CircuitInput& in = c.file.inputs[i];
    const bool fraction = in.quantity == host::CircuitQuantity::kFraction;
    for (const double f : {0.5, 1.5}) {
      OperatingPoint p{in.name + (f < 1.0 ? " 50 %" : " 150 %"), c.values.inputs};
      p.inputs.v[i] = fraction && std::fabs(u) <= 1.0 ? std::clamp(u * f, -1.0, 1.0) : u * f;
      if (p.inputs.v[i] != u) out.push_back(p);
    }
    if (fraction) {
      OperatingPoint p{in.name + " reversed", c.values.inputs};
      p.inputs.v[i] = -u;
      out.push_back(p);
    }
  }
  // The drive the other way: every fraction and every torque reversed together (a load
  // that opposes the motion turns with it), so the other line carries the load.
  OperatingPoint back{"", c.values.inputs};
  bool fractions = false, torques = false;
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    const host::CircuitQuantity q = c.file.inputs[i].quantity;
    if (c.values.inputs.v[i] == 0.0 || (q != host::CircuitQuantity::kFraction && q != host::CircuitQuantity::kTorque)) continue;
    back.name += (back.name.empty() ? "" : " and ") + c.file.inputs[i].name;
    back.inputs.v[i] = -c.values.inputs.v[i];
    fractions = fractions || q == host::CircuitQuantity::kFraction;
    torques = torques || q == host::CircuitQuantity::kTorque;
  }
  if (fractions && torques) {
    back.name += " reversed";
    out.push_back(back);
  }
  return out;
}

OperatingPointSplit split_by_operating_point(const LoadedCircuit& c, const FaultTableBuilders& build,
                                             SignatureParts parts, const std::vector<std::string>& only,
                                             const CircuitFaultTable* nominal) {
  OperatingPointSplit out;
  // Only the rows judged: a pair's relation reads its two rows alone (the sensor rows,
  // always built, keep which channels exist).
  auto table_at = [&](const LoadedCircuit& at) {
    return std::make_unique<const CircuitFaultTable>(only.empty() ? build.table(at) : build.rows(at, only));
  };
  std::vector<PointTable> tables;
  for (const OperatingPoint& op : operating_points(c)) {
    LoadedCircuit at = c;
    at.values.inputs = op.inputs;
    PointTable p;
    p.name = op.name;
    if (tables.empty()) {
      if (nominal == nullptr) p.own = table_at(at);  // the nominal point: its error is the caller's
    } else {
      try {
        p.own = table_at(at);
      } catch (const std::exception&) {
        continue;  // no steady state there
      }
    }
    p.table = p.own != nullptr ? p.own.get() : nominal;
    p.iso = circuit_isolability(*p.table, parts);
    p.rows = index_rows(*p.table);
    out.points.push_back(p.name);
    tables.push_back(std::move(p));
  }
  const PointTable& n = tables.front();
  const std::set<std::string> wanted(only.begin(), only.end());
  for (std::size_t i = 0; i < n.table->names.size(); ++i) {
    for (std::size_t j = i + 1; j < n.table->names.size(); ++j) {
      const std::string &a = n.table->names[i], &b = n.table->names[j];
      if (n.iso.isolable[i][j] == 1) continue;
      if (!wanted.empty() && (wanted.count(a) == 0 || wanted.count(b) == 0)) continue;
      for (std::size_t k = 1; k < tables.size(); ++k) {
        if (!splits(n, tables[k], a, b)) continue;
        out.pairs.emplace_back(a, b);
        out.where.push_back(tables[k].name);
        break;
      }
    }
  }
  // The classes left: union of the nominal not-isolable pairs that no point splits.
  const std::size_t rows = n.table->names.size();
  std::vector<std::size_t> up(rows);
  for (std::size_t i = 0; i < rows; ++i) up[i] = i;
  auto root = [&](std::size_t i) {
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
  };
  std::set<std::pair<std::string, std::string>> split(out.pairs.begin(), out.pairs.end());
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = i + 1; j < rows; ++j) {
      if (n.iso.isolable[i][j] != 0 || split.count({n.table->names[i], n.table->names[j]}) > 0) continue;
      if (!wanted.empty() && (wanted.count(n.table->names[i]) == 0 || wanted.count(n.table->names[j]) == 0)) continue;
      up[root(i)] = root(j);
    }
  }
  std::map<std::size_t, std::vector<std::string>> by_root;
  for (std::size_t i = 0; i < rows; ++i) by_root[root(i)].push_back(n.table->names[i]);
  for (auto& entry : by_root) {
    if (entry.second.size() >= 2) out.classes.push_back(std::move(entry.second));
  }
  return out;
}

}  // namespace hstmon::circuit_tools
