// `hstmon replay [--circuit FILE] LOG`: prints per-channel residual statistics of a log of
// a circuit (the built-in thesis rig by default) and the monitor's diagnosis.
#include "cli_circuit_replay.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli_circuit_replay_report.hpp"
#include "cli_commands.hpp"
#include "cli_events.hpp"
#include "hstmon_circuit/bound_lead.hpp"
#include "hstmon_circuit/candidate_class.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/replay_outcome.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::cli {

namespace {

using circuit_tools::CandidateClass;
using circuit_tools::CircuitFaultTable;
using circuit_tools::CircuitReplayResult;
using circuit_tools::LoadedCircuit;

const char* start_words(InitialState k) {
  switch (k) {
    case InitialState::kMeasured: return "from the measured state";
    case InitialState::kSteady: return "at steady state (measured states set to their readings)";
    case InitialState::kRest: return "at rest (measured states set to their readings)";
  }
  return "?";
}

// The class of the final candidates, and what would split them (candidate_class.hpp), on
// the matcher's table `table` (nullptr: not built); empty when the matcher did not run or
// ended on no candidates.
CandidateClass final_class(const LoadedCircuit& c, const CircuitReplayResult& r, const CircuitFaultTable* table) {
  if (r.table_rows == 0) return {};
  try {
    return circuit_tools::candidate_class(c, circuit_tools::verdict_candidates(r.events), fdi::signature_fault_tables(),
                                          table);
  } catch (const std::exception&) {
    return {};  // no table at the nominal inputs: the replay's notes say so
  }
}

void print_json(const CircuitReplayArgs& a, const LoadedCircuit& c, const CircuitReplayResult& r,
                const CandidateClass& cls) {
  nlohmann::json head = replay_head_json(a.log, r);
  head["circuit"] = c.file.name;
  head["circuit_file"] = c.file.path;
  head["params_file"] = c.params_path;
  head["fault_table_rows"] = r.table_rows;
  head["undetectable"] = r.undetectable;
  head["states"] = r.states;
  head["stiff_nodes"] = r.stiff_nodes;
  head["implicit_ticks"] = r.implicit_ticks;
  fmt::print("{}\n", head.dump());
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const auto& s = r.channels[ch];
    const host::CircuitSensor& sensor = c.file.sensors[ch];
    nlohmann::json j = {{"type", "residual"},
                        {"channel", sensor.name},
                        {"unit", host::circuit_si_unit(sensor.quantity)},
                        {"measured", static_cast<bool>(r.measured[ch])},
                        {"sensor_noise", sensor.noise},
                        {"clipped_rows", r.clipped[ch]},
                        {"n", s.n}};
    add_residual_stats(j, s);
    fmt::print("{}\n", j.dump());
  }
  nlohmann::json leads = nlohmann::json::array();
  for (std::size_t ch = 0; ch < r.bound_lead.size(); ++ch) {
    const auto& l = r.bound_lead[ch];
    const std::string name = circuit_tools::lead_name(c, l);
    leads.push_back({{"channel", c.file.sensors[ch].name},
                     {"bound", l.bound},
                     {"lead", name.empty() ? nlohmann::json() : nlohmann::json(name)},
                     {"share", l.share}});
  }
  fmt::print("{}\n", nlohmann::json{{"type", "bound"}, {"at", "last row"}, {"channels", leads}}.dump());
  nlohmann::json more = nlohmann::json::object();
  if (!cls.sentence.empty()) {
    more["class"] = cls.description;
    more["split_by"] = cls.split_by.empty() ? nlohmann::json() : nlohmann::json(cls.split_by);
    more["verdict"] = r.final_status + ": " + cls.sentence;
  }
  print_json_diagnosis(r.envelope, r.events, r.table_rows > 0 ? r.final_status : std::string("not_run"), more);
}

