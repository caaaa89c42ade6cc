#pragma once
/// @file paper_tables.hpp
/// Reader of the paper-rig test tables (seed 001 §IV) for `hstmon identify --paper`.
///
/// Format: delimited text (',' or ';' or tab, detected from the header), '#' comments and
/// blank lines skipped, one header row naming four columns in any order:
///
///     kind,label,p[bar],q[l/min]
///     pump,,10,11.8          # pump B: p = pump pressure, q = delivered flow
///     dcv,A1,2.5,3.1         # DCV at opening A1: p = pressure drop Ps − Pmi, q = valve flow
///     prv,A2,40,5.0          # PRV at opening A2: p = pressure drop Ppp − Patm, q = valve flow
///
/// kind is pump, dcv or prv (case-insensitive); label names the opening (A1…A4, any text
/// without separator) and may be empty for pump rows. p takes the pressure units of log
/// files (Pa, kPa, bar, MPa, psi; none = Pa); q takes m3/s (default), l/min (L/min, lpm),
/// l/s, cm3/s (cc/s). Errors carry file:line.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_host/source_error.hpp"
#include "hstmon_ident/port_area.hpp"
#include "hstmon_ident/pump_curve_fit.hpp"

namespace hstmon::ident {

/// Contents of a paper table file, in SI.
struct PaperTables {
  std::vector<FlowPressureSample> pump;                   ///< pump rows (P [Pa], Q [m³/s])
  std::map<std::string, std::vector<PortSample>> dcv;     ///< DCV samples per opening label
  std::map<std::string, std::vector<PortSample>> prv;     ///< PRV samples per opening label
  std::optional<host::SourceError> error;                 ///< set on failure (then nothing else is valid)
  /// True when the file was read without error.
  bool ok() const noexcept { return !error.has_value(); }
};

/// SI factor of a flow unit ("m3/s", "l/min", …) [m³/s per unit]; nullopt if unknown.
std::optional<double> flow_unit_factor(const std::string& unit);

/// Parses table text; `path` names it in errors.
PaperTables parse_paper_tables(const std::string& text, const std::string& path);

/// Reads and parses the file at `path`.
PaperTables read_paper_tables(const std::string& path);

}  // namespace hstmon::ident
