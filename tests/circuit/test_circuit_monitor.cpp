// The monitor of any circuit (circuit::CircuitMonitor through hstmon replay --circuit's
// code, circuit_replay.cpp) on data the monitor did not make: logs of host_sim's
// Rosenbrock-4 reference of the full equations with the sensors' noise.
//  - Nominal runs of every shipped circuit — shipped logs, starts from rest, input steps —
//    raise no event.
//  - A parameter fault is detected after it happens and never before, and the true fault
//    is in the reported set (the paper's HST, the test stand, the thesis rig).
//  - thesis.json through the engine gives the demo log the thesis monitor's diagnosis:
//    detected at 80.03 s, kp− isolated at 80.18 s.
//  - The generated table names its rows after the circuit's parameters and inputs.
//  - A fault silent until a later load is isolated by when it can have begun.
// The replays whose expectations read the candidates run on the table `hstmon replay
// --circuit` builds (fdi::circuit_signature_table: the steady signs and directions with the
// causal graph's slopes and orders); the nominal ones on the default steady-state table, which
// gives the same detections (the table is read only after one) at a fraction of the cost in
// Debug builds (the CLI's table simulates every fault: 6 s for closed_loop_hst at -O0).
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "../support/loaded_circuit.hpp"
#include "../support/mem_log.hpp"
#include "../support/sim_options.hpp"
#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/circuit_monitor.hpp"
#include "hstmon/circuit/monitor_setup.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/circuit_replay.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"
#include "hstmon_host/log_reader.hpp"
#include "../support/replay_events.hpp"

