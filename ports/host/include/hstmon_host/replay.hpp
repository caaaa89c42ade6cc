#pragma once
/// @file replay.hpp
/// Replays a log through the thesis observer: the host port's main loop. Each log row
/// is one measurement; the observer ticks at a fixed rate in between (inputs held from
/// the last row), so a 4 s DAS log and a 1 kHz log go through the same code.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include "hstmon/circuit/thesis_impl.hpp"
#include "hstmon/residual_stats.hpp"
#include "hstmon/thesis_params.hpp"
#include "hstmon/fault_matcher.hpp"
#include "hstmon/initial_state.hpp"
#include "hstmon_host/envelope_result.hpp"
#include "hstmon_host/replay_event.hpp"
#include "hstmon_host/log_reader.hpp"
#include "hstmon_host/sensor_ranges.hpp"

namespace hstmon::host {

/// How the observer state is initialised at the first row.
enum class InitMode {
  kAuto,    ///< from the first row's measurements (hstmon::choose_initial_state: measured states, else rest or steady)
  kRest,    ///< at rest: ωm = 0, Ppp = Pbp
  kSteady,  ///< the steady state for the first row's inputs
};

/// Options of replay().
struct ReplayOptions {
  double tick = 0.0;             ///< observer tick [s]; 0 = the log's median sample period, capped at 10 ms
  InitMode init = InitMode::kAuto;
  bool keep_trace = false;       ///< keep a TraceRow per log row (for residual CSV and plots)
  bool diagnose = true;          ///< run the fault matcher on the residuals (events, candidates)
  /// The implementation of the thesis equations the monitor runs. The hand-written
  /// specialisation by default: about 2.3× the engine's rows per second, which the
  /// one-hour log in a second needs (bench/RESULTS.md); the engine's (thesis.json compiled)
  /// gives the same events and residuals to 1e-9 (test_replay_thesis_model).
  ThesisImpl thesis = ThesisImpl::kSpecialised;
  /// Transmitter ranges for the sensor checks (a parameter file's "sensors" section);
  /// default: live zeros only (log_default_sensor_ranges()).
  SensorRanges sensors = log_default_sensor_ranges();
  /// Called with the fraction done (0…1) about every 1 % of rows; may be empty.
  std::function<void(double)> progress;
};

/// Residual statistics of one channel over the replay, in SI units (the firmware
/// replays count the same: hstmon/residual_stats.hpp).
using ChannelStats = ResidualStats<double>;

/// Measured, estimated and residual values at one log row (SI units).
struct TraceRow {
  double t = 0.0;                     ///< log time [s]
  std::array<double, 4> y{};          ///< measured Pmi, Pmo, Ppp [Pa], ωm [rad/s] (NaN if absent)
  std::array<double, 4> y_hat{};      ///< model estimate at the same instant
  std::array<double, 4> r{};          ///< residual y − ŷ (NaN if not computed)
  std::uint32_t health = 0;           ///< observer HealthFlag bits of this row's tick
};

/// Result of a replay.
struct ReplayResult {
  std::size_t rows = 0;                       ///< log rows replayed
  std::uint64_t ticks = 0;                    ///< observer ticks run
  double tick = 0.0;                          ///< tick used [s]
  double t_first = 0.0;                       ///< first row's time [s]
  double t_last = 0.0;                        ///< last row's time [s]
  std::array<bool, 4> measured{};             ///< channel present in the log
  std::array<ChannelStats, 4> channels{};     ///< per channel (Pmi, Pmo, Ppp, ωm)
  std::uint32_t health = 0;                   ///< HealthFlag bits OR-ed over all ticks
  std::size_t unhealthy_rows = 0;             ///< rows whose tick raised any flag
  std::uint32_t max_substeps = 0;             ///< largest RK4 substep count of a tick
  InitialState start = InitialState::kRest;   ///< how the observer's initial state was chosen
  double startup_hold = 0.0;                  ///< start-up hold-off: no detection before t_first + this [s]
  std::vector<TraceRow> trace;                ///< per row, if ReplayOptions::keep_trace
  std::vector<ReplayEvent> events;            ///< matcher events in time order (if diagnose)
  /// Matcher status after the last row, or "out_of_envelope" (the model does not describe
  /// this machine at its first steady stretch) or "unverified" (detected before the machine
  /// was seen to match the model, and never judged): then nothing is diagnosed
  std::string final_status = "nominal";
  EnvelopeResult envelope;                    ///< does the model describe this machine at its first steady stretch?
  std::array<double, 4> thresholds{};         ///< residual bound per channel at the first row (model bound + 2σ) [SI]
  std::vector<std::string> notes;             ///< what the replay assumed (defaults used, tick)
};

/// Replays `log` through the thesis monitor (observer, sensor checks, residual
/// evaluator and the fault matcher with the generated signature table).
/// Inputs missing from the log (p_sup, p_s, p_bp, kp) come from `defaults`; measured
/// channels missing from the log are simply not compared. The log must be valid
/// (read without error, or the valid prefix of a lenient read).
ReplayResult replay(const LogData& log, const ThesisParams<double>& params,
                    const ThesisInputs<double>& defaults, const ReplayOptions& options);

/// replay() chunk by chunk, for a log read with LogStream (log_stream.hpp): memory that
/// does not grow with the log (unless ReplayOptions::keep_trace). The same monitor and
/// result as replay() of the whole log, but for one thing: the default tick is the
/// median sample period of the first chunk's rows rather than of the whole log (the same
/// for a log sampled at one rate).
class ChunkedReplay {
 public:
  ChunkedReplay(const ThesisParams<double>& params, const ThesisInputs<double>& defaults,
                const ReplayOptions& options);
  ~ChunkedReplay();
  ChunkedReplay(const ChunkedReplay&) = delete;
  ChunkedReplay& operator=(const ChunkedReplay&) = delete;

  /// Replays `chunk`, the log's next rows (the same columns in every chunk; the first
  /// non-empty chunk fixes the tick and the initial state). `rows_total`: the log's rows,
  /// for ReplayOptions::progress; 0 = no progress calls (the caller reports progress).
  void add(const LogData& chunk, std::size_t rows_total = 0);

  /// The result after the last chunk; call once.
  ReplayResult finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// A matcher event (any model's monitor, double) as a replay event.
ReplayEvent to_replay_event(const MatchEvent<double>& e);

/// Names of the four measured channels in output order: p_mi, p_mo, p_pp, w_m.
extern const std::array<Signal, 4> kMeasuredSignals;

/// Text names of the HealthFlag bits set in `flags` ("substeps_clipped", ...).
std::vector<std::string> health_names(std::uint32_t flags);

}  // namespace hstmon::host
