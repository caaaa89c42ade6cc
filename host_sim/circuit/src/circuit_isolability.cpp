#include "hstmon_circuit/circuit_isolability.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include "hstmon/fault_signature.hpp"

namespace hstmon::circuit_tools {

namespace {

using Row = CircuitFaultTable::Row;
constexpr int kN = Row::kChannels;
constexpr double kParallel = 1.0 - 1e-6;
constexpr double kWeak = 0.98;

// Opposite signs contradict, and so does a structural 0 (the fault cannot move the
// channel at all: its direction there is exactly 0, a leak on a pump's delivery) against a
// ±. A 0 that is only small (below 1σ at 30 %) is what a smaller fault of the other kind
// shows (the matcher's soft rule): it tells nothing apart.
bool consistent(const Row& a, const Row& b) {
  auto sign = [](int m) { return m == kQualPlus || m == kQualMinus; };
  auto structural_zero = [](const Row& r, int i) { return r.channel[i].magnitude == kQualZero && r.direction[i] == 0.0f; };
  for (int i = 0; i < kN; ++i) {
    const int x = a.channel[i].magnitude, y = b.channel[i].magnitude;
    if ((x == kQualPlus && y == kQualMinus) || (x == kQualMinus && y == kQualPlus)) return false;
    if ((structural_zero(a, i) && sign(y)) || (structural_zero(b, i) && sign(x))) return false;
  }
  return true;
}

double cosine(const Row& a, const Row& b) {
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double x = static_cast<double>(a.direction[i]), y = static_cast<double>(b.direction[i]);
    ab += x * y;
    aa += x * x;
    bb += y * y;
  }
  return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : 0.0;
}

// The one channel a row moves, or −1 (none or several).
int only_channel(const Row& r) {
  int ch = -1;
  for (int i = 0; i < kN; ++i) {
    if (r.channel[i].magnitude == kQualZero) continue;
    if (ch >= 0) return -1;
    ch = i;
  }
  return ch;
}

// The steady relation: 0 not isolable, 2 weakly, 1 isolable.
int steady_relation(const Row& a, const Row& b) {
  if (a.sensor || b.sensor) {
    const Row& s = a.sensor ? a : b;
    const Row& f = a.sensor ? b : a;
    if (f.sensor) return 1;  // two sensors: different channels
    const int ch = only_channel(s);
    if (ch < 0) return 1;
    if (only_channel(f) == ch) return 0;
    // The matcher scores a sensor row by the deviation's share on its channel: a fault
    // that moves that channel nearly alone (the closed loop's charge pump on p_c) ranks
    // with the sensor row, its other channels small enough to read as unchanged.
    double norm = 0.0;
    for (int i = 0; i < kN; ++i) norm += static_cast<double>(f.direction[i]) * static_cast<double>(f.direction[i]);
    return norm > 0.0 && std::fabs(static_cast<double>(f.direction[ch])) / std::sqrt(norm) >= kWeak ? 2 : 1;
  }
  if (!consistent(a, b)) return 1;
  const double c = cosine(a, b);
  return c >= kParallel ? 0 : (c >= kWeak ? 2 : 1);
}

// The matcher's responds(): a channel the row lets move.
bool responds(const ChannelSignature& s) { return s.magnitude != kQualZero || s.slope != kQualZero; }

// A row's orders are known unless all are 0 (the table's "any channel may come first").
bool orders_known(const Row& r) {
  if (r.sensor) return false;
  for (int i = 0; i < kN; ++i) {
    if (responds(r.channel[i]) && r.channel[i].order > 0) return true;
  }
  return false;
}

// The table's channels that exist: rows have CircuitCap::kChannels entries, and those past
// the circuit's sensors read "0 magnitude, slope ?, order 0" — which would look like a
// channel every row reaches first. A channel exists where some row has a direction or a
// sensor row its own channel.
using Live = std::array<bool, static_cast<std::size_t>(kN)>;

Live live_channels(const std::vector<Row>& rows) {
  Live live{};
  for (const Row& r : rows) {
    for (int i = 0; i < kN; ++i) {
      live[static_cast<std::size_t>(i)] = live[static_cast<std::size_t>(i)] || r.direction[i] != 0.0f ||
                                          (r.sensor && r.channel[i].magnitude != kQualZero);
    }
  }
  return live;
}

bool slope_known(int q) { return q == kQualPlus || q == kQualMinus || q == kQualZero; }

// A channel whose slope both rows know and on which they differ: the matcher reads the
// sign at the channel's alarm onset, and a predicted 0 drops the row at any alarm there.
bool slopes_split(const Row& a, const Row& b, const Live& live) {
  for (int i = 0; i < kN; ++i) {
    const int x = a.channel[i].slope, y = b.channel[i].slope;
    if (live[static_cast<std::size_t>(i)] && slope_known(x) && slope_known(y) && x != y) return true;
  }
  return false;
}

// Under fault a, b fails the matcher's order test (order_slack 0): none of a's fastest
// responding channels (those that can alarm first) responds for b with b's smallest order
// among the channels that alarm — counted only where a moves them by a ± magnitude, so
// that b_min is one the matcher surely sees. Nothing is claimed when none of a's fastest
// channels has a ± magnitude (which alarms first is then not predicted).
bool order_excludes(const Row& a, const Row& b, const Live& live) {
  auto moves = [](const ChannelSignature& s) { return s.magnitude == kQualPlus || s.magnitude == kQualMinus; };
  auto on = [&](int i) { return live[static_cast<std::size_t>(i)]; };
  int a_min = 255;
  for (int i = 0; i < kN; ++i) {
    if (on(i) && responds(a.channel[i])) a_min = std::min(a_min, static_cast<int>(a.channel[i].order));
  }
  auto first = [&](int i) { return on(i) && responds(a.channel[i]) && a.channel[i].order == a_min; };
  int b_min = 255;
  bool first_moves = false;
  for (int i = 0; i < kN; ++i) {
    first_moves = first_moves || (first(i) && moves(a.channel[i]));
    if (on(i) && moves(a.channel[i]) && responds(b.channel[i])) b_min = std::min(b_min, static_cast<int>(b.channel[i].order));
  }
  if (!first_moves || b_min == 255) return false;
  for (int i = 0; i < kN; ++i) {
    if (first(i) && responds(b.channel[i]) && b.channel[i].order <= b_min) return false;
  }
  return true;
}

bool orders_split(const Row& a, const Row& b, const Live& live) {
  return orders_known(a) && orders_known(b) && (order_excludes(a, b, live) || order_excludes(b, a, live));
}

// SplitBy bits of the pair, and its matrix entry (0 not isolable, 2 weakly, 1 isolable).
std::pair<unsigned, int> relation(const Row& a, const Row& b, SignatureParts parts, const Live& live) {
  const int steady = steady_relation(a, b);
  unsigned bits = steady == 1 ? kSplitSteady : (steady == 2 ? kSplitSteadyWeak : 0u);
  // Sensor rows: the steady rule alone (see the header).
  if (parts == SignatureParts::kFull && !a.sensor && !b.sensor) {
    if (slopes_split(a, b, live)) bits |= kSplitSlope;
    if (orders_split(a, b, live)) bits |= kSplitOrder;
  }
  // Weak only when nothing but the close steady directions tells them apart.
  const int entry = bits == 0 ? 0 : (bits == kSplitSteadyWeak ? 2 : 1);
  return {bits, entry};
}

std::vector<std::vector<std::string>> classes_of(const std::vector<std::string>& names,
                                                  const std::vector<std::vector<int>>& m) {
  const std::size_t n = names.size();
  std::vector<int> label(n, -1);
  std::vector<std::vector<std::string>> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (label[i] >= 0) continue;
    std::vector<std::size_t> stack = {i}, members;
    label[i] = static_cast<int>(out.size());
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      members.push_back(k);
      for (std::size_t j = 0; j < n; ++j) {
        if (label[j] < 0 && m[k][j] == 0) {
          label[j] = label[i];
          stack.push_back(j);
        }
      }
    }
    std::vector<std::string> cls;
    std::sort(members.begin(), members.end());
    for (std::size_t k : members) cls.push_back(names[k]);
    out.push_back(cls);
  }
  std::vector<std::vector<std::string>> big;
  for (auto& c : out) {
    if (c.size() >= 2) big.push_back(std::move(c));
  }
  return big;
}

}  // namespace