namespace {

using hstmon_test::event_lines;

namespace ct = hstmon::circuit_tools;

std::string example(const std::string& file) { return std::string(HSTMON_SOURCE_DIR) + "/examples/" + file; }

ct::LoadedCircuit load(const std::string& name) { return hstmon_test::load_example(name); }

// The CLI's replay options: its table, built once per circuit and test process.
ct::CircuitReplayOptions cli_options(const ct::LoadedCircuit& c) {
  static std::map<std::string, ct::CircuitFaultTable> built;  // rows point into their own names: never copied
  auto it = built.find(c.file.name);
  if (it == built.end()) it = built.emplace(c.file.name, hstmon::fdi::circuit_signature_table(c)).first;
  ct::CircuitReplayOptions o;
  o.table = &it->second;
  return o;
}

ct::InputStep step(const ct::LoadedCircuit& c, const std::string& text, bool fault) {
  ct::InputStep st;
  const auto err = fault ? ct::parse_param_fault(text, c.file, st) : ct::parse_input_step(text, c.file, st);
  EXPECT_FALSE(err.has_value()) << *err;
  return st;
}

// A 5 s run at 1 kHz (seed 4) of a machine whose motor displacement Dm is dm_factor × the
// file's, with these steps: {text, true} a parameter fault, {text, false} an input step.
ct::CircuitLog run_with_motor(const ct::LoadedCircuit& c, double dm_factor,
                              std::initializer_list<std::pair<const char*, bool>> steps) {
  ct::LoadedCircuit m = c;
  m.values.params.v[c.file.param_index("Dm")] *= dm_factor;
  ct::CircuitSimOptions o = hstmon_test::sim_options(5.0, 1000.0, 4);
  for (const auto& [text, fault] : steps) o.steps.push_back(step(c, text, fault));
  return ct::simulate_circuit(m, o);
}

// Adds `offset` [SI] to sensor `name`'s readings from t0 [s] on; false when the log does not read it.
bool add_offset(const ct::LoadedCircuit& c, const char* name, double t0, double offset, ct::CircuitLog& log) {
  const int ch = c.file.sensor_index(name);
  if (ch < 0 || static_cast<std::size_t>(ch) >= log.sensors.size()) return false;
  std::vector<double>& y = log.sensors[static_cast<std::size_t>(ch)];
  if (y.size() != log.rows()) return false;
  for (std::size_t k = 0; k < log.rows(); ++k) {
    if (log.t[k] >= t0) y[k] += offset;
  }
  return true;
}

// A simulated run through the log text, as hstmon replay --circuit reads it.
ct::CircuitReplayResult simulate_and_replay(const ct::LoadedCircuit& c, ct::CircuitSimOptions o,
                                           const ct::CircuitReplayOptions& replay = {}) {
  const ct::CircuitLog log = ct::simulate_circuit(c, o);
  const ct::CircuitLog back = ct::parse_circuit_log(ct::circuit_log_text(c.file, log), "sim.csv", c.file);
  EXPECT_TRUE(back.ok());
  return ct::replay_circuit(c, back, replay);
}

TEST(CircuitMonitor, ShippedLogsRaiseNoEvent) {
  for (const char* name : {"paper", "closed_loop_hst", "test_stand"}) {
    const ct::LoadedCircuit c = load(name);
    const ct::CircuitLog log = ct::read_circuit_log(example(std::string("circuits/") + name + ".csv"), c.file);
    ASSERT_TRUE(log.ok());
    const ct::CircuitReplayResult r = ct::replay_circuit(c, log, {});
    EXPECT_GT(r.table_rows, c.file.sensors.size()) << name << ": parameter rows besides the sensor rows";
    EXPECT_TRUE(r.events.empty()) << name << "\n" << event_lines(r);
    EXPECT_EQ(r.final_status, "nominal") << name;
  }
}

struct Nominal {
  const char* name;
  bool from_rest;
  std::vector<std::string> steps;
  double rate;
};

TEST(CircuitMonitor, StartsAndInputStepsRaiseNoEvent) {
  const Nominal cases[] = {
      {"paper", true, {"A_dcv=4 mm2@3", "A_prv=2.5 mm2@6"}, 1000.0},
      {"paper", false, {"A_prv=3 mm2@2", "A_prv=4 mm2@5"}, 100.0},
      {"closed_loop_hst", true, {"T_L=300 N*m@4", "eps=0.8@8"}, 500.0},
      {"test_stand", true, {"throttle=0.7@2", "throttle=1@4"}, 1000.0},
      {"thesis", true, {"kp=3e-8@2", "kp=6e-8@4"}, 1000.0},
  };
  for (const Nominal& k : cases) {
    const ct::LoadedCircuit c = load(k.name);
    ct::CircuitSimOptions o = hstmon_test::sim_options(10.0, k.rate);
    o.from_rest = k.from_rest;
    o.seed = 21 + static_cast<std::uint64_t>(&k - cases);
    for (const auto& s : k.steps) o.steps.push_back(step(c, s, false));
    const ct::CircuitReplayResult r = simulate_and_replay(c, o);
    EXPECT_TRUE(r.events.empty()) << k.name << (k.from_rest ? " from rest" : " steady") << "\n" << event_lines(r);
  }
}

struct Fault {
  const char* name;
  const char* fault;  // PARAM=FACTOR@T
  const char* truth;  // the row that must be in the reported set
};

TEST(CircuitMonitor, ParameterFaultDetectedAfterItAndTruthInTheSet) {
  const Fault cases[] = {
      {"paper", "Dm=1.1@5", "Dm+"},        {"paper", "Rfric=1.5@5", "Rfric+"},
      {"paper", "Rmlkg=0.2@5", "Rmlkg-"},  {"test_stand", "R_leak=0.2@5", "R_leak-"},
      {"thesis", "Rbl=1.3@5", "Rbl+"},     {"closed_loop_hst", "Dp=0.8@5", "Dp-"},
  };
  for (const Fault& k : cases) {
    const ct::LoadedCircuit c = load(k.name);
    ct::CircuitSimOptions o = hstmon_test::sim_options(14.0, 200.0, 5 + static_cast<std::uint64_t>(&k - cases));
    o.steps.push_back(step(c, k.fault, true));
    const ct::CircuitReplayResult r = simulate_and_replay(c, o, cli_options(c));
    ASSERT_FALSE(r.events.empty()) << k.name << " " << k.fault << ": not detected";
    EXPECT_EQ(r.events.front().event, "detected");
    EXPECT_GE(r.events.front().t, 5.0) << k.name << " " << k.fault << "\n" << event_lines(r);
    EXPECT_LE(r.events.front().t, 6.0) << k.name << " " << k.fault << "\n" << event_lines(r);
    // The last decision (isolated or ambiguous) names the truth among its candidates.
    const auto& last = r.events.back();
    EXPECT_TRUE(last.event == "isolated" || last.event == "ambiguous") << k.name << " " << k.fault << "\n" << event_lines(r);
    bool in_set = false;
    for (const auto& cand : last.candidates) in_set = in_set || cand.fault == k.truth;
    EXPECT_TRUE(in_set) << k.name << " " << k.fault << "\n" << event_lines(r);
  }
}

// A test stand logs its drive speed measured: every row a different input. The monitor
// treats the noise as one operating point (ModelMonitor::Config::input_tolerance) and
// gives the clean log's diagnosis: the same detection within a few samples, the same
// final status, and the clean verdict's candidates (the truth among them) still listed.
TEST(CircuitMonitor, MeasuredDriveSpeedGivesTheCleanLogsDiagnosis) {
  const ct::LoadedCircuit c = load("test_stand");
  ct::CircuitSimOptions o = hstmon_test::sim_options(14.0, 200.0, 8);
  o.steps.push_back(step(c, "R_leak=0.2@5", true));
  const ct::CircuitLog log = ct::simulate_circuit(c, o);
  ct::CircuitLog measured = ct::parse_circuit_log(ct::circuit_log_text(c.file, log), "sim.csv", c.file);
  ASSERT_TRUE(measured.ok());
  const ct::CircuitLog clean = measured;
  int drive = -1;
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    if (c.file.inputs[i].name == "n_drive") drive = static_cast<int>(i);
  }
  ASSERT_GE(drive, 0);
  ASSERT_FALSE(measured.inputs[drive].empty()) << "the log has the drive speed";
  std::mt19937_64 rng(4);
  std::normal_distribution<double> rpm_noise(0.0, 2.0 * M_PI / 30.0);  // 2 rpm [rad/s]
  for (double& w : measured.inputs[drive]) w += rpm_noise(rng);
  const ct::CircuitReplayResult a = ct::replay_circuit(c, clean, cli_options(c));
  const ct::CircuitReplayResult b = ct::replay_circuit(c, measured, cli_options(c));
  ASSERT_FALSE(a.events.empty()) << "\n" << event_lines(a);
  ASSERT_FALSE(b.events.empty()) << "\n" << event_lines(b);
  const std::string both = "clean:\n" + event_lines(a) + "measured:\n" + event_lines(b);
  // The drive speed's noise enters the model's flow, so the residual is a little noisier
  // and the CUSUM a few samples slower: 0.1 s is 20 samples. Near-equal candidates may
  // swap places window by window (each swap an event), so the verdicts are compared, not
  // the count of events.
  EXPECT_EQ(a.events.front().event, b.events.front().event) << both;
  EXPECT_NEAR(a.events.front().t, b.events.front().t, 0.1) << both;
  EXPECT_EQ(a.final_status, b.final_status) << both;
  auto names = [](const ct::CircuitReplayResult& r) {
    std::set<std::string> s;
    for (const auto& cand : r.events.back().candidates) s.insert(cand.fault);
    return s;
  };
  // The measured speed's noise may keep one more candidate consistent, never fewer.
  const std::set<std::string> from_clean = names(a), from_noisy = names(b);
  EXPECT_TRUE(from_clean.count("R_leak-") == 1 && from_noisy.count("R_leak-") == 1) << both;
  for (const auto& n : from_clean) EXPECT_EQ(from_noisy.count(n), 1u) << n << "\n" << both;
}

TEST(CircuitMonitor, ThesisCircuitGivesTheDemoDiagnosis) {
  // examples/prv_blockage.csv (thesis columns) through thesis.json's engine and the
  // generated table: the thesis monitor's events (test_replay_diagnosis) to the tick.
  const ct::LoadedCircuit c = load("thesis");
  const ct::CircuitLog log = ct::read_circuit_log(example("prv_blockage.csv"), c.file);
  ASSERT_TRUE(log.ok()) << log.error->to_string();
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, cli_options(c));
  ASSERT_GE(r.events.size(), 2u) << "\n" << event_lines(r);
  EXPECT_EQ(r.events[0].event, "detected");
  EXPECT_NEAR(r.events[0].t, 80.03, 1e-9) << "\n" << event_lines(r);
  EXPECT_EQ(r.events[1].event, "isolated") << "\n" << event_lines(r);
  EXPECT_NEAR(r.events[1].t, 80.18, 1e-9) << "\n" << event_lines(r);
  ASSERT_FALSE(r.events[1].candidates.empty());
  EXPECT_EQ(r.events[1].candidates[0].fault, "kp-");
}

