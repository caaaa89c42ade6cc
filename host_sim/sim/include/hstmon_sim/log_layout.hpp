#pragma once
/// @file log_layout.hpp
/// Column layout and units of the simulator's logs. Inputs come first so that a replay
/// knows them, then the measured channels.
///   thesis: t[s], p_sup[P], p_s[P], p_bp[P], kp[m^3/(s*Pa^0.5)], p_mi[P], p_mo[P], p_pp[P], w_m[W]
///   paper:  t[s], a_dcv[m^2], a_prv[m^2], p_pump[P], p_mi[P], p_pp[P], w_m[W]
/// with P = bar or Pa and W = rad/s or rpm. kp stays SI (its unit holds Pa) in every case.
/// p_s is the thesis's Ps (DCV return pressure); p_pump is the paper's Ps (pump B).

#include <ostream>
#include <vector>

#include "hstmon_host/log_writer.hpp"
#include "hstmon_sim/measure.hpp"

namespace hstmon::sim {

/// Pressure unit of a log.
enum class PressureUnit { kBar, kPa };
/// Speed unit of a log.
enum class SpeedUnit { kRadPerSec, kRpm };

/// Units of a log.
struct LogUnits {
  PressureUnit pressure = PressureUnit::kBar;  ///< unit of every pressure column
  SpeedUnit speed = SpeedUnit::kRadPerSec;     ///< unit of the speed column
};

/// Columns of a thesis log (the host port's writer converts SI values to their units).
std::vector<host::CsvColumn> thesis_log_columns(const LogUnits& units);
/// Columns of a paper log.
std::vector<host::CsvColumn> paper_log_columns(const LogUnits& units);

/// Row of a thesis log for measurement m, in SI (the column order above).
std::vector<double> thesis_log_row(const Measurement<ThesisInputs<double>>& m);
/// Row of a paper log for measurement m, in SI.
std::vector<double> paper_log_row(const Measurement<PaperInputs<double>>& m);

/// Writes a complete thesis log (header and rows), 10 significant digits.
void write_log(std::ostream& os, const ThesisMeasurements& ms, const LogUnits& units);
/// Writes a complete paper log (header and rows).
void write_log(std::ostream& os, const PaperMeasurements& ms, const LogUnits& units);

}  // namespace hstmon::sim
