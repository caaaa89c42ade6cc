/// @file circuit_signature_table.cpp
#include "hstmon_fdi/circuit_signature_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hstmon_fdi/circuit_crosscheck.hpp"
#include "hstmon_fdi/circuit_tcg.hpp"
#include "hstmon_fdi/forward.hpp"
#include "hstmon_fdi/qual.hpp"
#include "fault_runs.hpp"

namespace hstmon::fdi {

namespace {

/// The engine's 0+ slope and order of one fault on each channel, at every checked point.
struct EngineReading {
  std::vector<QualSign> slope;
  std::vector<int> order;
};

void append(std::string& to, const std::string& what) { to += (to.empty() ? "" : "; ") + what; }

/// Per channel of c, from one fault's run (fault_runs.hpp): true when the channel's first
/// crossing of every threshold T ≥ σ is on the side `sign` (or it crosses none), i.e. its
/// alarm onset reads `sign` whatever the threshold; false where an opposite excursion is the
/// first to reach some T (an early undershoot, the closed loop's p_c under n_e+). Nothing
/// when the faulted circuit has no steady state (a fault of that size is not one the table
/// describes: circuit_faults.hpp); empty when the run failed.
std::optional<std::vector<bool>> onset_holds(const FaultRun& run, const circuit_tools::LoadedCircuit& c,
                                             const std::vector<std::int8_t>& sign) {
  if (!run.steady) return std::nullopt;
  if (run.failed) return std::vector<bool>{};
  std::vector<bool> holds(sign.size(), true);
  for (std::size_t ch = 0; ch < sign.size() && ch < run.sensors.size(); ++ch) {
    if (sign[ch] != kQualPlus && sign[ch] != kQualMinus) continue;
    const std::vector<double>& y = run.sensors[ch];
    if (y.empty()) continue;
    const double sigma = circuit_tools::sensor_sigma(c.file.sensors[ch]);
    double with = 0.0;  // largest excursion so far on the predicted side [SI]
    for (std::size_t k = 0; k < y.size(); ++k) {
      const double d = (y[k] - y[0]) * (sign[ch] == kQualPlus ? 1.0 : -1.0);
      with = std::max(with, d);
      if (-d > std::max(sigma, with)) {
        holds[ch] = false;
        break;
      }
    }
  }
  return holds;
}

// The engine at each point of default_circuit_cases, one point at a time: fault name → one
// reading per point; `points` the number of points checked (0 when a check fails, noted).
// `faults`: the rows read (empty: every one).
std::map<std::string, std::vector<EngineReading>> engine_readings(const circuit_tools::LoadedCircuit& c,
                                                                  const std::vector<std::string>& faults,
                                                                  std::vector<std::string>& notes,
                                                                  std::size_t& points) {
  std::map<std::string, std::vector<EngineReading>> engine;
  points = 0;
  for (const CircuitCase& cs : default_circuit_cases(c)) {
    CircuitCrosscheckOptions o;
    o.cases = {cs};
    o.max_order = kCircuitTableMaxOrder;
    o.faults = faults;
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
      notes.push_back("engine check at " + cs.name + " failed (" + e.what() + "): slopes left ?");
      points = 0;
      break;
    }
  }
  return engine;
}

// How long the fault transients are simulated [s]: 3 slowest time constants at op (0.2 … 10 s).
double transient_duration(const CircuitOperatingPoint& op) {
  double z0[circuit::kExtent<host::HostCircuitModel::kZ>] = {};
  for (std::size_t k = 0; k < op.z.size() && k < std::size(z0); ++k) z0[k] = op.z[k];
  const double rate = op.model.slowest_rate(op.model.from_z(z0));
  return rate > 0.0 ? std::min(std::max(3.0 / rate, 0.2), 10.0) : 1.0;
}

// The row's slopes and orders from the graph, each slope kept only where every engine reading
// agrees and it is the steady change's sign; why collects the reasons. Whether the engine's
// orders are the graph's everywhere.
bool set_graph_slopes_and_orders(circuit_tools::CircuitFaultTable::Row& row, std::string& why, const CircuitTcg& g,
                                 const std::vector<ParamStep>& steps, const std::vector<EngineReading>& readings,
                                 int channels) {
  const std::vector<ChannelPrediction> q = forward_qualitative_at(g.graph, steps, kCircuitTableMaxOrder, g.measured);
  const std::vector<ChannelPrediction> w = forward_weighted_at(g.graph, steps, kCircuitTableMaxOrder, g.measured);
  bool orders_hold = true;
  for (int i = 0; i < channels; ++i) {
    const auto ch = static_cast<std::size_t>(i);
    ChannelSignature& s = row.channel[i];
    // Opposite paths meeting: the operating-point gains decide, as in the thesis table.
    const QualSign slope = q[ch].order < 0 ? kQualZero : (q[ch].slope == kQualAny ? w[ch].slope : q[ch].slope);
    bool engine_agrees = true;
    for (const EngineReading& e : readings) {
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
  return orders_hold;
}

// The matcher reads the sign at the alarm onset, which the 0+ derivative gives only if
// no opposite excursion reaches a threshold first: the fault `base` (dir ±1) run at 10 %
// and 30 % for `transient` s; a slope that does not hold becomes `?`.
void check_onsets(circuit_tools::CircuitFaultTable::Row& row, std::string& why, const circuit_tools::LoadedCircuit& c,
                  const FaultRuns& runs, const std::string& base, int dir, double transient,
                  const std::vector<std::string>& measured, int channels) {
  std::vector<std::int8_t> sign(static_cast<std::size_t>(channels));
  bool any = false;
  for (int i = 0; i < channels; ++i) {
    sign[static_cast<std::size_t>(i)] = row.channel[i].slope;
    any = any || row.channel[i].slope == kQualPlus || row.channel[i].slope == kQualMinus;
  }
  int simulated = 0;
  for (const double size : {0.1, 0.3}) {
    if (!any) break;
    const std::optional<std::vector<bool>> run = onset_holds(runs(base, 1.0 + dir * size, transient), c, sign);
    if (!run) continue;
    ++simulated;
    const std::vector<bool>& holds = *run;
    for (int i = 0; i < channels; ++i) {
      const auto ch = static_cast<std::size_t>(i);
      if (sign[ch] != kQualPlus && sign[ch] != kQualMinus) continue;
      if (holds.empty() || !holds[ch]) {
        row.channel[i].slope = kQualAny;
        sign[ch] = kQualAny;
        append(why, measured[ch] + (holds.empty() ? " slope: the fault does not simulate" :
                                    " slope: an opposite excursion crosses a threshold first at " +
                                        std::to_string(static_cast<int>(size * 100.0 + 0.5)) + " %"));
      }
    }
  }
  if (any && simulated == 0) {
    for (int i = 0; i < channels; ++i) row.channel[i].slope = kQualAny;
    append(why, "slopes ?: no steady state after a 10 or 30 % fault to simulate towards");
  }
}

// The matcher wants a channel of the row's smallest order among the first to alarm
// (fault_matcher.hpp). That channel is first only if it is also the most visible one;
// otherwise which alarms first depends on the fault's size and the thresholds (the
// thesis's Rbl+ at 100 Hz: w_m is order 1, p_pp order 2 but twice the σ, and alarms first).
// The most visible channel when it is not on the fastest path, else -1.
int most_visible_off_fastest_path(const circuit_tools::CircuitFaultTable::Row& row, int channels) {
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
  return fastest >= 0 && fastest_visible < most_visible ? most : -1;
}

// The slopes and orders of t, c's steady table or some of its rows (`faults`, empty: all),
// each slope's onset checked on the fault runs `runs`.
circuit_tools::CircuitFaultTable with_transients(const circuit_tools::LoadedCircuit& c,
                                                 circuit_tools::CircuitFaultTable t,
                                                 const std::vector<std::string>& faults, const FaultRuns& runs) {
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

  // A point without a steady state checks nothing, and every row then keeps `?` (nothing
  // confirms the graph there).
  std::size_t points = 0;
  const std::map<std::string, std::vector<EngineReading>> engine = engine_readings(c, faults, t.notes, points);
  const double transient = transient_duration(op);
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
    const auto it = engine.find(name);
    const bool checked = points > 0 && it != engine.end() && it->second.size() == points;
    if (!checked) {
      why = "no engine check at every point: slopes ?, orders 0";
      continue;
    }
    bool orders_hold = set_graph_slopes_and_orders(row, why, g, steps, it->second, channels);
    check_onsets(row, why, c, runs, base, dir, transient, g.measured, channels);
    if (!orders_hold) append(why, "orders 0: the engine's differ from the graph's");
    const int most = orders_hold ? most_visible_off_fastest_path(row, channels) : -1;
    if (most >= 0) {
      orders_hold = false;
      append(why, "orders 0: " + g.measured[static_cast<std::size_t>(most)] + ", the most visible channel, is not on the fastest path");
    }
    if (!orders_hold) {
      for (int i = 0; i < channels; ++i) row.channel[i].order = 0;
    }
  }
  return t;
}

FaultRuns simulated_for(const circuit_tools::LoadedCircuit& c) {
  return [&c](const std::string& base, double factor, double duration) {
    return simulate_fault(c, base, factor, duration);
  };
}

}  // namespace

circuit_tools::CircuitFaultTable circuit_signature_table(const circuit_tools::LoadedCircuit& c) {
  return with_transients(c, circuit_tools::circuit_fault_table(c), {}, simulated_for(c));
}

circuit_tools::CircuitFaultTable circuit_signature_rows(const circuit_tools::LoadedCircuit& c,
                                                        const std::vector<std::string>& faults) {
  return with_transients(c, circuit_tools::circuit_fault_rows(c, faults), faults, simulated_for(c));
}

std::vector<std::optional<circuit_tools::CircuitFaultTable>> circuit_signature_tables_with_each(
    const circuit_tools::LoadedCircuit& c, const std::vector<circuit_tools::AddedSensor>& added) {
  std::vector<std::optional<circuit_tools::CircuitFaultTable>> out(added.size());
  const auto n = static_cast<std::size_t>(c.file.circuit.n_channels);
  const auto cap = static_cast<std::size_t>(host::CircuitCap::kChannels);
  const std::size_t room = n < cap ? cap - n : 0;
  // As many added channels as c has room for at a time, their fault runs simulated once.
  for (std::size_t first = 0; room > 0 && first < added.size(); first += room) {
    const std::size_t last = std::min(first + room, added.size());
    circuit_tools::LoadedCircuit all = c;
    for (std::size_t k = first; k < last; ++k) all = circuit_tools::with_added_sensor(all, added[k]);
    SharedFaultRuns shared(std::move(all));
    for (std::size_t k = first; k < last; ++k) {
      std::vector<std::size_t> channels(n + 1);
      for (std::size_t ch = 0; ch < n; ++ch) channels[ch] = ch;
      channels[n] = n + (k - first);
      const auto runs = [&](const std::string& base, double factor, double duration) {
        return shared.run(base, factor, duration, channels);
      };
      const circuit_tools::LoadedCircuit with = circuit_tools::with_added_sensor(c, added[k]);
      try {
        out[k] = with_transients(with, circuit_tools::circuit_fault_table(with), {}, runs);
      } catch (const std::exception&) {
        // no table with this channel: left empty
      }
    }
  }
  return out;
}

circuit_tools::FaultTableBuilders signature_fault_tables() {
  return {circuit_signature_table, circuit_signature_rows, circuit_signature_tables_with_each};
}

}  // namespace hstmon::fdi
