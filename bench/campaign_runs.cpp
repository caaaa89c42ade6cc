/// @file campaign_runs.cpp
#include "campaign_runs.hpp"

#include <cmath>
#include <cstdio>

#include <cstdlib>

#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/thesis_log.hpp"
#include "hstmon_fdi/circuit_signature_table.hpp"

namespace hstmon_campaign {

using hstmon::sim::LoadShape;
using hstmon::sim::SensorFaultKind;
namespace sim = hstmon::sim;

std::vector<Condition> campaign_conditions() {
  const Condition base{"baseline", "base"};
  std::vector<Condition> out = {base};
  auto vary = [&](const char* name, const char* factor, auto set) {
    Condition c = base;
    c.name = name;
    c.factor = factor;
    set(c);
    out.push_back(c);
  };
  vary("lag 1 ms", "lag", [](Condition& c) { c.lag = 1e-3; });
  vary("lag 3 ms", "lag", [](Condition& c) { c.lag = 3e-3; });
  vary("lag 10 ms", "lag", [](Condition& c) { c.lag = 10e-3; });
  vary("rate 500 Hz", "rate", [](Condition& c) { c.rate = 500.0; });
  vary("rate 100 Hz", "rate", [](Condition& c) { c.rate = 100.0; });
  vary("rate 0.25 Hz (DAS)", "rate", [](Condition& c) { c.rate = 0.25; });
  vary("supply on at 0.5 s", "start", [](Condition& c) { c.supply_on = 0.5; });
  vary("start steady", "start", [](Condition& c) { c.from_rest = false; });
  vary("load constant", "load", [](Condition& c) { c.load = LoadShape::kConstant; });
  vary("load ramp", "load", [](Condition& c) { c.load = LoadShape::kRamp; });
  vary("load sine", "load", [](Condition& c) { c.load = LoadShape::kSine; });
  vary("ADC none", "quant", [](Condition& c) { c.quant = 0.0; });
  vary("ADC 12 bit/range", "quant", [](Condition& c) { c.adc_bits = 12; });
  vary("param error 0", "param", [](Condition& c) { c.spread = 0.0; });
  // A 0–250 bar Ppp transmitter (the thesis rig's assumed one) clips the overshoot of a PRV
  // step; the installation declares its ranges, so a reading at the top is saturated.
  vary("Ppp 250 bar, ranges", "range", [](Condition& c) {
    c.ppp_range = 250e5;
    c.declare_ranges = true;
  });
  return out;
}

double time_scale(const Condition& c) { return 1.0 / c.rate >= 0.1 ? 20.0 : 1.0; }

sim::SensorConfig sensors_of(const Condition& c) {
  sim::SensorConfig s = sim::with_lag(sim::rig_fast_sensors(c.rate), c.lag);
  s.channels[2].range_hi = c.ppp_range;
  return c.adc_bits > 0 ? sim::with_pressure_adc_bits(s, c.adc_bits) : sim::with_pressure_step(s, c.quant);
}

sim::RigRun run_of(const Condition& c, double duration, double level, std::uint64_t load_seed, bool with_cycles) {
  const double k = time_scale(c);
  sim::RigRun r;
  r.duration = duration;
  r.from_rest = c.from_rest;
  r.supply_on = c.from_rest ? c.supply_on * k : 0.0;
  if (with_cycles && c.from_rest) {
    r.run_time = 0.6 * duration - r.supply_on;
    r.stop_time = 0.1 * duration;
  }
  r.load.shape = c.load;
  r.load.level = level;
  r.load.seed = load_seed;
  // Steps every 2 s (the validation logs' pace), first at 1 s; ramp legs 10 s; sine 20 s.
  r.load.period = (c.load == LoadShape::kSteps ? 2.0 : c.load == LoadShape::kRamp ? 10.0 : 20.0) * k;
  r.load.first = c.load == LoadShape::kSteps ? 1.0 * k : -1.0;
  r.load.update = 0.1;
  return r;
}

namespace {

FaultCase param_case(const char* row, double Params::*param, double Inputs::*input, double factor, const char* label,
                     const char* group) {
  FaultCase f;
  f.row = row;
  f.label = label;
  f.group = group;
  f.target = param ? Target::kParam : Target::kInput;
  f.param = param;
  f.input = input;
  f.factor = factor;
  return f;
}

}  // namespace

std::vector<FaultCase> parameter_faults() {
  struct Spec {
    const char* name;
    double Params::*param;
    double Inputs::*input;
    double mag[2];
    bool minus_only;
  };
  // Magnitudes as in the first campaign (docs/fault_campaign.md): 10/30 % by default, kp
  // 30/50 %, Pbp 30/60 %, Rf 30/90 %, leakage resistances −50/−90 %.
  const Spec specs[] = {
      {"kp", nullptr, &Inputs::kp, {0.3, 0.5}, false},      {"kf", &Params::kf, nullptr, {0.1, 0.3}, false},
      {"Psupl", nullptr, &Inputs::Psupl, {0.1, 0.3}, false}, {"Pbp", nullptr, &Inputs::Pbp, {0.3, 0.6}, false},
      {"Rbl", &Params::Rbl, nullptr, {0.1, 0.3}, false},    {"Rf", &Params::Rf, nullptr, {0.3, 0.9}, false},
      {"Dp", &Params::Dp, nullptr, {0.1, 0.3}, false},      {"Dm", &Params::Dm, nullptr, {0.1, 0.3}, false},
      {"Rlkg", &Params::Rlkg, nullptr, {0.5, 0.9}, true},   {"Ripl", &Params::Ripl, nullptr, {0.5, 0.9}, true},
  };
  std::vector<FaultCase> out;
  for (const Spec& s : specs) {
    for (int sg = 0; sg < (s.minus_only ? 1 : 2); ++sg) {
      const double sign = sg == 0 ? -1.0 : 1.0;
      const std::string row = std::string(s.name) + (sg == 0 ? "-" : "+");
      for (double m : s.mag) {
        char label[48];
        std::snprintf(label, sizeof label, "%s %g%%", row.c_str(), m * 100.0);
        const bool blockage = row == "kp-" && m == 0.5;
        out.push_back(param_case(row.c_str(), s.param, s.input, 1.0 + sign * m, label, blockage ? "kp- 50%" : "param"));
      }
    }
  }
  return out;
}

std::vector<FaultCase> sensor_faults(const sim::SensorConfig& sensors) {
  static const char* chans[] = {"p_mi", "p_mo", "p_pp", "w_m"};
  struct Kind {
    SensorFaultKind kind;
    double fs;
    const char* label;
    const char* group;
  };
  const Kind kinds[] = {{SensorFaultKind::kLoopBreak, 0.0, "loop break", "loop break"},
                        {SensorFaultKind::kStuck, 0.0, "stuck", "stuck"},
                        {SensorFaultKind::kBias, 0.02, "bias +2%FS", "bias 2%FS"},
                        {SensorFaultKind::kBias, -0.02, "bias -2%FS", "bias 2%FS"},
                        {SensorFaultKind::kBias, 0.05, "bias +5%FS", "bias 5%FS"},
                        {SensorFaultKind::kBias, -0.05, "bias -5%FS", "bias 5%FS"}};
  std::vector<FaultCase> out;
  for (int ch = 0; ch < 4; ++ch) {
    const auto& spec = sensors.channels.at(static_cast<std::size_t>(ch));
    // Full scale: the transmitter's span (ωm: 0–3000 rpm, its magnitude range).
    const double fs = ch == 3 ? spec.range_hi : spec.range_hi - spec.range_lo;
    for (const Kind& k : kinds) {
      FaultCase f;
      f.row = std::string("sensor_") + chans[ch];
      f.label = std::string(chans[ch]) + " " + k.label;
      f.group = k.group;
      f.target = Target::kSensor;
      f.sensor.channel = ch;
      f.sensor.kind = k.kind;
      f.sensor.value = k.fs * fs;
      out.push_back(f);
    }
  }
  return out;
}

namespace {

namespace ct = hstmon::circuit_tools;

// The built-in thesis.json, as `hstmon replay` loads it without --circuit.
const ct::LoadedCircuit& thesis_circuit() {
  static const ct::LoadedCircuit c = [] {
    ct::LoadedCircuit l;
    if (auto err = ct::load_circuit("", "", l)) {
      std::fprintf(stderr, "campaign: %s\n", err->to_string().c_str());
      std::abort();
    }
    return l;
  }();
  return c;
}

// Its fault table, as `hstmon replay` builds it; once for every log.
const ct::CircuitFaultTable& thesis_table() {
  static const ct::CircuitFaultTable t = hstmon::fdi::circuit_signature_table(thesis_circuit());
  return t;
}

}  // namespace

std::string log_text(const sim::ThesisMeasurements& log, const std::string& note) {
  return ct::circuit_log_text(thesis_circuit().file, ct::thesis_circuit_log(log, thesis_circuit().file), {note});
}

ct::CircuitReplayResult replay_log(const sim::ThesisMeasurements& log, const sim::SensorConfig& sensors,
                                   bool declare_ranges) {
  ct::LoadedCircuit c = thesis_circuit();
  const ct::CircuitLog d = ct::thesis_circuit_log(log, c.file);
  for (std::size_t ch = 0; declare_ranges && ch < 4; ++ch) {
    c.file.sensors[ch].lo = sensors.channels[ch].range_lo;
    c.file.sensors[ch].hi = sensors.channels[ch].range_hi;
  }
  ct::CircuitReplayOptions o;
  o.table = &thesis_table();
  return ct::replay_circuit(c, d, o);
}

NominalStats score_nominal(const ct::CircuitReplayResult& r) {
  NominalStats st;
  st.seconds = r.t_last - r.t_first;
  st.rows = static_cast<long>(r.rows);
  st.health = r.health;
  for (const auto& c : r.channels) {
    if (!std::isfinite(c.sum) || !std::isfinite(c.sumsq)) ++st.nonfinite;
  }
  bool want = false;
  for (const auto& e : r.events) {
    if (e.event == "detected") {
      ++st.detections;
      st.times.push_back(e.t);
      want = true;
    } else if (want && is_decision(e.event)) {
      st.calls.push_back(e.candidates.empty() ? "(" + e.event + ")" : e.candidates[0].fault);
      want = false;
    }
  }
  if (want) st.calls.emplace_back("(undecided)");
  return st;
}

}  // namespace hstmon_campaign
