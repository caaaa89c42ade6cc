#pragma once
/// @file fault_fit_diagnosis.hpp
/// The diagnosis of `hstmon replay --circuit`: the fault matcher (fault_matcher.hpp)
/// detects and gives the first guess from the transient; once a steady window after the
/// detection is in, the fault estimator (fault_estimator.hpp) decides, from the model
/// fitted at every operating point the machine visits since:
///  - `isolated` / `ambiguous` list the hypotheses consistent with every window, best
///    first, each with its fitted size;
///  - a matcher `cleared` is withheld while the windows say the fault is still there (a
///    persisting fault is not cleared by an input change), and the episode ends only on a
///    window where no fault fits as well as any;
///  - a sensor flag (a frozen, absent or out-of-range reading) keeps the matcher's
///    verdict: the physics cannot produce it.
/// It detects too, where the matcher cannot: a step in the readings while the inputs hold
/// still (held_step_detector.hpp) is a change in the machine, however far inside the model
/// bound it stays. Such a step, and a matcher detection at inputs held long enough, leave
/// the estimator a baseline: the readings at the same inputs before the fault, so the
/// first window compares the change with each hypothesis's change, free of the model's
/// own error there. And it keeps a record of the machine's healthy steady windows
/// (healthy_record.hpp): a window at a point not seen before whose readings are not what
/// that record predicts is a change too, and at every point an episode visits the
/// prediction stands in for a baseline where no reading before the fault exists.

#include <memory>
#include <string>
#include <vector>

#include "hstmon/fault_matcher.hpp"
#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_circuit/circuit_load.hpp"
#include "hstmon_host/replay.hpp"

namespace hstmon::circuit_tools {

class FaultFitDiagnosis {
 public:
  using Model = host::HostCircuitModel;

  /// @param model     the monitor's model (nominal parameters; its description outlives this)
  /// @param measured  bit ch: channel ch is in the log
  /// @param record    keep the healthy record (healthy_record.hpp; CircuitReplayOptions::healthy_record)
  FaultFitDiagnosis(const LoadedCircuit& c, const Model& model, unsigned measured, bool record = true);
  ~FaultFitDiagnosis();
  FaultFitDiagnosis(const FaultFitDiagnosis&) = delete;
  FaultFitDiagnosis& operator=(const FaultFitDiagnosis&) = delete;

  /// One matcher event at time t under inputs u: recorded in `out`, or withheld.
  /// @param sensor_flag  the matcher has a sensor flag in this episode
  void on_matcher_event(const host::ReplayEvent& e, double t, const Model::Inputs& u, bool sensor_flag,
                        std::vector<host::ReplayEvent>& out);
  /// One log row, after the matcher's events of that row; pointers per channel, SI.
  struct Row {
    double t = 0.0;                 ///< [s]
    const double* y = nullptr;      ///< readings
    unsigned valid = 0;             ///< bit ch: y[ch] compared
    const double* r = nullptr;      ///< the observer's residual (measured − model)
    const double* y_hat = nullptr;  ///< the observer's model outputs
    unsigned r_valid = 0;           ///< bit ch: r[ch] is one
    const double* bound = nullptr;  ///< the monitor's model bound at the row's inputs
    bool matcher_quiet = false;     ///< the matcher's status is nominal
    /// The monitor's nominal steady outputs at inputs *bound_u, where `bound` was computed
    /// too (nullptr: none on offer); the fit's windows at exactly those inputs take them and
    /// `bound` instead of solving the same steady states again (FaultEstimator::offer_nominal)
    const double* steady_y = nullptr;
    const Model::Inputs* bound_u = nullptr;
  };
  void on_row(const Row& row, const Model::Inputs& u, std::vector<host::ReplayEvent>& out);
  /// The end of the log: the open window counts.
  void finish(double t, std::vector<host::ReplayEvent>& out);

  /// "nominal", "detected", "isolated", "ambiguous" or "unexplained".
  const std::string& status() const { return status_; }
  /// Notes for the replay's summary (hypotheses, windows).
  std::vector<std::string> notes() const;

 private:
  struct Impl;
  void decide(double t, std::vector<host::ReplayEvent>& out);
  void watch(const Row& row, const Model::Inputs& u, std::vector<host::ReplayEvent>& out);
  void start_episode(double t, const Model::Inputs& u, double settled_for = 0.0);
  void expect(double t, const Model::Inputs& u);
  void end_episode(double t);
  bool gone() const;
  void emit(host::ReplayEvent e, std::vector<host::ReplayEvent>& out);

  std::unique_ptr<Impl> impl_;
  bool active_ = false;       ///< an episode is running (ours; it may outlive the matcher's)
  bool sensor_lock_ = false;  ///< the matcher flagged a sensor: its verdict stands
  std::string status_ = "nominal";
  std::string last_key_;      ///< kind and candidate names of the last verdict event
};

}  // namespace hstmon::circuit_tools
