/// @file thesis_scenarios.cpp
#include "hstmon_sim/thesis_scenarios.hpp"

#include <algorithm>
#include <stdexcept>

#include "hstmon/circuit/thesis_circuit_model.hpp"

namespace hstmon::sim {

namespace {

ThesisInputs<double> table_2_2_inputs(double kp_factor) {
  ThesisInputs<double> u;  // Table 2.2 defaults
  u.kp = kThesisKpNominal * kp_factor;
  return u;
}

}  // namespace

ThesisScenario thesis_start_from_rest(double duration) {
  ThesisScenario sc;
  sc.name = "start_from_rest";
  sc.description = "thesis rig from rest, Table 2.2 supply applied at t = 0";
  sc.schedule = {{0.0, table_2_2_inputs(1.0)}};
  sc.duration = duration;
  sc.initial = InitialCondition::kRest;
  validate(sc);
  return sc;
}

ThesisScenario thesis_prv_staircase(double hold) {
  ThesisScenario sc;
  sc.name = "prv_staircase";
  sc.description = "thesis rig, steady, kp stepped through 1.6/1.3/1.0/0.8/0.65/0.5 x 4.41e-8";
  double t = 0.0;
  for (double f : kStaircaseFactors) {
    sc.schedule.push_back({t, table_2_2_inputs(f)});
    t += hold;
  }
  sc.duration = t;
  sc.initial = InitialCondition::kSteady;
  validate(sc);
  return sc;
}

ThesisScenario thesis_prv_blockage() {
  ThesisScenario sc;
  sc.name = "prv_blockage";
  sc.description = "thesis rig steady at Table 2.2, kp halved (50 % PRV blockage) at t = 80 s; the log records the nominal kp (the fault is not a setting)";
  sc.schedule = {{0.0, table_2_2_inputs(1.0)}, {80.0, table_2_2_inputs(0.5)}};
  sc.logged = {{0.0, table_2_2_inputs(1.0)}};
  sc.duration = 120.0;
  sc.initial = InitialCondition::kSteady;
  validate(sc);
  return sc;
}

std::vector<std::string> thesis_scenario_names() { return {"start_from_rest", "prv_staircase", "prv_blockage"}; }

std::optional<ThesisScenario> thesis_scenario(std::string_view name, double sample_period) {
  if (name == "start_from_rest") return thesis_start_from_rest();
  if (name == "prv_staircase") return thesis_prv_staircase(std::max(2.0, 10.0 * sample_period));
  if (name == "prv_blockage") return thesis_prv_blockage();
  return std::nullopt;
}

ThesisState<double> thesis_rest_state(const ThesisInputs<double>& u) {
  ThesisState<double> x;
  x.Pmi = u.Ps;
  x.Pmo = u.Ps;
  x.Ppp = u.Pbp;
  x.w_m = 0.0;
  return x;
}

ThesisState<double> thesis_steady_state(const ThesisInputs<double>& u, const ThesisParams<double>& p) {
  ThesisCircuitModel<double> m(p);
  m.set_inputs(u);
  ThesisCircuitModel<double>::State s;
  if (!ThesisCircuitModel<double>::params_valid(p) || !m.steady_state(s)) {
    throw std::invalid_argument("thesis_steady_state: the inputs admit no steady state");
  }
  const ThesisCircuitModel<double>::Output y = m.outputs(s);
  ThesisState<double> x;
  x.Pmi = y[kChPmi];
  x.Pmo = y[kChPmo];
  x.Ppp = y[kChPpp];
  x.w_m = y[kChWm];
  return x;
}

ThesisState<double> thesis_initial_state(const ThesisScenario& sc, const ThesisParams<double>& p) {
  validate(sc);
  const ThesisInputs<double>& u0 = sc.schedule.front().u;
  return sc.initial == InitialCondition::kSteady ? thesis_steady_state(u0, p) : thesis_rest_state(u0);
}

}  // namespace hstmon::sim
