/// @file log_layout.cpp
#include "hstmon_sim/log_layout.hpp"

namespace hstmon::sim {

namespace {

double pressure_factor(PressureUnit u) { return u == PressureUnit::kBar ? 1.0 / kPaPerBar : 1.0; }
const char* pressure_name(PressureUnit u) { return u == PressureUnit::kBar ? "bar" : "Pa"; }
double speed_factor(SpeedUnit u) { return u == SpeedUnit::kRpm ? 1.0 / kRadPerSecPerRpm : 1.0; }
const char* speed_name(SpeedUnit u) { return u == SpeedUnit::kRpm ? "rpm" : "rad/s"; }

}  // namespace

std::vector<LogColumn> thesis_log_columns(const LogUnits& units) {
  const std::string p = pressure_name(units.pressure);
  return {{"t", "s"},      {"p_sup", p}, {"p_s", p}, {"p_bp", p}, {"kp", "m^3/(s*Pa^0.5)"},
          {"p_mi", p},     {"p_mo", p},  {"p_pp", p},   {"w_m", speed_name(units.speed)}};
}

std::vector<LogColumn> paper_log_columns(const LogUnits& units) {
  const std::string p = pressure_name(units.pressure);
  return {{"t", "s"},   {"a_dcv", "m^2"}, {"a_prv", "m^2"},
          {"p_pump", p}, {"p_mi", p},      {"p_pp", p}, {"w_m", speed_name(units.speed)}};
}

std::vector<double> thesis_log_row(const Measurement<ThesisInputs<double>>& m, const LogUnits& units) {
  const double fp = pressure_factor(units.pressure);
  const double fw = speed_factor(units.speed);
  return {m.t,           m.u.Psupl * fp, m.u.Ps * fp,    m.u.Pbp * fp, m.u.kp,
          m.y[0] * fp,   m.y[1] * fp,    m.y[2] * fp,    m.y[3] * fw};
}

std::vector<double> paper_log_row(const Measurement<PaperInputs<double>>& m, const LogUnits& units) {
  const double fp = pressure_factor(units.pressure);
  const double fw = speed_factor(units.speed);
  return {m.t, m.u.A_dcv, m.u.A_prv, m.y[0] * fp, m.y[1] * fp, m.y[2] * fp, m.y[3] * fw};
}

void write_log(std::ostream& os, const ThesisMeasurements& ms, const LogUnits& units) {
  CsvLogWriter w(os, thesis_log_columns(units));
  for (const auto& m : ms) w.write_row(thesis_log_row(m, units));
}

void write_log(std::ostream& os, const PaperMeasurements& ms, const LogUnits& units) {
  CsvLogWriter w(os, paper_log_columns(units));
  for (const auto& m : ms) w.write_row(paper_log_row(m, units));
}

}  // namespace hstmon::sim
