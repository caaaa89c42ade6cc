/// @file sim_app.cpp
/// hstmon-sim: a synthetic measurement log of a circuit (the built-in thesis.json unless
/// --circuit names one), integrated with its full equations (sim_circuit.hpp):
///   hstmon-sim [--circuit FILE [--params FILE]] [--step INPUT=VALUE@T ...]
///              [--fault PARAM=FACTOR@T | INPUT=FACTOR@T ...] [--start rest|steady]
///              [--inputs LOG [--inputs-hold linear|step] [--compare]]
///              [--duration S] [--rate HZ] [--seed N] [--no-noise | --ideal] [--out FILE.csv]
///              [--units bar|Pa] [--rpm] [--list]
///              [--preset NAME] [--lag MS] [--quant BAR | --adc-bits N] [--param-error F --machine-seed N]
///   a named run of the thesis rig (on a circuit with its inputs Psupl, Ps, Pbp, kp):
///              --scenario start_from_rest | prv_staircase | prv_blockage
///              --scenario rig [--start rest|steady] [--supply-on S] [--cycle ON,OFF]
///              [--load constant|steps|ramp|sine] [--load-period S] [--load-range LO,HI]
///              [--load-seed N] [--blockage T]

#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli_validators.hpp"
#include "hstmon_sensors/sensor_presets.hpp"
#include "hstmon_sim/param_fault.hpp"
#include "hstmon_sim/rig_run.hpp"
#include "hstmon_sim/thesis_scenarios.hpp"
#include "sim_circuit.hpp"

