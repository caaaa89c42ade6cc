// hstmon._core.replay: a circuit log through the circuit's monitor (circuit_replay.hpp),
// with the options and the fault table of `hstmon replay --circuit`.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>

#include "binding.hpp"
#include "hstmon_circuit/candidate_class.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/replay_outcome.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::python {

namespace {

using circuit_tools::CircuitReplayResult;

py::dict stats_of(const host::ChannelStats& s) {
  using S = host::ChannelStats;
  py::dict d;
  d["n"] = s.n;
  if (s.n == 0) return d;  // as the CLI: no statistics without samples
  put_fields(d, s, "mean", &S::mean, "rms", &S::rms, "max_abs", &S::max_abs, "max", &S::max_signed, "t_max", &S::t_max,
             "noise", &S::noise);
  return d;
}

py::dict event_of(const host::ReplayEvent& e) {
  using C = host::ReplayCandidate;
  py::list cands;
  for (const C& c : e.candidates) {
    cands.append(dict_of(c, "fault", &C::fault, "score", &C::score, "size", &C::size, "size_lo", &C::size_lo, "size_hi",
                         &C::size_hi, "size_text", &C::size_text));
  }
  using E = host::ReplayEvent;
  py::dict d = dict_of(e, "t", &E::t, "event", &E::event, "consistent", &E::consistent);
  d["candidates"] = cands;
  d["why"] = e.why;
  return d;
}

// Per row and channel, one field of the trace as a rows × channels array.
py::array_t<double> trace_field(const CircuitReplayResult& r, std::size_t channels,
                                std::vector<double> circuit_tools::CircuitTraceRow::*field) {
  py::array_t<double> a({static_cast<py::ssize_t>(r.trace.size()), static_cast<py::ssize_t>(channels)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    const std::vector<double>& v = r.trace[i].*field;
    for (std::size_t ch = 0; ch < channels; ++ch) {
      w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(ch)) = ch < v.size() ? v[ch] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return a;
}

py::dict trace_of(const CircuitReplayResult& r, std::size_t channels) {
  py::array_t<double> t(static_cast<py::ssize_t>(r.trace.size()));
  py::array_t<std::uint32_t> health(static_cast<py::ssize_t>(r.trace.size()));
  auto tw = t.mutable_unchecked<1>();
  auto hw = health.mutable_unchecked<1>();
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    tw(static_cast<py::ssize_t>(i)) = r.trace[i].t;
    hw(static_cast<py::ssize_t>(i)) = r.trace[i].health;
  }
  py::dict d;
  d["t"] = t;
  d["y"] = trace_field(r, channels, &circuit_tools::CircuitTraceRow::y);
  d["y_hat"] = trace_field(r, channels, &circuit_tools::CircuitTraceRow::y_hat);
  d["r"] = trace_field(r, channels, &circuit_tools::CircuitTraceRow::r);
  d["bound"] = trace_field(r, channels, &circuit_tools::CircuitTraceRow::bound);
  d["health"] = health;
  return d;
}

// The replay's result as a dict; `table` the matcher's (nullptr: none was built), which the
// verdict's class reads too.
py::dict result_of(const circuit_tools::LoadedCircuit& c, const CircuitReplayResult& r, bool keep_trace,
                   const circuit_tools::CircuitFaultTable* table) {
  using R = CircuitReplayResult;
  py::dict d = dict_of(r, "rows", &R::rows, "ticks", &R::ticks, "tick", &R::tick, "t_first", &R::t_first, "t_last",
                       &R::t_last, "states", &R::states, "stiff_nodes", &R::stiff_nodes);
  d["start"] = to_string(r.start);
  d["startup_hold"] = r.startup_hold;
  d["health"] = host::health_names(r.health);
  put_fields(d, r, "unhealthy_rows", &R::unhealthy_rows, "max_substeps", &R::max_substeps, "implicit_ticks",
             &R::implicit_ticks, "table_rows", &R::table_rows, "undetectable", &R::undetectable);
  // As the CLI: a replay without a fault table has no diagnosis to report.
  d["status"] = r.table_rows > 0 ? r.final_status : std::string("not_run");
  // As the CLI's diagnosis line: the final candidates' class and what would split them
  // (None when the matcher ended on no candidates).
  circuit_tools::CandidateClass cls;
  if (r.table_rows > 0) {
    try {
      py::gil_scoped_release release;
      cls = circuit_tools::candidate_class(c, circuit_tools::verdict_candidates(r.events),
                                           fdi::signature_fault_tables(), table);
    } catch (const std::exception&) {
      cls = {};
    }
  }
  d["class"] = cls.sentence.empty() ? py::object(py::none()) : py::object(py::str(cls.description));
  d["split_by"] = cls.split_by.empty() ? py::object(py::none()) : py::object(py::str(cls.split_by));
  d["verdict"] = cls.sentence.empty() ? py::object(py::none())
                                      : py::object(py::str(r.final_status + ": " + cls.sentence));
  d["notes"] = r.notes;
  py::list channels;
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const host::CircuitSensor& s = c.file.sensors[ch];
    py::dict row = stats_of(r.channels[ch]);
    row["channel"] = s.name;
    row["unit"] = host::circuit_si_unit(s.quantity);
    row["measured"] = static_cast<bool>(r.measured[ch]);
    row["sensor_noise"] = s.noise;
    row["clipped_rows"] = r.clipped[ch];
    channels.append(row);
  }
  d["channels"] = channels;
  py::list events;
  for (const host::ReplayEvent& e : r.events) events.append(event_of(e));
  d["events"] = events;
  using Env = decltype(r.envelope);
  d["envelope"] = dict_of(r.envelope, "checked", &Env::checked, "out", &Env::out, "unverified", &Env::unverified, "t0",
                          &Env::t0, "t1", &Env::t1, "text", &Env::text);
  py::list leads;  // per channel, what leads its model bound at the last row's inputs
  for (std::size_t ch = 0; ch < r.bound_lead.size(); ++ch) {
    const auto& l = r.bound_lead[ch];
    py::dict row;
    row["channel"] = c.file.sensors[ch].name;
    row["bound"] = l.bound;
    const std::string name = circuit_tools::lead_name(c, l);
    row["lead"] = name.empty() ? py::object(py::none()) : py::object(py::str(name));
    row["share"] = l.share;
    leads.append(row);
  }
  d["bound"] = leads;
  if (keep_trace) d["trace"] = trace_of(r, r.channels.size());
  return d;
}

py::dict replay(const std::shared_ptr<Log>& log, double tick, const std::string& init, bool diagnose, bool fit,
                bool keep_trace) {
  if (!(tick >= 0.0)) throw py::value_error("tick must be >= 0 s (0 = the log's median period, at most 10 ms)");
  circuit_tools::CircuitReplayOptions o;
  o.tick = tick;
  if (init == "auto") {
    o.init = host::InitMode::kAuto;
  } else if (init == "rest") {
    o.init = host::InitMode::kRest;
  } else if (init == "steady") {
    o.init = host::InitMode::kSteady;
  } else {
    throw py::value_error("init must be 'auto', 'rest' or 'steady', not '" + init + "'");
  }
  o.diagnose = diagnose;
  o.fit = fit;
  o.keep_trace = keep_trace;
  o.fault_table = fdi::circuit_signature_table;  // the committed headers' table, as the CLI
  const Circuit& c = *log->circuit;
  CircuitReplayResult r;
  {
    py::gil_scoped_release release;
    if (diagnose) o.table = c.fault_table();
    r = circuit_tools::replay_circuit(c.loaded(), log->data, o);
  }
  if (const std::string why = circuit_tools::why_not_replayed(r); !why.empty()) {
    throw LocatedError(host::SourceError{c.path(), 0, 0, "nothing replayed on " + log->data.path + ": " + why});
  }
  return result_of(c.loaded(), r, keep_trace, o.table);
}

}  // namespace

void bind_replay(py::module_& m) {
  m.def("replay", &replay, py::arg("log"), py::arg("tick") = 0.0, py::arg("init") = "auto", py::arg("diagnose") = true,
        py::arg("fit") = true, py::arg("keep_trace") = false,
        "Replays a log through its circuit's monitor; a dict of the result (SI units)");
  m.def("health_names", &host::health_names, py::arg("flags"), "names of the observer's HealthFlag bits");
}

}  // namespace hstmon::python
