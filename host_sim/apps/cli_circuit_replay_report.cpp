// Plot and report of a circuit replay (cli_circuit_replay_report.hpp).
#include "cli_circuit_replay_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hstmon_circuit/bound_lead.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::cli {

namespace {

// Narrowest y range shown [display unit]: the sensor's noise, at least, so that a flat
// signal is not drawn as rounding noise (the thesis panels use 0.1 bar and 1 rpm).
double min_span(const host::CircuitSensor& s, double scale) {
  const double floor = s.noise > 0.0 ? 4.0 * s.noise * scale : 0.0;
  return floor > 0.0 && std::isfinite(floor) ? floor : 1e-9;
}

}  // namespace

std::string bound_lead_sentence(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitReplayResult& r) {
  std::string line;
  for (std::size_t ch = 0; ch < r.bound_lead.size() && ch < r.measured.size(); ++ch) {
    if (!r.measured[ch]) continue;
    const host::CircuitSensor& s = c.file.sensors[ch];
    const std::string lead = circuit_tools::lead_text(c, r.bound_lead[ch]);
    line += fmt::format("{}{} ±{}{}", line.empty() ? "" : ", ", s.name,
                        host::display_unit(s.quantity, s.unit).text(r.bound_lead[ch].bound),
                        lead.empty() ? "" : " (" + lead + ")");
  }
  return line.empty() ? line : "model bound at the last row's inputs (the parameter that leads it): " + line;
}

PlotTrace circuit_plot_trace(const circuit_tools::LoadedCircuit& c, const circuit_tools::CircuitReplayResult& r) {
  PlotTrace trace;
  const std::size_t n = r.measured.size();
  for (std::size_t ch = 0; ch < n; ++ch) {
    const host::CircuitSensor& s = c.file.sensors[ch];
    PlotChannel p;
    p.name = s.name;
    const host::DisplayUnit d = host::display_unit(s.quantity, s.unit);
    p.unit = d.unit;
    p.scale = d.per_si;
    p.min_span = min_span(s, p.scale);
    p.measured = r.measured[ch];
    trace.channels.push_back(p);
  }
  set_trace_rows(trace, r, n);
  return trace;
}

ReplayReport circuit_replay_report(const CircuitReplayArgs& a, const circuit_tools::LoadedCircuit& c,
                                   const circuit_tools::CircuitReplayResult& r) {
  ReplayReport rep = replay_report_facts(a.log, r);
  rep.circuit = fmt::format("circuit {} ({}{})", c.file.name, c.file.path,
                            c.params_path.empty() ? std::string() : ", " + c.params_path);
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    ReportChannel rc;
    rc.label = c.file.sensors[ch].name;
    const host::DisplayUnit d = host::display_unit(c.file.sensors[ch].quantity, c.file.sensors[ch].unit);
    rc.unit = d.unit;
    rc.scale = d.per_si;
    rc.measured = r.measured[ch];
    rc.stats = r.channels[ch];
    rep.channels.push_back(rc);
  }
  if (const std::string lead = bound_lead_sentence(c, r); !lead.empty()) rep.notes.push_back(lead);
  rep.diagnosed = a.diagnose && r.table_rows > 0;
  rep.plot = circuit_plot_trace(c, r);
  return rep;
}

}  // namespace hstmon::cli
