#pragma once
/// @file params_file.hpp
/// JSON parameter files for the thesis model:
///
///     {"model": "thesis",
///      "description": "optional free text",
///      "params": {"Dm": 7.96e-6, "K": 1e14, ...},
///      "inputs": {"Psupl": "35 bar", "Ps": 0, "Pbp": 1e6, "kp": 4.41e-8},
///      "sensors": {"p_pp": ["0 bar", "400 bar"], "w_m": [null, "3000 rpm"]}}
///
/// Keys are the field names of hstmon::ThesisParams / ThesisInputs. Values are SI
/// numbers; pressure fields (Psupl, Ps, Pbp, dp_t_dcv, dp_t_prv) also take a string
/// with a unit ("35 bar"), kf and kp a string with their SI unit. Missing keys keep the
/// defaults (Table 2.2). "model" is required and must be "thesis".
///
/// "sensors" (optional) gives transmitter ranges [low end, high end] per measured
/// channel (p_mi, p_mo, p_pp, w_m): SI numbers (Pa, rad/s), strings with a unit of the
/// channel's quantity ("200 bar", "3000 rpm"), or null for no end; low < high. Channels
/// not named keep thesis_sensor_ranges() (sensor_ranges.hpp says what a range end means).

#include <optional>
#include <string>
#include <string_view>

#include "hstmon/thesis_params.hpp"
#include "hstmon_host/sensor_ranges.hpp"
#include "hstmon_host/source_error.hpp"

namespace hstmon::host {

/// Result of reading a parameter file: both parts set on success, neither on error.
struct ParamsFileResult {
  std::optional<ThesisParams<double>> params;  ///< physical parameters (SI)
  std::optional<ThesisInputs<double>> inputs;  ///< inputs (SI)
  /// Transmitter ranges (SI) if the file has a "sensors" section, else unset (the caller
  /// keeps its default); never set on error.
  std::optional<SensorRanges> sensors;
  std::string description;                     ///< the file's "description", if any
  std::optional<SourceError> error;            ///< set on failure, with line:column
  /// True when the file was read and validated.
  bool ok() const noexcept { return !error.has_value(); }
};

/// Reads and validates the parameter file at `path`. Errors: unreadable file, JSON
/// syntax, unknown or duplicated key, wrong type, unknown unit, and values the model
/// refuses (non-finite, ≤ 0 where a magnitude must be positive, kp < 0).
ParamsFileResult read_params_file(const std::string& path);

/// As read_params_file, from text in memory; `path_for_messages` names it in errors.
ParamsFileResult parse_params_json(std::string_view text, std::string path_for_messages);

/// The JSON text write_params_file writes (all keys, SI numbers, round-trip precision).
std::string format_params_json(const ThesisParams<double>& params,
                               const ThesisInputs<double>& inputs,
                               const std::string& description = {});

/// Writes a parameter file (via a temporary file renamed into place).
/// @return an error if the file cannot be written
std::optional<SourceError> write_params_file(const std::string& path,
                                             const ThesisParams<double>& params,
                                             const ThesisInputs<double>& inputs,
                                             const std::string& description = {});

}  // namespace hstmon::host
