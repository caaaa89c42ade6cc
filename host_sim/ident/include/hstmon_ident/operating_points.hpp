#pragma once
/// @file operating_points.hpp
/// Steady operating points of the thesis rig: one per steady window, with the window means
/// of (Pmi, Pmo, Ppp, ωm), the known inputs (Psupl, Ps, Pbp) and the PRV setting the point
/// belongs to. Each setting gets its own kp in the fit.
///
/// Settings: within one log, windows whose logged kp (median over the window) is equal
/// share a setting — the kp column records the operator's PRV setting, not its value,
/// which is estimated. Without a kp column, or with setting_per_window, every window is a
/// setting of its own. Settings of different logs are always distinct.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "hstmon/thesis_params.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_ident/steady_windows.hpp"

namespace hstmon::ident {

/// One steady operating point of the thesis rig.
struct OperatingPoint {
  std::string source;            ///< "file t=a…b s" for messages
  std::size_t setting = 0;       ///< index of the PRV setting (0-based) into the settings list
  ThesisInputs<double> u{};      ///< known Psupl, Ps, Pbp [Pa]; u.kp is not used by the fit
  /// Window means (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) in ThesisChannel order; NaN = not measured.
  std::array<double, 4> y{};
  /// Within-window Σ(y − ȳ)² per channel [Pa², (rad/s)²]; 0 for a single sample.
  std::array<double, 4> ss{};
  std::size_t n = 1;             ///< samples averaged
  bool assumed = false;          ///< steadiness assumed, not tested (window of < 3 samples)
};

/// Options of operating_points().
struct OperatingPointOptions {
  bool setting_per_window = false;  ///< every window its own PRV setting, even with a kp column
  /// Inputs used where the log has no p_sup / p_s / p_bp column [Pa] (Table 2.2 by default).
  ThesisInputs<double> defaults{};
};

/// Operating points from the windows of one log, appended to `points`; the log's settings
/// are numbered from settings.size() on and their labels ("file kp=4.41e-08" or
/// "file t=… s") appended to `settings`.
void append_operating_points(const host::LogData& log, const SteadyWindowResult& windows,
                             const OperatingPointOptions& options, std::vector<OperatingPoint>& points,
                             std::vector<std::string>& settings);

}  // namespace hstmon::ident
