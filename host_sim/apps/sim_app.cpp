/// @file sim_app.cpp
/// hstmon-sim: writes a synthetic measurement log of a scenario.
///   hstmon-sim --scenario prv_blockage --rate 100 --seed 1 --out FILE.csv
///              [--no-noise] [--ideal] [--model thesis|paper] [--preset NAME]
///              [--duration S] [--units bar|Pa] [--rpm] [--list]
///   rig conditions, each switchable alone (thesis model):
///              [--lag MS] [--quant BAR | --adc-bits N] [--param-error F --machine-seed N]
///              --scenario rig [--start rest|steady] [--supply-on S] [--cycle ON,OFF]
///              [--load constant|steps|ramp|sine] [--load-period S] [--load-range LO,HI]
///              [--load-seed N] [--blockage T]
///   any circuit file (docs/circuits.md; sim_circuit.hpp):
///              --circuit FILE [--params FILE] [--step INPUT=VALUE@T ...] [--start rest|steady]
///              [--inputs LOG [--inputs-hold linear|step] [--compare]]
///              [--duration S] [--rate HZ] [--seed N] [--no-noise | --ideal] [--out FILE.csv]
///              [--units bar|Pa] [--rpm] [--list]
///              [--lag MS] [--quant BAR | --adc-bits N] [--param-error F --machine-seed N]

#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli_validators.hpp"
#include "hstmon_sim/param_fault.hpp"
#include "hstmon_sim/sim.hpp"
#include "sim_circuit.hpp"

