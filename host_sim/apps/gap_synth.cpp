// hstmon-gap-synth: writes a synthetic "machine" log with chosen effects switched on in
// the truth simulator (for blind tests and the gap benchmark).
//   hstmon-gap-synth --profile A --duration 15 --rate 1000 --effect coulomb_friction=1.5 --out a.csv
#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "hstmon_gap/gap.hpp"
#include "hstmon_gap/synth.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/log_writer.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hstmon-gap-synth: synthetic HST logs with unmodelled effects switched on"};
  char profile = 'A';
  double duration = 15, rate = 1000;
  std::uint64_t seed = 1;
  std::vector<std::string> effects;
  std::string out, start = "steady";
  double g_pp = 0;
  app.add_option("--start", start, "truth starts at 'steady' state or at 'rest' (supply on at the first sample)")
      ->check(CLI::IsMember({"steady", "rest"}));
  app.add_option("--load-pump-leak", g_pp, "truth only, outside the library: leakage conductance loading-pump node to drain [m^3/(s*Pa)]");
  std::string inputs_from;
  double noise_p = 5e3, noise_w = 0.3;
  app.add_option("--inputs", inputs_from, "take t and the inputs (p_sup, kp, ...) from this log instead of a profile");
  app.add_option("--noise-p", noise_p, "pressure noise [Pa]");
  app.add_option("--noise-w", noise_w, "speed noise [rad/s]");
  app.add_option("--profile", profile, "input staircase A or B");
  app.add_option("--duration", duration, "[s]");
  app.add_option("--rate", rate, "[Hz]");
  app.add_option("--seed", seed, "noise seed");
  app.add_option("--effect", effects, "name=v1[:v2][@channel] (SI values; channel 0..3 for sensor_offset)");
  app.add_option("--out", out, "output CSV")->required();
  CLI11_PARSE(app, argc, argv);
  hstmon::gap::ExtendedModel truth;
  for (const auto& s : effects) {
    const auto eq = s.find('=');
    const auto e = hstmon::gap::effect_from_name(s.substr(0, eq));
    if (!e || eq == std::string::npos) {
      std::fprintf(stderr, "bad --effect %s\n", s.c_str());
      return 1;
    }
    hstmon::gap::ActiveEffect a;
    a.id = *e;
    std::string rest = s.substr(eq + 1);
    const auto at = rest.find('@');
    if (at != std::string::npos) {
      a.channel = std::stoi(rest.substr(at + 1));
      rest = rest.substr(0, at);
    }
    std::stringstream ss(rest);
    std::string v;
    while (std::getline(ss, v, ':')) a.values.push_back(std::stod(v));
    truth.effects.push_back(a);
  }
  truth.extras.g_pp = g_pp;
  auto u = hstmon::gap::staircase_profile(profile, duration, rate);
  if (!inputs_from.empty()) {
    const auto in = hstmon::host::read_log(inputs_from);
    if (!in.ok()) {
      std::fprintf(stderr, "%s\n", in.error->to_string().c_str());
      return 2;
    }
    u = hstmon::gap::inputs_from_log(in, hstmon::ThesisInputs<double>{});
  }
  u.start = start == "rest" ? hstmon::gap::StartRule::kRest : hstmon::gap::StartRule::kSteady;
  const auto log = hstmon::gap::synth_log(truth, u, {noise_p, noise_w}, seed, out);
  if (!log.ok()) {
    std::fprintf(stderr, "%s\n", log.error->message.c_str());
    return 2;
  }
  const auto err = hstmon::host::write_log(out, log, {{hstmon::host::Signal::kPSup, "bar"},
                                                      {hstmon::host::Signal::kPBp, "bar"},
                                                      {hstmon::host::Signal::kPMi, "bar"},
                                                      {hstmon::host::Signal::kPMo, "bar"},
                                                      {hstmon::host::Signal::kPPp, "bar"},
                                                      {hstmon::host::Signal::kWm, "rpm"}});
  if (err) {
    std::fprintf(stderr, "%s\n", err->to_string().c_str());
    return 2;
  }
  return 0;
}