TEST(CircuitMonitor, TableRowsAreNamedAfterTheCircuit) {
  const ct::LoadedCircuit c = load("paper");
  const ct::CircuitFaultTable t = ct::circuit_fault_table(c);
  std::vector<std::string> names;
  for (const auto& row : t.rows) names.emplace_back(row.name);
  for (const char* want : {"Dm+", "Dm-", "Rfric+", "A_prv-", "sensor_p_s", "sensor_w_m"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
  for (const char* never : {"Kpm+", "J+", "rho+"}) {  // capacitances, inertias, density: no row
    EXPECT_EQ(std::find(names.begin(), names.end(), never), names.end()) << never;
  }
  for (const auto& row : t.rows) {
    double n = 0.0;
    for (float d : row.direction) n += static_cast<double>(d) * d;
    EXPECT_NEAR(n, row.sensor ? 0.0 : 1.0, 1e-6) << row.name;
  }
}

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

/// The machine `m` (a healthy one that is not the model) run as `o` says raises no event
/// under the model `c`; with `fault` stepped in as well, the first event is a detection at
/// a time in [t_from, t_until] and the last event's candidates include `candidate`.
void expect_quiet_until_fault(const ct::LoadedCircuit& c, const ct::LoadedCircuit& m, const ct::CircuitSimOptions& o,
                              const ct::CircuitReplayOptions& replay, const std::string& fault,
                              const std::string& candidate, double t_from, double t_until) {
  for (const bool faulty : {false, true}) {
    ct::CircuitSimOptions run = o;
    if (faulty) run.steps.push_back(step(c, fault, true));
    const ct::CircuitLog log = ct::simulate_circuit(m, run);  // the machine's log, the model's monitor
    const ct::CircuitReplayResult r = ct::replay_circuit(c, log, replay);
    if (!faulty) {
      EXPECT_TRUE(r.events.empty()) << "nominal\n" << event_lines(r);
      continue;
    }
    ASSERT_FALSE(r.events.empty()) << candidate << " not detected";
    EXPECT_EQ(r.events.front().event, "detected");
    EXPECT_GE(r.events.front().t, t_from) << "\n" << event_lines(r);
    EXPECT_LE(r.events.front().t, t_until) << "\n" << event_lines(r);
    bool in_set = false;
    for (const auto& cand : r.events.back().candidates) in_set = in_set || cand.fault == candidate;
    EXPECT_TRUE(in_set) << "\n" << event_lines(r);
  }
}

}  // namespace

// Issue 15's false alarm on the test stand: a ±2 % machine (throttle and relief setting
// 2 % up, pump 2 % down) stepped in drive speed from 160 bar to the model's just-cracked
// relief valve. The machine's valve stays shut: it settles about 5 bar below the model,
// more than the sum of single-parameter changes (the valve absorbs each alone), and at
// its own, slower pace from the old point's model error. Neither is a fault (the corner
// models in the bound, the carried bound); a pump leak in the same situation still is.
TEST(CircuitMonitor, MachineWithShutReliefValveAtCrackingRaisesNoEventButLeakIsFound) {
  const ct::LoadedCircuit c = load("test_stand");
  ct::LoadedCircuit m = c;
  for (const auto& [name, factor] : std::vector<std::pair<std::string, double>>{
           {"k_throttle", 1.02}, {"p_crack", 1.02}, {"p_set", 1.02}, {"D", 0.98}}) {
    const int p = c.file.param_index(name);
    ASSERT_GE(p, 0) << name;
    m.values.params.v[p] *= factor;
  }
  m.values.inputs.v[c.file.input_index("n_drive")] *= 1600.0 / 1500.0;
  ct::CircuitSimOptions o = hstmon_test::sim_options(8.0, 1000.0, 81);
  o.steps.push_back(step(c, "n_drive=1780 rpm@2", false));
  expect_quiet_until_fault(c, m, o, cli_options(c), "R_leak=0.2@5", "R_leak-", 5.0, kNoLimit);
}

// Issue 15's last false alarms on the closed loop: a ±2 % machine (the campaign's nominal
// run 1000900000254, `--seed-base 1000000000000`) stepped in swash from 0.56 to 0.40
// between two samples, as the campaign's load steps are. 0.16 s later line A falls below
// the charge pressure and the check valve opens: the machine's p_c drops 1.8 bar some
// 3 ms before the model's, since its transient runs a little ahead. The allowance from
// the model's past change cannot cover a machine that leads; the model's change over the
// next ε·τ (Config::timing_lead) does (before it: detected at 3.659 s). A displacement
// loss after the step is still found.
TEST(CircuitMonitor, MachineWhoseCheckValveLeadsTheModelsRaisesNoEventButPumpLossIsFound) {
  const ct::LoadedCircuit c = load("closed_loop_hst");
  ct::LoadedCircuit m = c;
  for (const auto& [name, factor] : std::vector<std::pair<std::string, double>>{
           {"Dp", 0.9956}, {"Dm", 1.0100}, {"Dc", 0.9825}, {"beta", 1.0186}, {"c_m", 1.0027},
           {"R_case", 0.9989}, {"k_check", 1.0112}, {"p_check", 0.9991}, {"p_check_open", 0.9874},
           {"k_charge", 1.0165}, {"p_charge_crack", 0.9810}, {"p_charge", 1.0014}, {"k_hp", 0.9964},
           {"p_hp_crack", 1.0126}, {"p_hp", 1.0014}}) {
    const int p = c.file.param_index(name);
    ASSERT_GE(p, 0) << name;
    m.values.params.v[p] *= factor;
  }
  m.values.inputs.v[c.file.input_index("n_e")] *= 2298.01808 / 2000.0;  // the file's 2000 rpm
  m.values.inputs.v[c.file.input_index("eps")] = 0.561629545;
  m.values.inputs.v[c.file.input_index("T_L")] *= 182.224125 / 150.0;  // the file's 150 N·m
  ct::CircuitSimOptions o = hstmon_test::sim_options(6.0, 1000.0, 254);
  o.steps.push_back(step(c, "eps=0.403959747@3.5004", false));  // after the start-up hold-off
  expect_quiet_until_fault(c, m, o, {}, "Dp=0.8@4.5", "Dp-", 4.5, 5.5);
}

// Issue 15's steady w_m false alarm (nominal run 1000900000074, `--seed-base
// 1000000000000`): after a swash step 0.41 → 0.60 the machine ran 4.30 rad/s faster than
// the model, within the bound at 0.60 (5.1 rad/s), but the monitor judged it against the
// bound at 0.41 (3.45 rad/s): at 0.60 the steady solve of the ±2 % k_hp model cycled
// between two Newton iterates at the shut crossport relief's kink, the bound failed, and
// the old one stayed. The solve now falls back to the circuit's transient and converges.
TEST(CircuitMonitor, BoundExistsWhereNewtonCycledAtAReliefValvesKink) {
  using Model = hstmon::host::HostCircuitModel;
  const ct::LoadedCircuit c = load("closed_loop_hst");
  Model::Inputs u = c.values.inputs;
  u.v[c.file.input_index("eps")] = 0.599057844;
  Model::Params p = c.values.params;
  p.v[c.file.param_index("k_hp")] *= 1.02;
  const Model k_hp_up(c.file.circuit, p, u);
  Model::State xs;
  EXPECT_TRUE(k_hp_up.steady_state(xs)) << "k_hp +2 % at swash 0.6";
  const Model model(c.file.circuit, c.values.params, u);
  double bound[hstmon::circuit::kExtent<Model::kOutputs>];
  ASSERT_EQ(hstmon::ModelBound<Model>::compute(model, ct::default_uncertainty(c.file), bound),
            hstmon::Status::kOk);
  ASSERT_EQ(c.file.sensors[3].name, "w_m");
  EXPECT_GT(bound[3], 4.30) << "the machine's steady offset [rad/s]";
}

// A parameter file's stated uncertainty (circuit_uncertainty) replaces the default 2 %:
// without one the monitor's uncertainty is the default; with Dm known to ±20 % the model
// bound widens on some channel and narrows on none.
TEST(CircuitMonitor, StatedUncertaintyWidensTheModelBound) {
  using Model = hstmon::host::HostCircuitModel;
  const ct::LoadedCircuit c = load("paper");
  const auto dflt = ct::default_uncertainty(c.file);
  const auto as_read = ct::circuit_uncertainty(c);
  for (std::size_t k = 0; k < c.file.params.size(); ++k) EXPECT_EQ(as_read.rel[k], dflt.rel[k]) << c.file.params[k].name;
  ct::LoadedCircuit loose = c;
  const int dm = c.file.param_index("Dm");
  ASSERT_GE(dm, 0);
  loose.values.uncertainty[static_cast<std::size_t>(dm)] = 0.2;
  const auto stated = ct::circuit_uncertainty(loose);
  EXPECT_EQ(stated.rel[dm], 0.2);
  const Model model(c.file.circuit, c.values.params, c.values.inputs);
  double tight[hstmon::circuit::kExtent<Model::kOutputs>];
  double wide[hstmon::circuit::kExtent<Model::kOutputs>];
  ASSERT_EQ(hstmon::ModelBound<Model>::compute(model, as_read, tight), hstmon::Status::kOk);
  ASSERT_EQ(hstmon::ModelBound<Model>::compute(model, stated, wide), hstmon::Status::kOk);
  bool wider = false;
  for (std::size_t ch = 0; ch < c.file.sensors.size(); ++ch) {
    EXPECT_GE(wide[ch], tight[ch]) << c.file.sensors[ch].name;
    wider = wider || wide[ch] > 1.5 * tight[ch];
  }
  EXPECT_TRUE(wider) << "Dm at ±20 % moves some channel's bound";
}

// Config::timing_lead takes the bound carry's time constants and steady state: without
// the carry, or negative, or not finite, it is an invalid configuration.
TEST(CircuitMonitor, TimingLeadNeedsTheBoundCarry) {
  using Mon = hstmon::circuit::CircuitMonitor<double, hstmon::host::CircuitCap>;
  const ct::LoadedCircuit c = load("closed_loop_hst");
  const Mon::Model model(c.file.circuit, c.values.params, c.values.inputs);
  auto mon = std::make_unique<Mon>();
  Mon::Config cfg;
  cfg.uncertainty = ct::default_uncertainty(c.file);
  hstmon::circuit::set_circuit_allowances(cfg);
  EXPECT_EQ(mon->configure(model, cfg, nullptr, 0), hstmon::Status::kOk);
  for (const double lead : {-1.0, std::nan("")}) {
    Mon::Config bad = cfg;
    bad.timing_lead = lead;
    EXPECT_EQ(mon->configure(model, bad, nullptr, 0), hstmon::Status::kInvalidConfig) << lead;
  }
  Mon::Config no_carry = cfg;
  no_carry.bound_carry = 0;
  EXPECT_EQ(mon->configure(model, no_carry, nullptr, 0), hstmon::Status::kInvalidConfig);
  no_carry.timing_lead = 0;
  EXPECT_EQ(mon->configure(model, no_carry, nullptr, 0), hstmon::Status::kInvalidConfig);  // settle_taus
  no_carry.settle_taus = 0;
  EXPECT_EQ(mon->configure(model, no_carry, nullptr, 0), hstmon::Status::kOk);
  for (const double taus : {-1.0, std::nan("")}) {
    Mon::Config bad = cfg;
    bad.settle_taus = taus;
    EXPECT_EQ(mon->configure(model, bad, nullptr, 0), hstmon::Status::kInvalidConfig) << taus;
  }
}

// Config::settle_taus: the matcher's windows follow the slowest time constant where the
// machine runs, not the first row's. The closed loop started at rest settles in seconds
// (a slow mode at rest that a running machine has not); after a step to its nominal
// inputs the windows shrink to that point's, and never below the configured ones.
TEST(CircuitMonitor, TimeConstantsRoundUpToAnEighthOfAnOctave) {
  using hstmon::model_monitor_detail::ceil_to_eighth_octave;
  for (const double x : {1e-4, 0.00316, 0.0387, 0.5, 0.52135, 1.0, 1.37426, 13.2, 1e3}) {
    const double q = ceil_to_eighth_octave(x);
    const double k = std::log2(q) * 8.0;
    EXPECT_NEAR(k, std::round(k), 1e-9) << x << " → " << q << ": on the grid";
    EXPECT_GE(q, x);
    EXPECT_LT(q, x * 1.0905077326652577 * (1 + 1e-12)) << x << ": the next step up at most";
    EXPECT_EQ(static_cast<double>(ceil_to_eighth_octave(static_cast<float>(x))),
              static_cast<double>(static_cast<float>(q)))
        << x << ": float rounds alike";
  }
  EXPECT_EQ(ceil_to_eighth_octave(0.5), 0.5);
  EXPECT_EQ(ceil_to_eighth_octave(1.0), 1.0);
}

TEST(CircuitMonitor, MatcherWindowsFollowTheOperatingPoint) {
  using Mon = hstmon::circuit::CircuitMonitor<double, hstmon::host::CircuitCap>;
  const ct::LoadedCircuit c = load("closed_loop_hst");
  Mon::Model model(c.file.circuit, c.values.params, c.values.inputs);
  auto mon = std::make_unique<Mon>();
  Mon::Config cfg;
  cfg.uncertainty = ct::default_uncertainty(c.file);
  hstmon::circuit::set_circuit_allowances(cfg);
  ASSERT_EQ(mon->configure(model, cfg, nullptr, 0), hstmon::Status::kOk);
  // The slowest time constant at u over the model and the bound's copies, as the monitor
  // takes it: rounded up to an eighth of an octave.
  const auto tau_at = [&](const Mon::Inputs& u) {
    Mon::Model m = model;
    m.set_inputs(u);
    double bound[Mon::kN_];
    double tau = 0.0;
    EXPECT_EQ(hstmon::ModelBound<Mon::Model>::compute(m, cfg.uncertainty, bound, &tau), hstmon::Status::kOk);
    return hstmon::model_monitor_detail::ceil_to_eighth_octave(tau);
  };
  Mon::Inputs slow = c.values.inputs;  // the machine idling: engine running, pump in neutral, no load
  slow.v[1] = 0.0;                     // eps
  slow.v[2] = 0.0;                     // T_L
  const Mon::Inputs nominal = c.values.inputs;
  const double tau_slow = tau_at(slow), tau_nominal = tau_at(nominal);
  ASSERT_GT(tau_slow, 0.0);
  ASSERT_GT(tau_nominal, 0.0);
  ASSERT_GT(tau_slow, 2.0 * tau_nominal) << tau_slow << " s at idle, " << tau_nominal << " s at the nominal point";
  const Mon::Measurement none{};
  ASSERT_EQ(mon->reset_steady(slow), hstmon::Status::kOk);
  (void)mon->step(0.0, slow, none);
  EXPECT_NEAR(mon->matcher().config().settle_time, 3.0 * tau_slow, 1e-6 * tau_slow);
  EXPECT_NEAR(mon->matcher().config().average_time, tau_slow, 1e-6 * tau_slow);
  (void)mon->step(0.001, nominal, none);
  EXPECT_NEAR(mon->matcher().config().settle_time, 3.0 * tau_nominal, 1e-6 * tau_nominal);
  EXPECT_NEAR(mon->matcher().config().average_time, tau_nominal, 1e-6 * tau_nominal);
  // An episode keeps the windows it was detected under; they follow the inputs again once it
  // has ended. Readings: the model's with noise, p_a 50 bar high (detected), then without it.
  const int n_ch = static_cast<int>(c.file.sensors.size());
  double t = 0.002;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise;
  const auto run = [&](const Mon::Inputs& u, double seconds, double offset) {
    for (const double end = t + seconds; t < end; t += 0.001) {
      Mon::Measurement m;
      m.valid = static_cast<std::uint8_t>((1u << n_ch) - 1u);
      for (int ch = 0; ch < n_ch; ++ch)
        m.y[ch] = mon->observer().estimate()[ch] + mon->evaluator().sigma(ch) * noise(rng);
      m.y[0] += offset;
      (void)mon->step(t, u, m);
    }
  };
  ASSERT_EQ(mon->reset_steady(nominal), hstmon::Status::kOk);  // no transient of the model's own
  run(nominal, 0.1, 50e5);
  ASSERT_NE(mon->matcher().status(), hstmon::MatchStatus::kNominal);
  run(slow, 0.1, 50e5);
  EXPECT_NEAR(mon->matcher().config().settle_time, 3.0 * tau_nominal, 1e-6 * tau_nominal) << "during the episode";
  // Cleared once the new point's transient has gone (5 time constants of the model and the
  // transducer, FaultMatcher::update's settled) and the readings stayed quiet for clear_hold.
  run(slow, 5.0 * (tau_slow + cfg.transducer_response) + 1.0, 0.0);
  ASSERT_EQ(mon->matcher().status(), hstmon::MatchStatus::kNominal) << "cleared";
  EXPECT_NEAR(mon->matcher().config().settle_time, 3.0 * tau_slow, 1e-6 * tau_slow) << "after the episode";
  // A floor above 3 τ stays.
  Mon::Config long_windows = cfg;
  long_windows.matcher.settle_time = 100.0;
  long_windows.matcher.average_time = 50.0;
  ASSERT_EQ(mon->configure(model, long_windows, nullptr, 0), hstmon::Status::kOk);
  ASSERT_EQ(mon->reset_steady(nominal), hstmon::Status::kOk);
  (void)mon->step(0.0, nominal, none);
  EXPECT_EQ(mon->matcher().config().settle_time, 100.0);
  EXPECT_EQ(mon->matcher().config().average_time, 50.0);
}

// After a detection the steady windows decide (fault_estimator.hpp): the fault is fitted
// at every operating point the machine visits since, so an operating-point change after
// the fault neither clears it nor changes its name, and the verdict carries its size.
TEST(CircuitMonitor, FaultFittedAcrossOperatingPointsWithItsSize) {
  struct Case {
    const char* name;
    const char* fault;
    const char* later;  // an input step after the fault
    const char* truth;
    double factor;
  };
  const Case cases[] = {
      {"paper", "Rfric=1.25@4", "A_prv=2.2 mm2@9", "Rfric+", 1.25},
      {"closed_loop_hst", "Dm=0.85@4", "T_L=60 N*m@9", "Dm-", 0.85},
  };
  for (const Case& k : cases) {
    const ct::LoadedCircuit c = load(k.name);
    ct::CircuitSimOptions o = hstmon_test::sim_options(14.0, 200.0, 11);
    o.steps.push_back(step(c, k.fault, true));
    o.steps.push_back(step(c, k.later, false));
    const ct::CircuitReplayResult r = simulate_and_replay(c, o, cli_options(c));
    ASSERT_FALSE(r.events.empty()) << k.name << ": not detected";
    for (const auto& e : r.events) {
      EXPECT_NE(e.event, "cleared") << k.name << ": a persisting fault cleared" << "\n" << event_lines(r);
    }
    const auto& last = r.events.back();
    ASSERT_EQ(last.event, "isolated") << k.name << "\n" << event_lines(r);
    ASSERT_FALSE(last.candidates.empty());
    EXPECT_EQ(last.candidates.front().fault, k.truth) << k.name << "\n" << event_lines(r);
    EXPECT_NEAR(last.candidates.front().size, k.factor, 0.05 * k.factor) << k.name;
    EXPECT_LE(last.candidates.front().size_lo, last.candidates.front().size);
    EXPECT_GE(last.candidates.front().size_hi, last.candidates.front().size);
  }
}

// A fault seen at one operating point may hide inside the model bound at the next: on
// paper.json a delivery gain (Q0 +30 %) shows on p_s at the valve opening where it begins,
// and the relief opening the load moves to next puts the pump on its curve's steep part,
// where the bound is wider than the fault's effect. The evidence there says nothing about
// the fault being gone, so it is not cleared; the later points name it (from a campaign run
// that was cleared before: hstmon_circuit_campaign --circuit paper.json, Q0+ seed 2).
TEST(CircuitMonitor, FaultHiddenInTheBoundAtTheNextPointIsNotCleared) {
  const ct::LoadedCircuit c = load("paper");
  ct::CircuitSimOptions o = hstmon_test::sim_options(9.5, 1000.0, 2);
  o.steps.push_back(step(c, "A_dcv=4.45 mm2@1.25", false));
  o.steps.push_back(step(c, "Q0=1.3@2.5", true));
  o.steps.push_back(step(c, "A_prv=1.9 mm2@4", false));
  o.steps.push_back(step(c, "A_dcv=7.5 mm2@6.7", false));
  const ct::CircuitReplayResult r = simulate_and_replay(c, o, cli_options(c));
  ASSERT_FALSE(r.events.empty()) << "not detected";
  EXPECT_GE(r.events.front().t, 2.5) << event_lines(r);
  for (const auto& e : r.events) EXPECT_NE(e.event, "cleared") << "a persisting fault cleared\n" << event_lines(r);
  bool named = false;
  for (const auto& cand : r.events.back().candidates) named = named || cand.fault == "Q0+";
  EXPECT_TRUE(named) << event_lines(r);
}

// On paper.json the model bound is wide (the compensator runs on its curve's steep part):
// the issue's 8 % motor displacement loss stays inside it, and the matcher stays quiet.
// The step at held inputs finds it, and the first window's fit of the change since the
// baseline names it with its size; nothing fires on the same run without the fault.
TEST(CircuitMonitor, FaultInsideTheBoundFoundAsAStepAtHeldInputs) {
  const ct::LoadedCircuit c = load("paper");
  for (const bool fault : {false, true}) {
    ct::CircuitSimOptions o = hstmon_test::sim_options(12.0, 1000.0, 23);
    o.steps.push_back(step(c, "A_prv=2.8 mm2@1", false));
    if (fault) o.steps.push_back(step(c, "Dm=0.92@6", true));
    const ct::CircuitReplayResult r = simulate_and_replay(c, o, cli_options(c));
    if (!fault) {
      EXPECT_TRUE(r.events.empty()) << "nominal" << "\n" << event_lines(r);
      continue;
    }
    ASSERT_FALSE(r.events.empty()) << "not detected";
    const auto& first = r.events.front();
    EXPECT_EQ(first.event, "detected");
    EXPECT_GE(first.t, 6.0);
    EXPECT_LE(first.t, 7.0) << "\n" << event_lines(r);
    EXPECT_NE(first.why.find("while the inputs held still"), std::string::npos) << first.why;
    const auto& last = r.events.back();
    ASSERT_EQ(last.event, "isolated") << "\n" << event_lines(r);
    EXPECT_EQ(last.candidates.front().fault, "Dm-") << "\n" << event_lines(r);
    EXPECT_NEAR(last.candidates.front().size, 0.92, 0.02) << "\n" << event_lines(r);
  }
}

// The same 8 % motor loss beginning with a DCV step, on a machine off the file by up to
// 2 %: no reading at the new point precedes it, so the step detector has nothing to compare,
// and it stays inside the bound until the bound carried from the old point has decayed. The
// healthy record of the point before it predicts the readings there; they are not that, so
// it is found sooner than by the bound (on the campaign's faults of 8 % that begin at an
// input step, it finds many the bound never does: bench/RESULTS.md), and the fit against
// the prediction names Dm− with its size. Without the fault nothing fires.
TEST(CircuitMonitor, FaultBegunInAnInputStepIsJudgedByTheHealthyRecord) {
  const ct::LoadedCircuit c = load("paper");
  ct::LoadedCircuit machine = c;
  for (const auto& [name, factor] : {std::pair{"Pc", 1.015}, {"Cd", 0.985}, {"Rfric", 0.98}, {"Dp", 0.985}}) {
    machine.values.params.v[c.file.param_index(name)] *= factor;
  }
  for (const bool fault : {false, true}) {
    ct::CircuitSimOptions o = hstmon_test::sim_options(12.0, 1000.0, 31);
    o.steps.push_back(step(c, "A_dcv=4.6 mm2@0.5", false));
    o.steps.push_back(step(c, "A_prv=3 mm2@0.5", false));
    o.steps.push_back(step(c, "A_dcv=4.0 mm2@5", false));
    if (fault) o.steps.push_back(step(c, "Dm=0.92@5", true));
    const ct::CircuitLog log = ct::simulate_circuit(machine, o);
    const ct::CircuitLog back = ct::parse_circuit_log(ct::circuit_log_text(c.file, log), "sim.csv", c.file);
    ASSERT_TRUE(back.ok());
    const ct::CircuitReplayResult r = ct::replay_circuit(c, back, cli_options(c));
    if (!fault) {
      EXPECT_TRUE(r.events.empty()) << "nominal\n" << event_lines(r);
      continue;
    }
    ct::CircuitReplayOptions without = cli_options(c);
    without.healthy_record = false;
    const ct::CircuitReplayResult w = ct::replay_circuit(c, back, without);
    ASSERT_FALSE(r.events.empty()) << "not detected";
    const double t_bound = w.events.empty() ? 1e9 : w.events.front().t;
    const auto& first = r.events.front();
    EXPECT_EQ(first.event, "detected");
    EXPECT_GE(first.t, 5.0);
    EXPECT_LT(first.t, t_bound) << "the bound alone:\n" << event_lines(w) << "with the record:\n" << event_lines(r);
    EXPECT_NE(first.why.find("healthy steady window"), std::string::npos) << first.why;
    const auto& last = r.events.back();
    ASSERT_EQ(last.event, "isolated") << "\n" << event_lines(r);
    EXPECT_EQ(last.candidates.front().fault, "Dm-") << "\n" << event_lines(r);
    EXPECT_NEAR(last.candidates.front().size, 0.92, 0.02) << "\n" << event_lines(r);
  }
}

// A friction rise inside the model bound, found as a step at held inputs 0.2 s before the
// next input change, on a machine whose motor is 2 % smaller than the file's (its speed
// sits at 0.6 of its bound before the fault): the step's own window decides, with the
// pre-fault baseline on every channel, and the truth is in the set (it ended "cleared"
// when the window waited a full settle, and undecided without the speed's baseline).
TEST(CircuitMonitor, StepFoundJustBeforeAnInputChangeIsDecided) {
  const ct::LoadedCircuit c = load("thesis");
  const ct::CircuitLog log = run_with_motor(c, 0.98, {{"Rf=1.3@2.5", true}, {"kp=4.46e-8@3", false}});
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, cli_options(c));
  ASSERT_FALSE(r.events.empty()) << "not detected";
  EXPECT_EQ(r.events.front().event, "detected");
  EXPECT_GE(r.events.front().t, 2.5);
  EXPECT_LE(r.events.front().t, 2.95) << "\n" << event_lines(r);
  const auto& last = r.events.back();
  ASSERT_TRUE(last.event == "isolated" || last.event == "ambiguous") << "\n" << event_lines(r);
  bool truth = false;
  for (const auto& k : last.candidates) truth = truth || k.fault == "Rf+";
  EXPECT_TRUE(truth) << "\n" << event_lines(r);
}

