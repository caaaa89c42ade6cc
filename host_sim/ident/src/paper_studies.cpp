/// @file paper_studies.cpp
/// Figs. 7–9 of seed 001 by stiff simulation of the paper model.
#include "hstmon_ident/paper_studies.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "hstmon_sim/paper_scenarios.hpp"
#include "hstmon_sim/scenario.hpp"
#include "hstmon_sim/simulate.hpp"

namespace hstmon::ident {

namespace {

void finish(StudyCurve& c) {
  c.final_value = c.y.back();
  const auto it = std::max_element(c.y.begin(), c.y.end());
  c.peak = *it;
  c.t_peak = c.t[static_cast<std::size_t>(it - c.y.begin())];
  const double band = 0.02 * std::fabs(c.final_value);
  c.settling_time = 0.0;
  for (std::size_t i = c.y.size(); i-- > 0;) {
    if (std::fabs(c.y[i] - c.final_value) > band) {
      c.settling_time = c.t[std::min(i + 1, c.t.size() - 1)];
      break;
    }
  }
  c.rise_time = c.t.back();
  for (std::size_t i = 0; i < c.y.size(); ++i) {
    if (c.y[i] >= 0.9 * c.final_value) {
      c.rise_time = c.t[i];
      break;
    }
  }
}

StudyCurve run(const PaperParams<double>& p, const PaperInputs<double>& u, double duration, double dt, int output) {
  sim::PaperScenario sc = sim::paper_start(duration);
  for (auto& step : sc.schedule) step.u = u;
  const std::vector<double> times = sim::uniform_times(duration, dt);
  const sim::PaperTrajectory tr = sim::simulate(sc, times, p);
  StudyCurve c;
  for (const auto& pt : tr) {
    c.t.push_back(pt.t);
    c.y.push_back(pt.x[output]);
  }
  finish(c);
  return c;
}

ParameterStudy vs_K(const std::vector<double>& K, double duration, double dt, const PaperParams<double>& base,
                    int output) {
  ParameterStudy s;
  const bool speed = output == PaperModel<double>::kWm;
  s.name = speed ? "fig7_speed_vs_K" : "fig9_pump_pressure_vs_K";
  s.title = speed ? "Fig. 7: motor speed for varying bulk stiffness K" : "Fig. 9: pump pressure for varying bulk stiffness K";
  s.output = speed ? "w_m" : "p_pump";
  s.unit = speed ? "rpm" : "bar";
  s.scale = speed ? 30.0 / M_PI : 1e-5;
  for (double k : K) {
    PaperParams<double> p = base;
    p.Kpmp = p.Kpm = p.Kpp = k;
    StudyCurve c = run(p, PaperInputs<double>{}, duration, dt, output);
    c.value = k;
    c.label = fmt::format("K = {:.3g} Pa/m³", k);
    s.curves.push_back(std::move(c));
  }
  return s;
}

}  // namespace

ParameterStudy study_speed_vs_bulk_stiffness(const std::vector<double>& K, double duration, double dt,
                                             const PaperParams<double>& base) {
  return vs_K(K, duration, dt, base, PaperModel<double>::kWm);
}

ParameterStudy study_pump_pressure_vs_bulk_stiffness(const std::vector<double>& K, double duration, double dt,
                                                     const PaperParams<double>& base) {
  return vs_K(K, duration, dt, base, PaperModel<double>::kPs);
}

ParameterStudy study_speed_vs_dcv_area(const std::vector<double>& areas, double duration, double dt,
                                       const PaperParams<double>& base) {
  ParameterStudy s;
  s.name = "fig8_speed_vs_Adcv";
  s.title = "Fig. 8: motor speed for varying DCV port area";
  s.output = "w_m";
  s.unit = "rpm";
  s.scale = 30.0 / M_PI;
  for (double a : areas) {
    PaperInputs<double> u;
    u.A_dcv = a;
    StudyCurve c = run(base, u, duration, dt, PaperModel<double>::kWm);
    c.value = a;
    c.label = fmt::format("A_dcv = {:.3g} m²", a);
    s.curves.push_back(std::move(c));
  }
  return s;
}

}  // namespace hstmon::ident