Isolability circuit_isolability(const CircuitFaultTable& t, SignatureParts parts) {
  Isolability r;
  const std::size_t n = t.rows.size();
  for (const auto& row : t.rows) r.faults.emplace_back(row.name);
  r.isolable.assign(n, std::vector<int>(n, 1));
  r.split.assign(n, std::vector<unsigned>(n, 0u));
  const Live live = live_channels(t.rows);
  for (std::size_t i = 0; i < n; ++i) {
    r.isolable[i][i] = 0;
    for (std::size_t j = i + 1; j < n; ++j) {
      const auto [bits, entry] = relation(t.rows[i], t.rows[j], parts, live);
      r.isolable[i][j] = r.isolable[j][i] = entry;
      r.split[i][j] = r.split[j][i] = bits;
    }
  }
  r.classes = classes_of(r.faults, r.isolable);
  // A weak pair inside a class says nothing more: the class already joins them (T_L+ and
  // sensor_p_b, both with c_m+ that moves p_b alone).
  auto together = [&](const std::string& a, const std::string& b) {
    for (const auto& cls : r.classes) {
      if (std::find(cls.begin(), cls.end(), a) != cls.end() && std::find(cls.begin(), cls.end(), b) != cls.end()) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (r.isolable[i][j] == 2 && !together(r.faults[i], r.faults[j])) r.weak.emplace_back(r.faults[i], r.faults[j]);
    }
  }
  r.undetectable = t.undetectable;
  return r;
}

