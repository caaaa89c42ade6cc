#pragma once
/// @file steady_windows.hpp
/// Steady-state windows in a measurement log: runs of consecutive samples over which every
/// measured channel is flat (no significant slope) and scatters only as much as its noise.
///
/// Algorithm (O(rows) apart from re-tests of trimmed windows):
///  1. Noise σ per measured channel: the option's value if given, else from successive
///     differences Δy: σ² = mean(Δy²)/2 over the |Δy| below 5× the larger of the MAD
///     scale median(|Δy|)/0.6745 and the smallest non-zero |Δy| (the ADC step — a
///     quantised channel has mostly zero differences); level steps are cut off. Floored
///     at noise_floor.
///  2. Grow a window from sample i while each new sample lies within outlier_k·σ·√(1+1/n)
///     of the window's running mean on every channel (a level step ends the window).
///  3. Accept it when it has ≥ min_samples samples spanning ≥ min_duration, every channel's
///     scatter about its least-squares line is ≤ scatter_k·σ, and every slope is within
///     slope_k standard errors of zero (|b| ≤ slope_k·σ/√Σ(t−t̄)² + slope_tol). A window
///     failing the slope test has its first quarter dropped (transients sit at the start)
///     and is tested again. Rejected samples are reported as not steady.
/// Works for 4 s DAS logs (a step shows as a level change between two samples) and for
/// 1 kHz logs (the decaying transient after a step fails the slope test). With
/// assume_steady a window may be one sample (the thesis recorded only after the rig had
/// settled); such windows carry assumed = true.
///
/// Inputs (p_sup, p_s, p_bp, kp, a_dcv, a_prv) do not split windows: a logger may record a
/// new setting one sample before the machine responds. Each window reports the median of
/// every logged input over its samples.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/signals.hpp"

namespace hstmon::ident {

/// Settings of find_steady_windows. Noise and tolerances are in SI (Pa, rad/s).
struct SteadyWindowOptions {
  double min_duration = 1.0;      ///< shortest accepted window [s] (ignored with assume_steady)
  std::size_t min_samples = 3;    ///< fewest samples in an accepted window (1 with assume_steady)
  bool assume_steady = false;     ///< accept single-sample windows (DAS logs recorded at steady state)
  double outlier_k = 5.0;         ///< growth test: new sample within outlier_k·σ of the running mean [-]
  double scatter_k = 2.0;         ///< acceptance: scatter about the line ≤ scatter_k·σ [-]
  double slope_k = 4.0;           ///< acceptance: |slope| ≤ slope_k standard errors [-]
  /// Per-signal noise σ (index(Signal)) [SI]; a value ≤ 0 or NaN means "estimate from the log".
  std::array<double, host::kSignalCount> noise{};
  /// Per-signal slope allowance added to the statistical bound [SI/s] (default 0).
  std::array<double, host::kSignalCount> slope_tol{};
};

/// Statistics of one measured channel over a window.
struct ChannelWindowStats {
  double mean = 0.0;     ///< mean [SI]
  double scatter = 0.0;  ///< standard deviation about the least-squares line [SI] (0 if n < 3)
  double slope = 0.0;    ///< least-squares slope [SI/s] (0 if n < 2)
  double ss = 0.0;       ///< Σ (y − mean)² [SI²]
};

/// One steady window.
struct SteadyWindow {
  std::size_t first = 0;   ///< index of the first sample (0-based row in LogData)
  std::size_t last = 0;    ///< index of the last sample (inclusive)
  double t0 = 0.0;         ///< time of the first sample [s]
  double t1 = 0.0;         ///< time of the last sample [s]
  bool assumed = false;    ///< fewer than 3 samples: steadiness assumed, not tested (assume_steady)
  /// Per-signal statistics (index(Signal)); valid where `measured` is true.
  std::array<ChannelWindowStats, host::kSignalCount> stats{};
  /// Median of each logged input over the window (index(Signal)) [SI]; NaN where absent.
  std::array<double, host::kSignalCount> inputs{};
  bool inputs_varied = false;  ///< a logged input took more than one value inside the window
  /// Number of samples.
  std::size_t samples() const noexcept { return last - first + 1; }
};

/// Windows of one log.
struct SteadyWindowResult {
  std::vector<SteadyWindow> windows;                          ///< in time order
  std::array<bool, host::kSignalCount> measured{};            ///< channels tested (measured and present)
  std::array<double, host::kSignalCount> noise{};             ///< σ used per tested channel [SI]
  std::array<bool, host::kSignalCount> noise_estimated{};     ///< σ came from the log, not the options
  std::size_t rejected_samples = 0;                           ///< samples in no window
  std::optional<std::string> error;                           ///< "file: …" when nothing could be done
};

/// Floor of the estimated noise [SI] for signal s (1 Pa for pressures, 1e-4 rad/s for speed):
/// a noise-free log still gets a finite tolerance.
double noise_floor(host::Signal s) noexcept;

/// Finds the steady windows of a successfully read log. Errors: the log has an error, no
/// rows, no measured channel, or a non-finite value.
SteadyWindowResult find_steady_windows(const host::LogData& log, const SteadyWindowOptions& options = {});

}  // namespace hstmon::ident