// A speed-sensor offset found as a step at held inputs, on a machine whose motor is 3 %
// smaller than the file's: the speed sat far from the model before (beyond half its
// bound), so the window there fits without the baseline, and the offset (10 rpm, 25σ)
// sits inside 0.25 of the bound: no fault fits better than none. But the readings are not
// back at the baseline, which is what says a fault has gone, so the episode goes on past
// the load step that follows (it ended "cleared" at that step before: thesis.json's
// campaign, sensor_w_m seed 19000059).
TEST(CircuitMonitor, StepThatStaysIsNotClearedByAWindowTheBoundCannotJudge) {
  const ct::LoadedCircuit c = load("thesis");
  ct::CircuitLog log = run_with_motor(c, 0.97, {{"kp=4.09e-8@0.5", false}, {"Pbp=13.8 bar@3", false}});
  ASSERT_TRUE(add_offset(c, "w_m", 2.5, 10.0 * hstmon_test::kRpm, log));
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, cli_options(c));
  ASSERT_FALSE(r.events.empty()) << "not detected";
  EXPECT_GE(r.events.front().t, 2.5) << "\n" << event_lines(r);
  for (const auto& e : r.events) EXPECT_NE(e.event, "cleared") << "\n" << event_lines(r);
}

// A crossport relief setting dropped early shows only when a load later needs more than
// it. After the detection a delivery loss, a case leak or a speed-sensor offset may fit
// the first windows as well, but each would have shown in the steady stretches before, so
// each can only have begun in the second before; the relief can have been there since the
// start. The relief is isolated at its true size, by timing or because the later windows
// rule the others out, with nothing cleared. A delivery loss that begins in a hold, where
// the earlier stretches are the same for every candidate, is named as the delivery loss.
// (A delivery loss that begins at the very load step that takes the machine onto its
// relief is named as the relief: timing favours the candidate that could have hidden, and
// the steady data on the relief do not tell them apart. docs/circuits.md, "When can each
// candidate have begun?")
TEST(CircuitMonitor, FaultSilentUntilALaterLoadIsIsolatedByTiming) {
  const ct::LoadedCircuit c = load("closed_loop_hst");
  struct Case {
    const char* fault;
    const char* truth;
    double shows;  ///< when the fault first moves the readings [s]
    double factor;
  };
  for (const Case& k : {Case{"p_hp_crack=0.75@2", "p_hp_crack-", 14.0, 0.75}, Case{"Dp=0.9@10", "Dp-", 10.0, 0.9}}) {
    ct::CircuitSimOptions o = hstmon_test::sim_options(22.0, 200.0, 3);
    for (const char* s : {"T_L=200 N*m@1", "T_L=150 N*m@6", "T_L=280 N*m@14", "eps=0.7@18"}) o.steps.push_back(step(c, s, false));
    o.steps.push_back(step(c, k.fault, true));
    const ct::CircuitReplayResult r = simulate_and_replay(c, o, cli_options(c));
    ASSERT_FALSE(r.events.empty()) << k.fault << ": not detected";
    EXPECT_GE(r.events.front().t, k.shows) << k.fault << "\n" << event_lines(r);
    const auto& last = r.events.back();
    ASSERT_EQ(last.event, "isolated") << k.fault << "\n" << event_lines(r);
    EXPECT_EQ(last.candidates.front().fault, k.truth) << k.fault << "\n" << event_lines(r);
    EXPECT_NEAR(last.candidates.front().size, k.factor, 0.2 * (1.0 - k.factor)) << k.fault << "\n" << event_lines(r);
    for (const auto& e : r.events) EXPECT_NE(e.event, "cleared") << k.fault << "\n" << event_lines(r);
  }
}

