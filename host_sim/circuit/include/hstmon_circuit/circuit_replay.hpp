#pragma once
/// @file circuit_replay.hpp
/// Replays a circuit log through the circuit's monitor (hstmon replay --circuit):
/// circuit::CircuitMonitor — observer, sensor checks, residual evaluator with the model
/// bound from the circuit's parameter uncertainty, and the fault matcher on the table the
/// caller's builder makes (CircuitReplayOptions::fault_table: `hstmon replay --circuit` passes
/// fdi::circuit_signature_table, the committed headers' builder). The observer ticks at a fixed rate, each log row one measurement,
/// inputs held from the last row, as the thesis replay (ports/host replay.hpp); it starts
/// by hstmon::choose_initial_state (reset_measured) unless told otherwise, and then, when
/// the first row lies within 3σ of the steady state's outputs on every channel (each with
/// a sensor noise σ), at that steady state instead: a parallel model keeps the readings'
/// noise as its initial error, and a lightly damped circuit rings with it. Stiff nodes are
/// taken quasi-steady for the tick (circuit::auto_stiff_mask). A reading at or beyond an
/// end of its sensor's range goes to the monitor's sensor checks (saturation, loop break)
/// but not into the residual statistics (a clipped transmitter says only "there or
/// beyond").

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hstmon/initial_state.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_circuit/circuit_log.hpp"
#include "hstmon_circuit/bound_lead.hpp"
#include "hstmon_host/envelope_result.hpp"
#include "hstmon_host/replay.hpp"

namespace hstmon::circuit_tools {

/// Options of replay_circuit().
struct CircuitReplayOptions {
  double tick = 0.0;                         ///< observer tick [s]; 0 = the log's median period, at most 10 ms
  host::InitMode init = host::InitMode::kAuto;
  bool diagnose = true;                      ///< run the fault matcher (false: residuals only)
  /// After a detection, fit every hypothesis to each steady window (FaultFitDiagnosis), whose
  /// verdict supersedes the matcher's; false: the matcher's verdict alone, as the firmware runs it.
  bool fit = true;
  bool keep_trace = false;                   ///< keep measured, model and residual per row (CircuitReplayResult::trace)
  /// Builds the matcher's table. nullptr: circuit_fault_table (steady-state signs only, slopes
  /// `?`, orders 0); the host programs pass fdi::circuit_signature_table (slopes and orders
  /// from the circuit's causal graph), which circuit_tools cannot call itself (fdi depends on it).
  CircuitFaultTable (*fault_table)(const LoadedCircuit&) = nullptr;
  /// A table already built for c by the caller (a campaign replaying many logs of one
  /// circuit builds it once); when set, fault_table is not called. Must outlive the call.
  const CircuitFaultTable* table = nullptr;
  /// Run the interpreter even where the circuit is compiled into the program
  /// (compiled_circuits.hpp); for comparing the two, which give the same numbers.
  bool interpret = false;
  /// The fit after a detection takes the monitor's nominal steady outputs and model bound
  /// at the inputs it computed them for, instead of solving the same steady states again
  /// (false: it solves them; the same numbers, for comparing the two).
  bool share_bound = true;
  /// The fit also keeps a record of the machine's healthy steady windows (healthy_record.hpp):
  /// where it sits inside its parameters' uncertainty, and so what it should read at a point
  /// not seen yet. A change from that, inside the model bound, is detected, and the windows
  /// after it are judged against it. false: the bound and the steps at held inputs alone (for
  /// comparing the two).
  bool healthy_record = true;
};

/// One log row of a circuit replay, per channel in sensor order, SI (NaN where absent).
struct CircuitTraceRow {
  double t = 0.0;                 ///< [s]
  std::vector<double> y, y_hat, r;
  /// Per channel, the matcher's bound on |r| at this row: model bound (parameter
  /// uncertainty at the operating point, carried over input changes) + transient allowance
  /// + 2σ; beyond it the CUSUM accumulates [SI]
  std::vector<double> bound;
  /// Per channel, what leads the model bound at this row's operating point (bound_lead.hpp)
  std::vector<ChannelBoundLead> lead;
  std::uint32_t health = 0;       ///< HealthFlag bits of the row's tick
};

/// Result of a circuit replay; channels in the circuit's sensor order, SI units.
struct CircuitReplayResult {
  std::size_t rows = 0;
  std::uint64_t ticks = 0;
  double tick = 0.0;                          ///< [s]
  double t_first = 0.0, t_last = 0.0;         ///< [s]
  int states = 0, stiff_nodes = 0;            ///< the reduced model's states and quasi-steady nodes
  bool compiled = false;                      ///< the monitor ran a compiled circuit's code (compiled_circuits.hpp)
  std::vector<bool> measured;                 ///< per channel: in the log
  std::vector<host::ChannelStats> channels;   ///< per channel
  std::vector<std::size_t> clipped;           ///< per channel: rows not compared (reading at a range end)
  std::uint32_t health = 0;                   ///< HealthFlag bits OR-ed over all ticks
  std::size_t unhealthy_rows = 0;
  std::uint32_t max_substeps = 0;             ///< most steps a tick took (RK4 substeps, or Rosenbrock steps)
  std::uint64_t implicit_ticks = 0;           ///< ticks integrated by Rosenbrock steps (stiff ticks)
  InitialState start = InitialState::kRest;
  double startup_hold = 0.0;                  ///< start-up hold-off: no detection before t_first + this [s]
  std::vector<host::ReplayEvent> events;      ///< matcher events in time order (if diagnose)
  /// Matcher status after the last row, or the fit's (fault_fit_diagnosis.hpp), or
  /// "out_of_envelope" (hstmon/envelope_check.hpp: the model does not describe this machine)
  std::string final_status = "nominal";
  host::EnvelopeResult envelope;                  ///< does the model describe this machine at its first steady stretch?
  /// Per channel, the model bound at the last row's inputs and the parameter that leads it
  /// (empty when there is no steady state there)
  std::vector<ChannelBoundLead> bound_lead;
  std::size_t table_rows = 0;                 ///< hypotheses in the circuit's fault table (0: not run)
  std::vector<std::string> undetectable;      ///< parameter faults without a row (no visible steady change)
  std::vector<CircuitTraceRow> trace;         ///< per row, if CircuitReplayOptions::keep_trace
  std::vector<std::string> notes;
};

/// Replays `log` (read for c, without error) through the observer on c's engine.
CircuitReplayResult replay_circuit(const LoadedCircuit& c, const CircuitLog& log, const CircuitReplayOptions& o);

}  // namespace hstmon::circuit_tools
