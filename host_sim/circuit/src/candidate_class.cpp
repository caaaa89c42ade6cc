#include "hstmon_circuit/candidate_class.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <numeric>
#include <set>

#include "hstmon_circuit/fault_words.hpp"
#include "hstmon_circuit/operating_points.hpp"

namespace hstmon::circuit_tools {

namespace {

// The number of groups n items fall into when `together` joins pairs (its transitive closure).
int count_groups(std::size_t n, const std::function<bool(std::size_t, std::size_t)>& together) {
  std::vector<std::size_t> up(n);
  std::iota(up.begin(), up.end(), std::size_t{0});
  std::function<std::size_t(std::size_t)> root = [&](std::size_t i) { return up[i] == i ? i : up[i] = root(up[i]); };
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (together(i, j)) up[root(i)] = root(j);
    }
  }
  std::set<std::size_t> roots;
  for (std::size_t i = 0; i < n; ++i) roots.insert(root(i));
  return static_cast<int>(roots.size());
}

// Index of the class holding f, or −1 (a class of its own).
int class_of(const std::vector<std::vector<std::string>>& classes, const std::string& f) {
  for (std::size_t k = 0; k < classes.size(); ++k) {
    if (std::find(classes[k].begin(), classes[k].end(), f) != classes[k].end()) return static_cast<int>(k);
  }
  return -1;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

std::vector<std::string> verdict_candidates(const std::vector<host::ReplayEvent>& events) {
  std::vector<std::string> out;
  if (events.empty()) return out;
  const host::ReplayEvent& e = events.back();
  if (e.event != "detected" && e.event != "isolated" && e.event != "ambiguous") return out;
  const std::size_t k = e.event == "isolated" ? std::min<std::size_t>(e.candidates.size(), 1)
                        : std::min(e.candidates.size(), static_cast<std::size_t>(std::max(e.consistent, 1)));
  for (std::size_t i = 0; i < k; ++i) out.push_back(e.candidates[i].fault);
  return out;
}

CandidateClass candidate_class(const LoadedCircuit& c, const std::vector<std::string>& candidates,
                               const FaultTableBuilders& build, const CircuitFaultTable* nominal) {
  CandidateClass r;
  r.candidates = candidates;
  if (candidates.empty()) return r;
  r.description = class_words(c, candidates);
  const std::size_t n = candidates.size();
  if (n == 1) {
    r.groups_now = r.groups_split = 1;
    r.sentence = r.description + ": " + candidates.front();
    return r;
  }
  // The nominal table, built once: the operating points and the sensor placement read it too.
  std::unique_ptr<const CircuitFaultTable> own;
  if (nominal == nullptr) own = std::make_unique<const CircuitFaultTable>(build.table(c));
  const CircuitFaultTable& table = nominal != nullptr ? *nominal : *own;
  const Isolability now = circuit_isolability(table, SignatureParts::kFull);
  std::vector<int> row(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = std::find(now.faults.begin(), now.faults.end(), candidates[i]);
    if (it != now.faults.end()) row[i] = static_cast<int>(it - now.faults.begin());
  }
  auto together_now = [&](std::size_t i, std::size_t j) {
    return row[i] >= 0 && row[j] >= 0 &&
           now.isolable[static_cast<std::size_t>(row[i])][static_cast<std::size_t>(row[j])] != 1;
  };
  r.groups_now = count_groups(n, together_now);
  r.groups_split = r.groups_now;
  if (r.groups_now == static_cast<int>(n)) {
    r.split_by = "more settled data at a steady operating point";
  } else {
    // A change of operating point: the pairs it splits among the candidates.
    const OperatingPointSplit op = split_by_operating_point(c, build, SignatureParts::kFull, candidates, &table);
    auto split_elsewhere = [&](std::size_t i, std::size_t j) {
      for (const auto& p : op.pairs) {
        if ((p.first == candidates[i] && p.second == candidates[j]) ||
            (p.first == candidates[j] && p.second == candidates[i])) {
          return true;
        }
      }
      return false;
    };
    const int groups_op =
        count_groups(n, [&](std::size_t i, std::size_t j) { return together_now(i, j) && !split_elsewhere(i, j); });
    // The single added channel that splits them into the most groups.
    int groups_sensor = r.groups_now;
    std::string best_sensor;
    for (const SensorCandidate& s : rank_added_sensors(c, build, SignatureParts::kFull, &table)) {
      const int g = count_groups(n, [&](std::size_t i, std::size_t j) {
        const int ci = class_of(s.classes, candidates[i]);
        return together_now(i, j) && ci >= 0 && ci == class_of(s.classes, candidates[j]);
      });
      if (g > groups_sensor) {
        groups_sensor = g;
        best_sensor = s.name;
      }
    }
    if (groups_op > r.groups_now && groups_op >= groups_sensor) {
      std::vector<std::string> where;
      for (std::size_t k = 0; k < op.pairs.size(); ++k) {
        if (std::find(where.begin(), where.end(), op.where[k]) == where.end()) where.push_back(op.where[k]);
      }
      if (where.size() > 2) where.resize(2);
      r.split_by = "a change of operating point (" + joined(where) + ")";
      r.groups_split = groups_op;
    } else if (groups_sensor > r.groups_now) {
      r.split_by = added_sensor_words(best_sensor);
      r.groups_split = groups_sensor;
    } else {
      r.split_by = "nothing in reach";
    }
  }
  std::string tail;
  if (r.split_by == "nothing in reach") {
    tail = "nothing in reach tells them apart: no single added sensor, no change of operating point";
  } else {
    tail = r.split_by + (r.groups_split == static_cast<int>(n) ? " would tell them apart" : " would tell some of them apart");
  }
  r.sentence = r.description + ": " + joined(candidates) + " (" + tail + ")";
  return r;
}

}  // namespace hstmon::circuit_tools