// A sensor offset of 12σ (3 bar on p_b, line B at charge pressure in forward drive) 1 s
// after a load step, on the independent simulator's nominal log of the closed circuit
// (tests/data/validation_circuits): the model transient's envelope decays with the running
// machine's time constants, not those of the machine at rest where the log began (with
// those, seconds: the offset was found only at 11.8 s), so it is found at once and named.
TEST(CircuitMonitor, SensorOffsetAfterALoadStepIsFoundAtTheRunningMachinesPace) {
  const std::string dir = std::string(HSTMON_SOURCE_DIR) + "/tests/data/validation_circuits/";
  ct::LoadedCircuit c;
  const auto err = ct::load_circuit(dir + "circuit.json", "", c);
  ASSERT_FALSE(err.has_value()) << err->to_string();
  ct::CircuitLog log = ct::read_circuit_log(dir + "logs/nominal_A.csv.gz", c.file);
  ASSERT_TRUE(log.ok());
  ASSERT_TRUE(add_offset(c, "p_b", 6.0, 3e5, log));
  const ct::CircuitReplayResult r = ct::replay_circuit(c, log, cli_options(c));
  ASSERT_FALSE(r.events.empty()) << "not detected";
  EXPECT_GE(r.events.front().t, 6.0) << "\n" << event_lines(r);
  EXPECT_LE(r.events.front().t, 6.5) << "\n" << event_lines(r);
  const auto& last = r.events.back();
  ASSERT_FALSE(last.candidates.empty()) << "\n" << event_lines(r);
  EXPECT_EQ(last.candidates.front().fault, "sensor_p_b") << "\n" << event_lines(r);
}

