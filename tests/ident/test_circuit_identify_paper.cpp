// identify --circuit with the paper rig's analyses and with a setting per window
// (hstmon_ident circuit_fit.hpp, paper_circuit.hpp; hstmon identify):
//  - a log without the column of the input that sets the load: every steady window gets
//    its own value of it, fitted with the named parameters, and both come back;
//  - --paper with --circuit gives the numbers it gives without, plus the circuit's values
//    beside them; --paper and --studies need no LOG files with a circuit either.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../support/cli_run.hpp"
#include "../support/loaded_circuit.hpp"
#include "../support/sim_options.hpp"
#include "hstmon/pump_curve.hpp"
#include "hstmon_circuit/circuit_sim.hpp"
#include "hstmon_ident/circuit_fit.hpp"
#include "hstmon_ident/paper_circuit.hpp"
#include "hstmon_sensors/gaussian.hpp"

namespace {

namespace ct = hstmon::circuit_tools;
namespace id = hstmon::ident;
namespace fs = std::filesystem;

// The paper rig's log (200 Hz, 26 s) with Rmlkg × 0.8 and the PRV area stepped: the
// settings A_prv = 3.525 (nominal), 2.5, 3, 4.5 mm², then A_dcv 5 → 4 mm² at 4.5. The last
// setting is held 10 s: without the PRV column the settle time is judged at the nominal
// A_prv, where the rig is slower.
ct::CircuitLog stepped_log(const ct::LoadedCircuit& c) {
  ct::LoadedCircuit m = c;
  m.values.params.v[c.file.param_index("Rmlkg")] *= 0.8;
  ct::CircuitSimOptions o = hstmon_test::sim_options(26.0, 200.0, 3);
  for (const char* s : {"A_prv=2.5 mm2@4", "A_prv=3 mm2@8", "A_prv=4.5 mm2@12", "A_dcv=4 mm2@16"}) {
    ct::InputStep st;
    const auto err = ct::parse_input_step(s, c.file, st);
    EXPECT_FALSE(err.has_value()) << *err;
    o.steps.push_back(st);
  }
  return ct::simulate_circuit(m, o);
}

// The PRV area the machine held at time t [m²].
double prv_area_at(double t) { return t < 4.0 ? 3.525e-6 : t < 8.0 ? 2.5e-6 : t < 12.0 ? 3e-6 : 4.5e-6; }

// Tolerance on a per-window area: a window averages 200–1000 rows of 0.05 bar noise on
// ΔP ≈ 10–30 bar, so one area is known to ~1e-4 (relative: A ∝ Q/√ΔP; the fit's SE says
// 0.6–1.8e-4). 0.2 % is 10 SE at least: room for the few rows of transient the step
// search (0.05 s blocks) may leave at a window's end, none for a wrong setting.
constexpr double kAreaTolerance = 0.002;

TEST(CircuitIdentifyPerWindow, RecoversTheUnloggedLoadSettingAndTheParameter) {
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  ct::CircuitLog log = stepped_log(c);
  const int a_prv = c.file.input_index("A_prv");
  ASSERT_GE(a_prv, 0);
  log.inputs[static_cast<std::size_t>(a_prv)].clear();  // the logger did not record the PRV setting
  id::CircuitFitOptions o;
  o.fit = {"Rmlkg"};
  o.setting_per_window = true;
  const id::CircuitFitResult r = id::fit_circuit(c, {log}, o);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  ASSERT_EQ(r.window_inputs, std::vector<std::string>{"A_prv"});
  std::string said;
  for (const auto& p : r.points) said += " [" + std::to_string(p.t0) + ", " + std::to_string(p.t1) + "]";
  for (const auto& n : r.notes) said += "\n" + n;
  ASSERT_EQ(r.points.size(), 5u) << "one point per setting: the outputs' steps split the log:" << said;
  for (const auto& p : r.points) {
    ASSERT_EQ(p.window_value.size(), 1u);
    const double truth = prv_area_at(0.5 * (p.t0 + p.t1));
    EXPECT_NEAR(p.window_value[0] / truth, 1.0, kAreaTolerance) << "t = " << p.t0 << " … " << p.t1;
    EXPECT_NEAR(p.window_start[0] / c.values.inputs.v[a_prv], 1.0, 1e-12) << "not logged: starts at the nominal value";
    std::printf("  t = %6.3f … %6.3f s  A_prv %.5g ± %.2g mm² (truth %.5g)\n", p.t0, p.t1, p.window_value[0] * 1e6,
                p.window_se[0] * 1e6, truth * 1e6);
    EXPECT_LT(p.window_se[0] / p.window_value[0], 0.01);
  }
  std::printf("  Rmlkg / truth %.5f ± %.2g\n", r.value[0] / c.values.params.v[c.file.param_index("Rmlkg")] / 0.8,
              r.rel_se[0]);
  EXPECT_NEAR(r.value[0] / c.values.params.v[c.file.param_index("Rmlkg")], 0.8, 0.005);
  EXPECT_LT(r.rms_after, 1.0);
  EXPECT_GT(r.rms_before, 20.0);
}

TEST(CircuitIdentifyPerWindow, EveryInputLoggedNeedsTheLoadInputNamed) {
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  const ct::CircuitLog log = stepped_log(c);
  id::CircuitFitOptions o;
  o.fit = {"Rmlkg"};
  o.setting_per_window = true;
  const id::CircuitFitResult refused = id::fit_circuit(c, {log}, o);
  ASSERT_TRUE(refused.error.has_value());
  EXPECT_NE(refused.error->find("--window-input"), std::string::npos) << *refused.error;
  // Named, the logged values only start it: the logged settings come back.
  o.window_inputs = {"A_prv"};
  const id::CircuitFitResult r = id::fit_circuit(c, {log}, o);
  ASSERT_FALSE(r.error.has_value()) << *r.error;
  ASSERT_EQ(r.points.size(), 5u);
  for (const auto& p : r.points) EXPECT_NEAR(p.window_value[0] / prv_area_at(p.t0), 1.0, kAreaTolerance);
  o.window_inputs = {"A_nope"};
  const id::CircuitFitResult bad = id::fit_circuit(c, {log}, o);
  ASSERT_TRUE(bad.error.has_value());
  EXPECT_NE(bad.error->find("A_nope"), std::string::npos);
}

TEST(PaperCircuit, MapsTheCompensatedPumpAndTheNamedOrifices) {
  const ct::LoadedCircuit c = hstmon_test::load_example("paper");
  const auto pumps = id::circuit_pump_curves(c);
  ASSERT_EQ(pumps.size(), 1u);
  EXPECT_EQ(pumps[0].element, "pump_b");
  EXPECT_EQ(pumps[0].params[1].name, "Rpump");
  EXPECT_DOUBLE_EQ(pumps[0].params[2].value, 75e5);
  const auto prv = id::circuit_orifices_named(c, "PRV");
  ASSERT_EQ(prv.size(), 1u);
  EXPECT_EQ(prv[0].area.name, "A_prv");
  EXPECT_TRUE(prv[0].area.input);
  EXPECT_DOUBLE_EQ(prv[0].area.value, 3.525e-6);
  EXPECT_DOUBLE_EQ(prv[0].cd.value, 0.61);
  EXPECT_TRUE(id::circuit_orifices_named(c, "motor").empty()) << "a motor is no orifice";
}

// ---- the CLI ----

// A paper table: Table I's pump curve with 0.5 % flow noise (91 points to 90 bar), and the
// paper's DCV and PRV openings with 2 % flow noise, as tests/ident/test_paper_fits.cpp draws them.
std::string write_paper_table(const fs::path& dir) {
  hstmon::PumpCurveParams<double> truth;
  hstmon::PumpCurve<double> curve;
  EXPECT_TRUE(curve.make(truth));
  hstmon::sim::GaussianSource g(5);
  std::ostringstream t;
  t.precision(10);
  t << "kind,label,p[Pa],q[m3/s]\n";
  for (int i = 0; i <= 90; ++i)
    t << "pump,," << 1e5 * i << "," << curve.flow(1e5 * i) + 0.005 * truth.Q0 * g.next() << "\n";
  const double dcv[4] = {3.86e-6, 4.29e-6, 4.43e-6, 4.77e-6}, prv[4] = {3.525e-6, 1.95e-6, 1.93e-6, 1.769e-6};
  for (int k = 0; k < 8; ++k) {
    const double area = k < 4 ? dcv[k] : prv[k - 4], lo = k < 4 ? 1e5 : 10e5, hi = k < 4 ? 20e5 : 80e5;
    const double qmax = 0.61 * area * std::sqrt(2.0 * hi / 870.0);
    for (int i = 0; i < 15; ++i) {
      const double dp = lo + (hi - lo) * i / 14.0;
      t << (k < 4 ? "dcv" : "prv") << ",A" << k % 4 + 1 << "," << dp << ","
        << 0.61 * area * std::sqrt(2.0 * dp / 870.0) + 0.02 * qmax * g.next() << "\n";
    }
  }
  const fs::path file = dir / "paper_table.csv";
  std::ofstream(file) << t.str();
  return file.string();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hstmon_ident_circuit_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

nlohmann::json json_of(const hstmon_test::CliRun& run) {
  // --json prints one object on stdout; stderr (2>&1) may carry notes before it.
  const std::size_t at = run.out.find('{');
  return at == std::string::npos ? nlohmann::json() : nlohmann::json::parse(run.out.substr(at), nullptr, false);
}

const std::string kPaperCircuit = hstmon_test::example_circuit("paper.json");

TEST(IdentifyCli, PaperTableWithACircuitGivesTheSameFitAndTheCircuitBesideIt) {
  const fs::path d = fresh_dir("paper");
  const std::string table = write_paper_table(d);
  const auto plain = hstmon_test::run_hstmon("identify --paper " + table + " --json");
  const auto circ = hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --paper " + table + " --json");
  ASSERT_EQ(plain.exit_code, 0) << plain.out;
  ASSERT_EQ(circ.exit_code, 0) << circ.out;
  const nlohmann::json a = json_of(plain), b = json_of(circ);
  ASSERT_TRUE(a.contains("paper") && b.contains("paper")) << circ.out;
  EXPECT_EQ(a["paper"]["pump_curve"], b["paper"]["pump_curve"]);
  EXPECT_EQ(a["paper"]["prv"], b["paper"]["prv"]) << "the circuit's Cd and ρ are the defaults'";
  const auto& pump = b["paper"]["circuit"]["pump"];
  ASSERT_EQ(pump.size(), 1u);
  EXPECT_EQ(pump[0]["element"], "pump_b");
  ASSERT_EQ(pump[0]["parameters"].size(), 5u);
  for (const auto& p : pump[0]["parameters"]) {
    // The table was drawn from Table I, the circuit's values: each inside its interval.
    EXPECT_TRUE(p["inside_ci"].get<bool>()) << p.dump();
    EXPECT_LT(std::fabs(p["difference_pct"].get<double>()), 10.0) << p.dump();
  }
  // The PRV's nominal area is the paper's opening A1.
  const auto& prv = b["paper"]["circuit"]["prv"];
  ASSERT_FALSE(prv.empty());
  EXPECT_EQ(prv[0]["opening"], "A1");
  EXPECT_LT(std::fabs(prv[0]["difference_pct"].get<double>()), 2.0);
  const auto text = hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --paper " + table);
  EXPECT_NE(text.out.find("beside circuit paper's pump_b"), std::string::npos) << text.out;
}

TEST(IdentifyCli, StudiesWithACircuitLandInItsReport) {
  const fs::path d = fresh_dir("studies");
  EXPECT_EQ(hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --studies").exit_code, 1)
      << "--studies draws into --report DIR";
  const auto run = hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --paper " + write_paper_table(d) +
                                           " --studies --report " + (d / "rep").string());
  ASSERT_EQ(run.exit_code, 0) << run.out;
  std::ifstream md(d / "rep" / "report.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("Pump curve beside circuit paper's pump_b"), std::string::npos);
  EXPECT_NE(text.find("Parameter study"), std::string::npos);
  EXPECT_TRUE(fs::exists(d / "rep" / "report.html"));
}

// A log's text without one column (by name, in the header row and every row after it).
std::string without_column(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line, out;
  long col = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) f.push_back(cell);
    if (col < 0) {
      for (std::size_t i = 0; i < f.size(); ++i) {
        if (f[i].rfind(name, 0) == 0) col = static_cast<long>(i);
      }
    }
    if (col >= 0 && static_cast<std::size_t>(col) < f.size()) {
      f.erase(f.begin() + col);
      line.clear();
      for (std::size_t i = 0; i < f.size(); ++i) line += (i ? "," : "") + f[i];
    }
    out += line + "\n";
  }
  return out;
}

TEST(IdentifyCli, SettingPerWindowFitsTheUnloggedInput) {
  const fs::path d = fresh_dir("window");
  // examples/circuits/paper.csv: 10 s at 200 Hz, A_prv 3.525 → 2.5 mm² at 5 s.
  std::ifstream in(hstmon_test::example_circuit("paper.csv"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path log = d / "no_prv.csv";
  std::ofstream(log) << without_column(text, "a_prv");
  const std::string base = "identify --circuit " + kPaperCircuit + " --fit Rmlkg " + log.string();
  const auto run = hstmon_test::run_hstmon(base + " --setting-per-window --json");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const nlohmann::json j = json_of(run);
  ASSERT_EQ(j["window_inputs"], nlohmann::json::array({"A_prv"})) << run.out;
  ASSERT_EQ(j["points"].size(), 2u) << run.out;
  const double truth[2] = {3.525e-6, 2.5e-6};
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(j["points"][k]["window_inputs"]["A_prv"]["value"].get<double>() / truth[k], 1.0, kAreaTolerance);
  }
  const auto txt = hstmon_test::run_hstmon(base + " --setting-per-window");
  EXPECT_NE(txt.out.find("window inputs fitted per operating point"), std::string::npos) << txt.out;
  // With every input logged, the load input is named.
  const auto all = hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --fit Rmlkg " +
                                           hstmon_test::example_circuit("paper.csv") + " --setting-per-window");
  EXPECT_EQ(all.exit_code, 2);
  EXPECT_NE(all.out.find("--window-input"), std::string::npos) << all.out;
  const auto named = hstmon_test::run_hstmon("identify --circuit " + kPaperCircuit + " --fit Rmlkg " +
                                             hstmon_test::example_circuit("paper.csv") +
                                             " --window-input A_prv --json");
  EXPECT_EQ(named.exit_code, 0) << named.out;
}

}  // namespace
