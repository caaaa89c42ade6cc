/// @file sim_app.cpp
/// hstmon-sim: writes a synthetic measurement log of a scenario.
///   hstmon-sim --scenario prv_blockage --rate 100 --seed 1 --out FILE.csv
///              [--no-noise] [--ideal] [--model thesis|paper] [--preset NAME]
///              [--duration S] [--units bar|Pa] [--rpm] [--list]

#include <CLI/CLI.hpp>
#include <cstdint>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "hstmon_sim/sim.hpp"

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
};

void list_all() {
  std::cout << "thesis scenarios:\n";
  for (const std::string& n : thesis_scenario_names()) {
    std::cout << "  " << n << "  -  " << thesis_scenario(n)->description << '\n';
  }
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

int run(const Options& o) {
  LogUnits units;
  units.pressure = (o.units == "Pa") ? PressureUnit::kPa : PressureUnit::kBar;
  units.speed = o.rpm ? SpeedUnit::kRpm : SpeedUnit::kRadPerSec;

  std::optional<ThesisScenario> ts;
  std::optional<PaperScenario> ps;
  const bool paper_wanted = (o.model == "paper");
  if (o.scenario.empty()) {
    if (paper_wanted) ps = paper_start(); else ts = thesis_prv_blockage();
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
    apply_duration(*ts, o.duration);
    write_log(*os, measure(*ts, sensors_for(o, false), o.seed), units);
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
                 "start_from_rest | prv_staircase | prv_blockage | paper_start (default: prv_blockage, "
                 "or paper_start with --model paper)");
  app.add_option("--model", o.model, "thesis | paper (checked against the scenario)")
      ->check(CLI::IsMember({"thesis", "paper"}));
  app.add_option("--preset", o.preset, "sensor preset: thesis_das | fast | paper_logger (default: fast / paper_logger)");
  app.add_option("--rate", o.rate, "sample rate [Hz] (default: the preset's)")->check(CLI::PositiveNumber);
  app.add_option("--duration", o.duration, "run length [s] (default: the scenario's)")->check(CLI::PositiveNumber);
  app.add_option("--seed", o.seed, "noise seed (std::mt19937_64)");
  app.add_option("--out", o.out, "output CSV file, - for stdout");
  app.add_flag("--no-noise", o.no_noise, "no sensor noise (lag and ADC kept)");
  app.add_flag("--ideal", o.ideal, "ideal sensors: the reference solution itself");
  app.add_option("--units", o.units, "pressure unit: bar | Pa")->check(CLI::IsMember({"bar", "Pa"}));
  app.add_flag("--rpm", o.rpm, "speed in rpm (default rad/s)");
  app.add_flag("--list", o.list, "list scenarios and presets, then exit");
  CLI11_PARSE(app, argc, argv);
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