// A machine the model cannot describe (its pump delivers half the flow of the file's)
// is said so at its first steady stretch, and no fault is named on it; the file's own
// machine passes the same check.
TEST(CircuitMonitor, MachineOutsideTheEnvelopeIsSaidSoAndNoFaultIsNamed) {
  const ct::LoadedCircuit c = load("test_stand");
  for (const bool other : {false, true}) {
    ct::LoadedCircuit m = c;
    if (other) m.values.params.v[c.file.param_index("D")] *= 0.5;
    ct::CircuitSimOptions o = hstmon_test::sim_options(6.0, 1000.0, 5);
    o.steps.push_back(step(c, "throttle=0.8@3", false));
    const ct::CircuitLog log = ct::simulate_circuit(m, o);
    const ct::CircuitReplayResult r = ct::replay_circuit(c, log, cli_options(c));
    EXPECT_TRUE(r.envelope.checked) << r.envelope.text;
    if (!other) {
      EXPECT_FALSE(r.envelope.out) << r.envelope.text;
      EXPECT_TRUE(r.events.empty()) << "\n" << event_lines(r);
      continue;
    }
    EXPECT_TRUE(r.envelope.out) << r.envelope.text;
    EXPECT_NE(r.envelope.text.find("does not describe this machine"), std::string::npos) << r.envelope.text;
    EXPECT_EQ(r.final_status, "out_of_envelope");
    for (const auto& e : r.events) {
      EXPECT_NE(e.event, "isolated") << "\n" << event_lines(r);
      EXPECT_NE(e.event, "ambiguous") << "\n" << event_lines(r);
    }
  }
}