std::vector<SensorCandidate> rank_added_sensors(const LoadedCircuit& c, const FaultTableBuilders& build,
                                                SignatureParts parts, const CircuitFaultTable* today_table) {
  const Isolability today = today_table != nullptr ? circuit_isolability(*today_table, parts)
                                                   : circuit_isolability(build.table(c), parts);
  const std::vector<AddedSensor> tries = added_sensors(c);
  const std::vector<std::optional<CircuitFaultTable>> tables = build.with_each_sensor(c, tries);
  std::vector<SensorCandidate> out;
  for (std::size_t t = 0; t < tries.size(); ++t) {
    if (!tables[t]) continue;  // no table with this channel
    const Isolability with = circuit_isolability(*tables[t], parts);
    SensorCandidate sc;
    sc.name = tries[t].name;
    sc.classes = with.classes;
    // A class of today is split when its members are no longer all in one class.
    auto class_of = [&](const std::string& f) -> int {
      for (std::size_t k = 0; k < with.classes.size(); ++k) {
        if (std::find(with.classes[k].begin(), with.classes[k].end(), f) != with.classes[k].end()) return static_cast<int>(k);
      }
      return -1;
    };
    for (const auto& cls : today.classes) {
      std::set<int> where;
      for (const auto& f : cls) where.insert(class_of(f));
      if (where.size() > 1 || where.count(-1) > 0) ++sc.classes_split;
    }
    for (const auto& f : today.undetectable) {
      if (std::find(with.undetectable.begin(), with.undetectable.end(), f) == with.undetectable.end()) ++sc.made_detectable;
    }
    for (const auto& w : today.weak) {
      if (std::find(with.weak.begin(), with.weak.end(), w) == with.weak.end()) ++sc.weak_cleared;
    }
    out.push_back(std::move(sc));
  }
  std::stable_sort(out.begin(), out.end(), [](const SensorCandidate& a, const SensorCandidate& b) {
    if (a.classes_split != b.classes_split) return a.classes_split > b.classes_split;
    if (a.made_detectable != b.made_detectable) return a.made_detectable > b.made_detectable;
    return a.weak_cleared > b.weak_cleared;
  });
  return out;
}

}  // namespace hstmon::circuit_tools