namespace {

using namespace hstmon::sim;

struct Options {
  std::string scenario;
  std::string model;        // "", "thesis" or "paper"
  std::string preset;       // "" = model default
  double rate = 0.0;        // [Hz]; 0 = preset's rate
  double duration = 0.0;    // [s]; 0 = scenario's
  std::uint64_t seed = 1;
  std::string out = "-";
  bool no_noise = false;
  bool ideal = false;
  std::string units = "bar";
  bool rpm = false;
  bool list = false;
  // Rig conditions (the thesis model; lag, ADC and parameter error on a circuit too).
  double lag_ms = -1.0;       // < 0: the preset's
  double quant_bar = -1.0;    // < 0: the preset's; 0: none
  int adc_bits = 0;           // 0: the preset's
  double param_error = 0.0;   // machine parameters off by uniform ±F
  std::uint64_t machine_seed = 1;
  std::string start = "rest";
  double supply_on = 0.0;
  std::vector<double> cycle;  // ON,OFF [s]
  std::string load = "constant";
  double load_period = 2.0;
  std::vector<double> load_range = {0.65, 1.6};
  std::uint64_t load_seed = 1;
  double blockage = -1.0;     // ≥ 0: true kp halved from then on, logged kp unchanged
  // Any circuit file (sim_circuit.hpp).
  std::string circuit;
  std::string circuit_params;
  std::string circuit_inputs;  // --inputs LOG
  std::string inputs_hold = "linear";
  bool compare = false;
  std::vector<std::string> steps;
  std::vector<std::string> faults;
};

void list_all() {
  std::cout << "thesis scenarios:\n";
  for (const std::string& n : thesis_scenario_names()) {
    std::cout << "  " << n << "  -  " << thesis_scenario(n)->description << '\n';
  }
  std::cout << "  rig  -  thesis rig as run (--start, --supply-on, --cycle, --load, --blockage; default 30 s)\n";
  std::cout << "paper scenarios:\n";
  for (const std::string& n : paper_scenario_names()) {
    std::cout << "  " << n << "  -  " << paper_scenario(n)->description << '\n';
  }
  std::cout << "sensor presets:";
  for (const std::string& n : sensor_preset_names()) std::cout << ' ' << n;
  std::cout << '\n';
}

SensorConfig sensors_for(const Options& o, bool paper) {
  std::string name = o.preset.empty() ? (paper ? "paper_logger" : "fast") : o.preset;
  std::optional<SensorConfig> cfg = sensor_preset(name);
  if (!cfg) throw CLI::ValidationError("--preset", "unknown preset " + name);
  if (paper != (name == "paper_logger")) {
    throw CLI::ValidationError("--preset", name + " does not match the " + (paper ? "paper" : "thesis") + " model");
  }
  if (o.rate > 0.0) cfg->sample_period = 1.0 / o.rate;
  if (o.lag_ms >= 0.0) cfg = with_lag(*cfg, o.lag_ms * 1e-3);
  if (o.quant_bar >= 0.0) cfg = with_pressure_step(*cfg, o.quant_bar * kPaPerBar);
  if (o.adc_bits > 0) cfg = with_pressure_adc_bits(*cfg, o.adc_bits);
  if (o.no_noise) cfg = without_noise(*cfg);
  if (o.ideal) cfg = ideal_sensors(*cfg);
  return *cfg;
}

template <class Scen>
void apply_duration(Scen& sc, double duration) {
  if (duration > 0.0) {
    sc.duration = duration;
    validate(sc);
  }
}

ThesisScenario rig_scenario(const Options& o) {
  RigRun r;
  r.duration = o.duration > 0.0 ? o.duration : 30.0;
  r.from_rest = o.start == "rest";
  r.supply_on = o.supply_on;
  if (o.cycle.size() == 2) {
    r.run_time = o.cycle[0];
    r.stop_time = o.cycle[1];
  }
  r.load.shape = *load_shape_from(o.load);
  r.load.period = o.load_period;
  r.load.lo = o.load_range.at(0);
  r.load.hi = o.load_range.at(1);
  r.load.seed = o.load_seed;
  ThesisScenario sc = thesis_rig_run(r);
  if (o.blockage >= 0.0) sc = with_input_fault(sc, &hstmon::ThesisInputs<double>::kp, 0.5, o.blockage);
  return sc;
}

int run(const Options& o) {
  LogUnits units;
  units.pressure = (o.units == "Pa") ? PressureUnit::kPa : PressureUnit::kBar;
  units.speed = o.rpm ? SpeedUnit::kRpm : SpeedUnit::kRadPerSec;

  std::optional<ThesisScenario> ts;
  std::optional<PaperScenario> ps;
  const bool paper_wanted = (o.model == "paper");
  if (o.scenario.empty()) {
    if (paper_wanted) ps = paper_start(); else ts = thesis_prv_blockage();
  } else if (o.scenario == "rig") {
    if (paper_wanted) throw CLI::ValidationError("--model", "scenario rig belongs to the thesis model");
    ts = rig_scenario(o);
  } else {
    ps = paper_scenario(o.scenario);
    if (!ps) {
      // The staircase hold adapts to the sample period, so look the rate up first.
      const SensorConfig probe = sensors_for(o, false);
      ts = thesis_scenario(o.scenario, probe.sample_period);
    }
    if (!ps && !ts) throw CLI::ValidationError("--scenario", "unknown scenario " + o.scenario + " (see --list)");
  }
  if (!o.model.empty() && (ps.has_value() != paper_wanted)) {
    throw CLI::ValidationError("--model", "scenario " + o.scenario + " belongs to the other model");
  }

  std::ofstream file;
  std::ostream* os = &std::cout;
  if (o.out != "-") {
    file.open(o.out);
    if (!file) throw std::runtime_error("cannot open " + o.out);
    os = &file;
  }
  if (ps) {
    apply_duration(*ps, o.duration);
    write_log(*os, measure(*ps, sensors_for(o, true), o.seed), units);
  } else {
    if (o.scenario != "rig") apply_duration(*ts, o.duration);
    const hstmon::ThesisParams<double> machine = perturbed_params(o.machine_seed, o.param_error);
    write_log(*os, measure(*ts, sensors_for(o, false), o.seed, machine), units);
  }
  os->flush();
  if (!*os) throw std::runtime_error("write failed");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hstmon-sim: synthetic HST measurement logs from the reference simulator"};
  Options o;
  app.add_option("--scenario", o.scenario,
                 "start_from_rest | prv_staircase | prv_blockage | rig | paper_start (default: prv_blockage, "
                 "or paper_start with --model paper); rig: the run set by --start, --supply-on, --cycle, --load*");
  app.add_option("--model", o.model, "thesis | paper (checked against the scenario)")
      ->check(CLI::IsMember({"thesis", "paper"}));
  app.add_option("--preset", o.preset,
                 "sensor preset: thesis_das | fast | rig_fast | paper_logger (default: fast / paper_logger)");
  app.add_option("--rate", o.rate, "sample rate [Hz] (default: the preset's)")->check(hstmon::cli::positive_number());
  app.add_option("--duration", o.duration, "run length [s] (default: the scenario's)")->check(hstmon::cli::positive_number());
  app.add_option("--seed", o.seed, "noise seed (std::mt19937_64)");
  app.add_option("--out", o.out, "output CSV file, - for stdout");
  app.add_flag("--no-noise", o.no_noise, "no sensor noise (lag and ADC kept)");
  app.add_flag("--ideal", o.ideal, "ideal sensors: the reference solution itself");
  app.add_option("--units", o.units, "pressure unit: bar | Pa (with --circuit default: the circuit file's)")
      ->check(CLI::IsMember({"bar", "Pa"}));
  app.add_flag("--rpm", o.rpm, "speed in rpm (default rad/s; with --circuit the circuit file's unit)");
  app.add_flag("--list", o.list,
               "list scenarios and presets, then exit; with --circuit its inputs, parameters and sensors");
  app.add_option("--lag", o.lag_ms, "transducer time constant of every channel [ms], 0 = none (default: the preset's)")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--quant", o.quant_bar, "pressure ADC step [bar], 0 = none (default: the preset's)")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--adc-bits", o.adc_bits, "pressure ADC bits over the transmitter range (instead of --quant)")
      ->check(CLI::Range(4, 24))
      ->excludes("--quant");
  app.add_option(
         "--param-error", o.param_error,
         "machine parameters off by uniform ±F, e.g. 0.02: the thesis model's Dm, Dp, Rlkg, Ripl, Rf, Rbl, kf, J, K "
         "off Table 2.2; a circuit's every parameter its monitor treats as uncertain off the parameter file")
      ->check(CLI::Range(0.0, 0.5));
  app.add_option("--machine-seed", o.machine_seed, "seed of the parameter error");
  app.add_option("--start", o.start, "rig: rest (logger runs before the supply) | steady")
      ->check(CLI::IsMember({"rest", "steady"}));
  app.add_option("--supply-on", o.supply_on, "rig: time the supply steps on [s] (default 0: at the first sample)")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--cycle", o.cycle, "rig: start/stop cycles ON,OFF [s]: supply on for ON, off for OFF, repeated")
      ->expected(2)
      ->delimiter(',');
  app.add_option("--load", o.load, "rig: PRV setting over time: constant | steps | ramp | sine")
      ->check(CLI::IsMember({"constant", "steps", "ramp", "sine"}));
  app.add_option("--load-period", o.load_period, "rig: steps' hold, a ramp's leg or the sine's period [s] (default 2)")
      ->check(hstmon::cli::positive_number());
  app.add_option("--load-range", o.load_range, "rig: kp range LO,HI as multiples of 4.41e-8 (default 0.65,1.6)")
      ->expected(2)
      ->delimiter(',');
  app.add_option("--load-seed", o.load_seed, "rig: seed of the step levels");
  app.add_option("--blockage", o.blockage, "rig: 50 % PRV blockage (true kp halved, logged kp kept) from T [s]")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--circuit", o.circuit,
                 "simulate this circuit file (docs/circuits.md) instead of a scenario: full equations, its sensors' "
                 "noise and range; --duration (default 10 s), --rate (default 100 Hz), --seed, --out, --start "
                 "(default steady), --no-noise, --ideal, --lag, --quant, --adc-bits, --param-error, --machine-seed, "
                 "--units, --rpm, --list, --params, --step, --fault, --inputs");
  app.add_option("--params", o.circuit_params,
                 "with --circuit: its parameter file (default: <stem>.params.json beside it, else the file's values)");
  app.add_option("--step", o.steps, "with --circuit: input step INPUT=VALUE@T, e.g. throttle=0.7@5 or \"A_prv=2.5 mm2@5\" (repeatable; a pressure, speed, flow, displacement, area or volume needs its unit)");
  app.add_option("--fault", o.faults,
                 "with --circuit: parameter fault PARAM=FACTOR@T, the parameter times FACTOR from T on, e.g. "
                 "Rmlkg=0.5@3 (repeatable); a valve's cracking pressure or a pump's cut-in moves the element's "
                 "other pressure thresholds by the same amount");
  app.add_option("--inputs", o.circuit_inputs,
                 "with --circuit: drive it with this log's input columns (a logged run re-simulated); inputs not in "
                 "the log keep their parameter-file values. The run is on the log's clock: it starts at the first "
                 "row's time (the steady state of its inputs, or --start rest), lasts to the last row (--duration "
                 "overrides) and writes the log's own row times, so the re-run lines up row by row with the log "
                 "(--rate R: rows t0 + k/R instead); --step/--fault times are on that clock and add to it");
  app.add_option("--inputs-hold", o.inputs_hold,
                 "with --inputs: the inputs between rows. linear (default): the straight line between the rows, "
                 "as a sampled ramp was (holding each row lags a ramp by half a row); a step between two rows is "
                 "spread over that one row. step: each row held until the next (zero-order hold, as the monitor "
                 "applies a row's inputs over its tick). Every row is a hard stop of the integrator either way")
      ->check(CLI::IsMember({"linear", "step"}));
  app.add_flag("--compare", o.compare,
               "with --inputs: print per sensor channel the mean, RMS and largest residual measured - simulated "
               "over the log's rows, in the channel's unit (to stdout, or stderr when the log goes to stdout)");
  CLI11_PARSE(app, argc, argv);
  if (o.circuit.empty() && (app.count("--params") > 0 || app.count("--step") > 0 || app.count("--fault") > 0 ||
                            app.count("--inputs") > 0)) {
    std::cerr << "hstmon-sim: --params, --step, --fault and --inputs go with --circuit\n";
    return 1;
  }
  if (o.circuit_inputs.empty() && (app.count("--inputs-hold") > 0 || o.compare)) {
    std::cerr << "hstmon-sim: --inputs-hold and --compare go with --inputs\n";
    return 1;
  }
  if (o.compare && app.count("--rate") > 0) {
    std::cerr << "hstmon-sim: --compare compares row by row, on the log's own rows: it does not go with --rate\n";
    return 1;
  }
  if (!o.circuit.empty()) {
    // A circuit file names its own inputs, sensors and parameters: the thesis rig's scenarios
    // and sensor presets are the built-in thesis model's.
    for (const char* opt : {"--scenario", "--model", "--preset", "--supply-on", "--cycle", "--load", "--load-period",
                            "--load-range", "--load-seed", "--blockage"}) {
      if (app.count(opt) > 0) {
        std::cerr << "hstmon-sim: " << opt
                  << " belongs to the built-in thesis scenarios; with --circuit use --step, --fault or --inputs "
                     "(--list names what they take)\n";
        return 1;
      }
    }
    hstmon::sim_app::CircuitSimArgs c;
    c.circuit = o.circuit;
    c.params = o.circuit_params;
    c.duration = o.duration;
    c.rate = o.rate;
    c.seed = o.seed;
    c.out = o.out;
    c.start = app.count("--start") > 0 ? o.start : "steady";
    c.no_noise = o.no_noise;
    c.ideal = o.ideal;
    c.lag = o.lag_ms > 0.0 ? o.lag_ms * 1e-3 : 0.0;
    c.pressure_step = o.quant_bar > 0.0 ? o.quant_bar * kPaPerBar : 0.0;
    c.adc_bits = o.adc_bits;
    c.param_error = o.param_error;
    c.machine_seed = o.machine_seed;
    c.steps = o.steps;
    c.faults = o.faults;
    c.inputs = o.circuit_inputs;
    c.inputs_hold = o.inputs_hold;
    c.compare = o.compare;
    if (app.count("--units") > 0) c.pressure_unit = o.units;
    c.rpm = o.rpm;
    c.list = o.list;
    return hstmon::sim_app::run_circuit_sim(c);
  }
  try {
    if (o.list) {
      list_all();
      return 0;
    }
    return run(o);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "hstmon-sim: " << e.what() << '\n';
    return 1;
  }
}
