/// @file circuit_signature_table.cpp
#include "hstmon_fdi/circuit_signature_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "hstmon_fdi/circuit_crosscheck.hpp"
#include "hstmon_fdi/circuit_tcg.hpp"
#include "hstmon_fdi/forward.hpp"
#include "hstmon_fdi/qual.hpp"

namespace hstmon::fdi {

namespace {

/// The engine's 0+ slope and order of one fault on each channel, at every checked point.
struct EngineReading {
  std::vector<QualSign> slope;
  std::vector<int> order;
};

void append(std::string& to, const std::string& what) { to += (to.empty() ? "" : "; ") + what; }

}  // namespace

circuit_tools::CircuitFaultTable circuit_signature_table(const circuit_tools::LoadedCircuit& c) {
  circuit_tools::CircuitFaultTable t = circuit_tools::circuit_fault_table(c);
  // Without a graph the table stays a steady-state one: a monitor still diagnoses.
  CircuitOperatingPoint op;
  if (const auto err = circuit_operating_point(c, c.values.params, c.values.inputs, op)) {
    t.notes.push_back("no operating point for the causal graph (" + *err + "): slopes ?, orders 0");
    return t;
  }
  CircuitTcg g;
  try {
    g = circuit_tcg(c, op);
  } catch (const std::exception& e) {
    t.notes.push_back(std::string("no causal graph (") + e.what() + "): slopes ?, orders 0");
    return t;
  }
  const std::vector<std::string> on_graph = circuit_graph_faults(g);

  // The engine at each point, one point at a time: a point without a steady state checks
  // nothing, and every row then keeps `?` (nothing confirms the graph there).
  std::map<std::string, std::vector<EngineReading>> engine;  // fault name → one reading per point
  std::size_t points = 0;
  for (const CircuitCase& cs : default_circuit_cases(c)) {
    CircuitCrosscheckOptions o;
    o.cases = {cs};
    o.max_order = kCircuitTableMaxOrder;
    try {
      const CircuitCrosscheck x = run_circuit_crosscheck(c, o);
      ++points;
      for (const CircuitCrosscheckRow& r : x.rows) {
        EngineReading e;
        for (const CircuitChannelCheck& ch : r.channel) {
          e.slope.push_back(ch.slope0);
          e.order.push_back(ch.order0);
        }
        engine[r.fault].push_back(std::move(e));
      }
    } catch (const std::exception& e) {
      t.notes.push_back("engine check at " + cs.name + " failed (" + e.what() + "): slopes left ?");
      points = 0;
      break;
    }
  }

  const int channels = static_cast<int>(c.file.sensors.size());
  t.remarks.assign(t.rows.size(), std::string());
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    auto& row = t.rows[k];
    if (row.sensor) continue;
    const std::string& name = t.names[k];
    const std::string base = name.substr(0, name.size() - 1);
    const int dir = name.back() == '+' ? 1 : -1;
    std::string& why = t.remarks[k];
    bool listed = false;
    for (const std::string& f : on_graph) listed = listed || f == base;
    if (!listed) {
      why = "not on the causal graph at the operating point: slopes ?, orders 0";
      continue;
    }
    const std::vector<ParamStep> steps = circuit_fault_steps(g, base, dir);
    const std::vector<ChannelPrediction> q = forward_qualitative_at(g.graph, steps, kCircuitTableMaxOrder, g.measured);
    const std::vector<ChannelPrediction> w = forward_weighted_at(g.graph, steps, kCircuitTableMaxOrder, g.measured);
    const auto it = engine.find(name);
    const bool checked = points > 0 && it != engine.end() && it->second.size() == points;
    if (!checked) {
      why = "no engine check at every point: slopes ?, orders 0";
      continue;
    }
    bool orders_hold = true;
    for (int i = 0; i < channels; ++i) {
      const auto ch = static_cast<std::size_t>(i);
      ChannelSignature& s = row.channel[i];
      // Opposite paths meeting: the operating-point gains decide, as in the thesis table.
      const QualSign slope = q[ch].order < 0 ? kQualZero : (q[ch].slope == kQualAny ? w[ch].slope : q[ch].slope);
      bool engine_agrees = true;
      for (const EngineReading& e : it->second) {
        engine_agrees = engine_agrees && e.slope[ch] == slope;
        orders_hold = orders_hold && e.order[ch] == q[ch].order;
      }
      if (!engine_agrees) append(why, g.measured[ch] + " slope: the engine's differs from the graph's");
      // A slope promised only where it is the steady change's sign too: a channel the fault
      // moves by less than 1 σ (or by a size-dependent sign) alarms, if at all, on some
      // later part of a transient, whose sign at the threshold is not the 0+ one (the closed
      // loop's Dp±, eps± on p_a, p_c: docs/fdi.md §10).
      s.slope = static_cast<std::int8_t>(engine_agrees && slope == s.magnitude ? slope : kQualAny);
      if (engine_agrees && (slope == kQualPlus || slope == kQualMinus) &&
          (s.magnitude == kQualPlus || s.magnitude == kQualMinus) && slope != s.magnitude) {
        append(why, g.measured[ch] + " slope opposite to the steady change");
      }
      s.order = static_cast<std::uint8_t>(q[ch].order < 0 ? 0 : q[ch].order);
    }
    if (!orders_hold) append(why, "orders 0: the engine's differ from the graph's");
    // The matcher wants a channel of the row's smallest order among the first to alarm
    // (fault_matcher.hpp). That channel is first only if it is also the most visible one;
    // otherwise which alarms first depends on the fault's size and the thresholds (the
    // thesis's Rbl+ at 100 Hz: w_m is order 1, p_pp order 2 but twice the σ, and alarms first).
    int fastest = -1;
    for (int i = 0; i < channels; ++i) {
      const ChannelSignature& s = row.channel[i];
      const bool responds = s.magnitude != kQualZero || s.slope != kQualZero;
      if (responds && (fastest < 0 || s.order < row.channel[fastest].order)) fastest = i;
    }
    float fastest_visible = 0.0f, most_visible = 0.0f;
    int most = -1;
    for (int i = 0; i < channels; ++i) {
      const float d = std::fabs(row.direction[i]);
      if (fastest >= 0 && row.channel[i].order == row.channel[fastest].order) fastest_visible = std::max(fastest_visible, d);
      if (most < 0 || d > most_visible) {
        most = i;
        most_visible = d;
      }
    }
    if (orders_hold && fastest >= 0 && fastest_visible < most_visible) {
      orders_hold = false;
      append(why, "orders 0: " + g.measured[static_cast<std::size_t>(most)] + ", the most visible channel, is not on the fastest path");
    }
    if (!orders_hold) {
      for (int i = 0; i < channels; ++i) row.channel[i].order = 0;
    }
  }
  return t;
}

}  // namespace hstmon::fdi