void print_human(const CircuitReplayArgs& a, const LoadedCircuit& c, const CircuitReplayResult& r,
                 const CandidateClass& cls) {
  fmt::print("hstmon replay {}\n", a.log);
  fmt::print("  circuit {}{}{}: {} states, {} quasi-steady nodes\n", c.file.name, c.builtin() ? " (built in)" : "",
             c.params_path.empty() ? std::string() : " with " + c.params_path, r.states, r.stiff_nodes);
  fmt::print("  {} rows, t = {:.6g} … {:.6g} s; observer tick {:.3g} ms, {} ticks, started {}\n", r.rows, r.t_first,
             r.t_last, r.tick * 1e3, r.ticks, start_words(r.start));
  for (const auto& n : r.notes) fmt::print("  note: {}\n", n);
  fmt::print("\n  residual = measured − model; noise = scatter estimated from successive samples; σ = the sensor's\n");
  fmt::print("  {:<16} {:>11} {:>11} {:>11} {:>11} {:>11} {:>10}\n", "channel", "mean", "RMS", "noise", "σ", "peak",
             "at t [s]");
  std::string beyond;
  for (std::size_t ch = 0; ch < r.channels.size(); ++ch) {
    const auto& s = r.channels[ch];
    const host::CircuitSensor& sensor = c.file.sensors[ch];
    const host::DisplayUnit d = host::display_unit(sensor.quantity, sensor.unit);
    const double k = d.per_si;
    const std::string label = fmt::format("{} [{}]", sensor.name, d.unit);
    if (!r.measured[ch]) {
      fmt::print("  {:<16} {:>11}\n", label, "not in log");
      continue;
    }
    fmt::print("  {:<16} {:>11.4g} {:>11.4g} {:>11.4g} {:>11.4g} {:>11.4g} {:>10.6g}\n", label, s.mean() * k,
               s.rms() * k, s.noise() * k, sensor.noise * k, s.max_signed * k, s.t_max);
    if (s.n > 1 && std::fabs(s.mean()) > 5.0 * s.noise() + 1e-12) {
      beyond += fmt::format("{}{}{}", beyond.empty() ? "" : ", ", sensor.name, s.mean() > 0 ? "+" : "−");
    }
  }
  if (beyond.empty()) {
    fmt::print("\n  residual means are within the sensor noise on every measured channel\n");
  } else {
    fmt::print("\n  residual means beyond 5× noise: {} (measured above (+) or below (−) the model)\n", beyond);
  }
  if (r.table_rows == 0) {
    fmt::print("\n  diagnosis: not run (no fault table)\n");
  } else {
    fmt::print("\n  fault table: {} hypotheses from the circuit's parameters and sensors (steady-state signs;"
               " slopes and orders from its causal graph)\n",
               r.table_rows);
    if (!r.undetectable.empty()) {
      std::string joined;
      for (const auto& n : r.undetectable) joined += (joined.empty() ? "" : ", ") + n;
      fmt::print("  not detectable at the nominal inputs (no channel moves by 1 sigma at 30 %): {}\n", joined);
    }
    if (const std::string lead = bound_lead_sentence(c, r); !lead.empty()) fmt::print("  {}\n", lead);
    fmt::print("\n  envelope: {}\n", r.envelope.text);
    print_events(r.events, r.final_status);
    if (!cls.sentence.empty()) fmt::print("    verdict: {}: {}\n", r.final_status, cls.sentence);
  }
  print_observer_health(r.health, r.unhealthy_rows, r.max_substeps, r.implicit_ticks);
}

// Measured, model, residual and the matcher's bound on it per row in each sensor's unit
// ("nan" where absent).
std::string write_circuit_residuals(const std::string& path, const LoadedCircuit& c, const CircuitReplayResult& r) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return "cannot open " + path + " for writing";
  std::vector<double> k;
  std::string head = "t[s]";
  for (const host::CircuitSensor& s : c.file.sensors) {
    const host::DisplayUnit d = host::display_unit(s.quantity, s.unit);
    k.push_back(d.per_si);
    head += fmt::format(",{0}[{1}],{0}_hat[{1}],r_{0}[{1}],b_{0}[{1}]", s.name, d.unit);
  }
  head += ",health";
  // After the numbers: per channel the parameter leading its model bound, and its share.
  for (const host::CircuitSensor& s : c.file.sensors) head += fmt::format(",lead_{0},lead_share_{0}[-]", s.name);
  std::fprintf(f, "%s\n", head.c_str());
  for (const auto& tr : r.trace) {
    std::string line = fmt::format("{}", tr.t);
    for (std::size_t ch = 0; ch < k.size(); ++ch) {
      line += fmt::format(",{},{},{},{}", tr.y[ch] * k[ch], tr.y_hat[ch] * k[ch], tr.r[ch] * k[ch], tr.bound[ch] * k[ch]);
    }
    line += fmt::format(",{}", tr.health);
    for (std::size_t ch = 0; ch < k.size(); ++ch) {
      const std::string name = ch < tr.lead.size() ? circuit_tools::lead_name(c, tr.lead[ch]) : std::string();
      line += name.empty() ? std::string(",,nan") : fmt::format(",{},{:.3g}", name, tr.lead[ch].share);
    }
    std::fprintf(f, "%s\n", line.c_str());
  }
  const bool ok = std::ferror(f) == 0;
  return std::fclose(f) == 0 && ok ? std::string() : "write failed: " + path;
}

}  // namespace

