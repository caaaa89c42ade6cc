/// @file log_layout.cpp
#include "hstmon_sim/log_layout.hpp"

#include <stdexcept>

namespace hstmon::sim {

namespace {

using host::Signal;

const char* pressure_name(PressureUnit u) { return u == PressureUnit::kBar ? "bar" : "Pa"; }
const char* speed_name(SpeedUnit u) { return u == SpeedUnit::kRpm ? "rpm" : "rad/s"; }

// Header and rows through the host port's writer, so the simulator writes exactly what
// the reader reads.
template <class Ms, class Row>
void write(std::ostream& os, const Ms& ms, std::vector<host::CsvColumn> cols, Row row) {
  host::CsvWriter w;
  host::WriteOptions opt;
  opt.precision = 10;
  if (auto err = w.open_memory(std::move(cols), opt)) throw std::invalid_argument(err->to_string());
  for (const auto& m : ms) {
    if (!w.write_row(row(m))) throw std::runtime_error(w.error() ? w.error()->to_string() : "write_row failed");
  }
  w.close();
  os << w.str();
}

}  // namespace

std::vector<host::CsvColumn> thesis_log_columns(const LogUnits& units) {
  const std::string p = pressure_name(units.pressure);
  return {host::column_for(Signal::kT, "s"),   host::column_for(Signal::kPSup, p), host::column_for(Signal::kPS, p),
          host::column_for(Signal::kPBp, p),   host::column_for(Signal::kKp, "m^3/(s*Pa^0.5)"),
          host::column_for(Signal::kPMi, p),   host::column_for(Signal::kPMo, p),  host::column_for(Signal::kPPp, p),
          host::column_for(Signal::kWm, speed_name(units.speed))};
}

std::vector<host::CsvColumn> paper_log_columns(const LogUnits& units) {
  const std::string p = pressure_name(units.pressure);
  return {host::column_for(Signal::kT, "s"),     host::column_for(Signal::kADcv, "m^2"),
          host::column_for(Signal::kAPrv, "m^2"), host::column_for(Signal::kPPump, p),
          host::column_for(Signal::kPMi, p),     host::column_for(Signal::kPPp, p),
          host::column_for(Signal::kWm, speed_name(units.speed))};
}

std::vector<double> thesis_log_row(const Measurement<ThesisInputs<double>>& m) {
  return {m.t, m.u.Psupl, m.u.Ps, m.u.Pbp, m.u.kp, m.y[0], m.y[1], m.y[2], m.y[3]};
}

std::vector<double> paper_log_row(const Measurement<PaperInputs<double>>& m) {
  return {m.t, m.u.A_dcv, m.u.A_prv, m.y[0], m.y[1], m.y[2], m.y[3]};
}

void write_log(std::ostream& os, const ThesisMeasurements& ms, const LogUnits& units) {
  write(os, ms, thesis_log_columns(units), [](const auto& m) { return thesis_log_row(m); });
}

void write_log(std::ostream& os, const PaperMeasurements& ms, const LogUnits& units) {
  write(os, ms, paper_log_columns(units), [](const auto& m) { return paper_log_row(m); });
}

}  // namespace hstmon::sim