// A test-stand export in the shape of a real one: 0.6 s at 4.8 kHz, an unlogged valve
// that halves the loading throttle at 0.08 s. The fault is detected before the machine
// was ever seen to match the model for long, and the log ends before a steady stretch
// could be judged: unverified, no fault named. The same switch in a 6 s log, after the
// machine ran quiet, is a fault and is named.
TEST(CircuitMonitor, DetectionBeforeTheMachineWasSeenToMatchIsUnverifiedOnAShortLog) {
  const ct::LoadedCircuit c = load("test_stand");
  for (const double duration : {0.6, 6.0}) {
    ct::CircuitSimOptions o = hstmon_test::sim_options(duration, 4800.0, 3);
    const double at = duration < 1.0 ? 0.08 : 3.0;
    o.steps.push_back(step(c, "k_throttle=0.5@" + std::to_string(at), true));
    const ct::CircuitReplayResult r = ct::replay_circuit(c, ct::simulate_circuit(c, o), cli_options(c));
    ASSERT_FALSE(r.events.empty()) << duration << " s: the switch is detected";
    if (duration < 1.0) {
      EXPECT_TRUE(r.envelope.unverified) << r.envelope.text;
      EXPECT_EQ(r.final_status, "unverified") << "\n" << event_lines(r);
      ASSERT_EQ(r.events.size(), 1u) << "\n" << event_lines(r);
      EXPECT_EQ(r.events.front().event, "unverified");
      EXPECT_TRUE(r.events.front().candidates.empty());
    } else {
      EXPECT_FALSE(r.envelope.unverified) << r.envelope.text;
      EXPECT_NE(r.final_status, "unverified") << "\n" << event_lines(r);
      ASSERT_FALSE(r.events.back().candidates.empty()) << "\n" << event_lines(r);
      const std::string first = r.events.back().candidates.front().fault;
      EXPECT_TRUE(first == "k_throttle-" || first == "throttle-") << "\n" << event_lines(r);
    }
  }
}