circuit_tools::CircuitReplayOptions circuit_replay_options(const CircuitReplayArgs& a) {
  circuit_tools::CircuitReplayOptions o;
  o.tick = a.tick;
  o.init = a.init == "rest"     ? host::InitMode::kRest
           : a.init == "steady" ? host::InitMode::kSteady
                                : host::InitMode::kAuto;
  o.diagnose = a.diagnose;
  o.fit = a.fit;
  o.interpret = a.interpret;
  o.keep_trace = !a.residuals_csv.empty() || !a.plot.empty() || !a.report.empty();
  o.fault_table = fdi::circuit_signature_table;  // the committed headers' table (hstmon-fdi table)
  return o;
}

std::shared_ptr<const CircuitFaultTable> replay_fault_table(const LoadedCircuit& c) {
  try {
    return std::make_shared<const CircuitFaultTable>(fdi::circuit_signature_table(c));
  } catch (const std::exception&) {
    return nullptr;
  }
}

int run_circuit_replay(const CircuitReplayArgs& a) {
  LoadedCircuit c;
  if (auto err = circuit_tools::load_circuit(a.circuit, a.params, c)) {
    fmt::print(stderr, "{}\n", err->to_string());
    return kExitBadInput;
  }
  const circuit_tools::CircuitLog log = circuit_tools::read_circuit_log(a.log, c.file, a.read);
  for (const auto& n : log.notes) fmt::print(stderr, "{}\n", n);
  if (log.error) {
    fmt::print(stderr, "{}\n", log.error->to_string());
    if (!a.read.lenient || log.rows() == 0) return kExitBadInput;
    fmt::print(stderr, "{}: note: --lenient: replaying the {} valid rows before the error\n", a.log, log.rows());
  }
  // A log of another machine: nothing compared is not "within noise".
  if (std::all_of(log.sensors.begin(), log.sensors.end(), [](const auto& col) { return col.empty(); })) {
    std::string columns;
    for (const host::CircuitSensor& s : c.file.sensors) columns += (columns.empty() ? "" : ", ") + s.column;
    fmt::print(stderr,
               "{}: error: none of circuit {}'s sensor columns ({}) is in the log, so nothing can be compared and "
               "nothing is diagnosed; name its columns with --map (e.g. --map {}=P1), or replay it through its own "
               "machine's circuit file with --circuit FILE (docs/circuits.md)\n",
               a.log, c.file.name, columns, c.file.sensors.empty() ? "p_a" : c.file.sensors.front().column);
    return kExitBadInput;
  }
  circuit_tools::CircuitReplayOptions o = circuit_replay_options(a);
  const std::shared_ptr<const CircuitFaultTable> table = a.diagnose ? replay_fault_table(c) : nullptr;
  o.table = table.get();
  const CircuitReplayResult r = circuit_tools::replay_circuit(c, log, o);
  // A run that did not happen has no residuals to report, least of all quiet ones.
  if (const std::string why = circuit_tools::why_not_replayed(r); !why.empty()) {
    fmt::print(stderr, "{}: error: nothing replayed on {}: {}\n", c.file.path, a.log, why);
    return kExitBadInput;
  }
  const CandidateClass cls = a.diagnose ? final_class(c, r, o.table) : CandidateClass{};
  if (a.json) {
    print_json(a, c, r, cls);
  } else {
    print_human(a, c, r, cls);
  }
  // An output that cannot be written is an error, after the others have been written; so
  // is a lenient read that stopped early.
  int code = log.error ? kExitBadInput : kExitOk;
  if (!a.residuals_csv.empty()) {
    if (const std::string err = write_circuit_residuals(a.residuals_csv, c, r); !err.empty()) {
      fmt::print(stderr, "hstmon replay: {}\n", err);
      code = kExitBadInput;
    } else if (!a.json) {
      fmt::print("  residuals written to {}\n", a.residuals_csv);
    }
  }
  ReplayReport report = circuit_replay_report(a, c, r);
  if (log.error) report.read_error = log.error->to_string();
  if (!cls.sentence.empty()) report.verdict_class = cls.sentence;
  if (!write_plot_and_report(a.plot, a.report, report, a.json)) code = kExitBadInput;
  return code;
}

}  // namespace hstmon::cli