namespace {

using namespace hstmon::sim;

struct Options {
  std::string scenario;
  std::string preset;       // "" = the circuit's sensors section
  double lag_ms = -1.0;     // < 0: none (or the preset's)
  double quant_bar = -1.0;  // < 0: none (or the preset's)
  int adc_bits = 0;         // 0: none (or the preset's)
  // The rig scenario's conditions.
  double supply_on = 0.0;
  std::vector<double> cycle;  // ON,OFF [s]
  std::string load = "constant";
  double load_period = 2.0;
  std::vector<double> load_range = {0.65, 1.6};
  std::uint64_t load_seed = 1;
  double blockage = -1.0;  // ≥ 0: true kp halved from then on, logged kp unchanged
};

/// The scenarios and presets --scenario and --preset take.
void list_scenarios() {
  std::cout << "scenarios (--scenario; the thesis rig's inputs Psupl, Ps, Pbp, kp):\n";
  for (const std::string& n : thesis_scenario_names()) {
    std::cout << "  " << n << "  -  " << thesis_scenario(n)->description << '\n';
  }
  std::cout << "  rig  -  thesis rig as run (--start, --supply-on, --cycle, --load, --blockage; default 30 s)\n";
  std::cout << "sensor presets (--preset; a channel per sensor, by name):";
  for (const std::string& n : sensor_preset_names()) std::cout << ' ' << n;
  std::cout << "\n\n";
}

/// The preset with --lag, --quant and --adc-bits applied.
std::optional<SensorConfig> logger_for(const Options& o) {
  if (o.preset.empty()) return std::nullopt;
  std::optional<SensorConfig> cfg = sensor_preset(o.preset);
  if (!cfg) throw CLI::ValidationError("--preset", "unknown preset " + o.preset + " (see --list)");
  if (o.lag_ms >= 0.0) cfg = with_lag(*cfg, o.lag_ms * 1e-3);
  if (o.quant_bar >= 0.0) cfg = with_pressure_step(*cfg, o.quant_bar * kPaPerBar);
  if (o.adc_bits > 0) cfg = with_pressure_adc_bits(*cfg, o.adc_bits);
  return cfg;
}

/// The rig scenario of the options.
ThesisScenario rig_scenario(const Options& o, const std::string& start, double duration) {
  RigRun r;
  r.duration = duration > 0.0 ? duration : 30.0;
  r.from_rest = start != "steady";
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

/// The named scenario (the staircase's hold follows the sample period, rate_hz).
ThesisScenario named_scenario(const Options& o, const hstmon::sim_app::CircuitSimArgs& c) {
  if (o.scenario == "rig") return rig_scenario(o, c.start, c.duration);
  const double rate = c.rate > 0.0 ? c.rate : c.logger ? 1.0 / c.logger->sample_period : 100.0;
  std::optional<ThesisScenario> sc = thesis_scenario(o.scenario, 1.0 / rate);
  if (!sc) throw CLI::ValidationError("--scenario", "unknown scenario " + o.scenario + " (see --list)");
  return *sc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "hstmon-sim: synthetic HST measurement logs from a circuit's full equations (default: the thesis rig, "
      "thesis.json built in)"};
  Options o;
  hstmon::sim_app::CircuitSimArgs c;
  app.add_option("--circuit", c.circuit,
                 "circuit file to simulate (docs/circuits.md; default: the thesis rig, thesis.json built in)");
  app.add_option("--params", c.params,
                 "the circuit's parameter file (default: <stem>.params.json beside it, else the file's values)");
  app.add_option("--scenario", o.scenario,
                 "a named run of the thesis rig, on a circuit with its inputs Psupl, Ps, Pbp and kp: start_from_rest | "
                 "prv_staircase | prv_blockage | rig (the run set by --start, --supply-on, --cycle, --load*); its "
                 "inputs come first, --step and --fault add to them");
  app.add_option("--preset", o.preset,
                 "sensor preset instead of the circuit's sensors section, a channel per sensor by name: thesis_das | "
                 "fast | rig_fast (the thesis rig's) | paper_logger (paper.json's); its rate unless --rate");
  app.add_option("--rate", c.rate, "sample rate [Hz] (default: the preset's, else 100)")
      ->check(hstmon::cli::positive_number());
  app.add_option("--duration", c.duration, "run length [s] (default: the scenario's, else 10)")
      ->check(hstmon::cli::positive_number());
  app.add_option("--seed", c.seed, "noise seed (std::mt19937_64)");
  app.add_option("--out", c.out, "output CSV file, - for stdout");
  app.add_flag("--no-noise", c.no_noise, "no sensor noise (lag and ADC kept)");
  app.add_flag("--ideal", c.ideal, "ideal sensors: the reference solution itself");
  app.add_option("--units", c.pressure_unit, "pressure columns in bar | Pa (default: the circuit file's)")
      ->check(CLI::IsMember({"bar", "Pa"}));
  app.add_flag("--rpm", c.rpm, "speed columns in rpm (default: the circuit file's unit)");
  app.add_flag("--list", c.list,
               "list the scenarios, presets and the circuit's inputs, parameters and sensors, then exit");
  app.add_option("--lag", o.lag_ms,
                 "transducer time constant of every channel [ms], 0 = none (default: the preset's, else none)")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--quant", o.quant_bar, "pressure ADC step [bar], 0 = none (default: the preset's, else none)")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--adc-bits", o.adc_bits, "pressure ADC bits over the transmitter range (instead of --quant)")
      ->check(CLI::Range(4, 24))
      ->excludes("--quant");
  app.add_option("--param-error", c.param_error,
                 "the machine: every parameter its monitor treats as uncertain off the parameter file by uniform ±F, "
                 "e.g. 0.02")
      ->check(CLI::Range(0.0, 0.5));
  app.add_option("--machine-seed", c.machine_seed, "seed of the parameter error");
  app.add_option("--start", c.start,
                 "rest | steady (default: the scenario's, else steady; rig: rest, the logger runs before the supply)")
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
  app.add_option("--blockage", o.blockage,
                 "rig: 50 % PRV blockage (true kp halved, logged kp kept) from T [s]; on any run: --fault kp=0.5@T")
      ->check(hstmon::cli::non_negative_number());
  app.add_option("--step", c.steps,
                 "input step INPUT=VALUE@T, e.g. throttle=0.7@5 or \"A_prv=2.5 mm2@5\" (repeatable; a pressure, speed, "
                 "flow, displacement, area or volume needs its unit)");
  app.add_option("--fault", c.faults,
                 "fault from T on (repeatable): PARAM=FACTOR@T, the parameter times FACTOR, e.g. Rmlkg=0.5@3 (a "
                 "valve's cracking pressure or a pump's cut-in moves the element's other pressure thresholds by the "
                 "same amount); INPUT=FACTOR@T, the machine gets FACTOR times the logged input, which the log keeps, "
                 "e.g. kp=0.5@80 (a PRV half blocked)");
  app.add_option("--inputs", c.inputs,
                 "drive the circuit with this log's input columns (a logged run re-simulated); inputs not in "
                 "the log keep their parameter-file values. The run is on the log's clock: it starts at the first "
                 "row's time (the steady state of its inputs, or --start rest), lasts to the last row (--duration "
                 "overrides) and writes the log's own row times, so the re-run lines up row by row with the log "
                 "(--rate R: rows t0 + k/R instead); --step/--fault times are on that clock and add to it");
  app.add_option("--inputs-hold", c.inputs_hold,
                 "with --inputs: the inputs between rows. linear (default): the straight line between the rows, "
                 "as a sampled ramp was (holding each row lags a ramp by half a row); a step between two rows is "
                 "spread over that one row. step: each row held until the next (zero-order hold, as the monitor "
                 "applies a row's inputs over its tick). Every row is a hard stop of the integrator either way")
      ->check(CLI::IsMember({"linear", "step"}));
  app.add_flag("--compare", c.compare,
               "with --inputs: print per sensor channel the mean, RMS and largest residual measured - simulated "
               "over the log's rows, in the channel's unit (to stdout, or stderr when the log goes to stdout)");
  CLI11_PARSE(app, argc, argv);
  if (c.inputs.empty() && (app.count("--inputs-hold") > 0 || c.compare)) {
    std::cerr << "hstmon-sim: --inputs-hold and --compare go with --inputs\n";
    return 1;
  }
  if (c.compare && app.count("--rate") > 0) {
    std::cerr << "hstmon-sim: --compare compares row by row, on the log's own rows: it does not go with --rate\n";
    return 1;
  }
  if (!o.scenario.empty() && !c.inputs.empty()) {
    std::cerr << "hstmon-sim: --scenario and --inputs both set the inputs: give one\n";
    return 1;
  }
  if (o.scenario != "rig") {
    for (const char* opt :
         {"--supply-on", "--cycle", "--load", "--load-period", "--load-range", "--load-seed", "--blockage"}) {
      if (app.count(opt) > 0) {
        std::cerr << "hstmon-sim: " << opt << " sets up --scenario rig (on any run, --step and --fault)\n";
        return 1;
      }
    }
  }
  try {
    c.preset = o.preset;
    c.logger = logger_for(o);
    if (!c.logger) {
      c.lag = o.lag_ms > 0.0 ? o.lag_ms * 1e-3 : 0.0;
      c.pressure_step = o.quant_bar > 0.0 ? o.quant_bar * kPaPerBar : 0.0;
      c.adc_bits = o.adc_bits;
    }
    if (c.list) {
      list_scenarios();
    } else if (!o.scenario.empty()) {
      c.scenario = named_scenario(o, c);
    }
    return hstmon::sim_app::run_circuit_sim(c);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "hstmon-sim: " << e.what() << '\n';
    return 1;
  }
}
