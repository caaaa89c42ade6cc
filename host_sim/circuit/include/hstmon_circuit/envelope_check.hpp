#pragma once
/// @file envelope_check.hpp
/// Does the model describe this machine at all? A fault is a change from a machine the
/// model describes; a machine that sits far outside what the model reaches from the first
/// steady stretch of its log is another machine (or this one badly parameterised), and
/// naming a fault on it would be a guess. The check: the first stretch of held inputs that
/// lasts a settle (3 slowest time constants at its inputs, as the fault estimator's) plus
/// a steady `window` seconds (its halves' mean residuals within 5 % of the tolerance:
/// a machine still running up is tried again later); over that window, per channel, the
/// mean residual against twice the matcher's own tolerance 2·(model bound + 2σ). Beyond it
/// on any channel: out of envelope. A window not begun by the first detection is given up:
/// it would judge the fault, not the machine.
/// A log without such a stretch is not checked, and says so.

#include <cstddef>
#include <string>
#include <vector>

#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::circuit_tools {

/// The verdict of the check.
struct EnvelopeResult {
  bool checked = false;  ///< a steady stretch was found and judged
  bool out = false;      ///< the machine lies outside the model's envelope there
  double t0 = 0.0, t1 = 0.0;  ///< the window judged [s]
  std::string text;      ///< one sentence: where and by how much, or why it was not checked
};

class EnvelopeCheck {
 public:
  using Model = host::HostCircuitModel;

  /// @param model  the monitor's nominal model (copied; its description must outlive this)
  /// @param window seconds of steady data judged [s]
  EnvelopeCheck(const LoadedCircuit& c, const Model& model, const std::vector<double>& sigma, double window = 0.5);

  /// One row: inputs u; r the residual per channel (measured − model) [SI], bit ch of valid
  /// set where r[ch] is one; bound the model bound per channel at u [SI].
  void add(double t, const Model::Inputs& u, const double* r, unsigned valid, const double* bound);

  /// The monitor detected a fault at t [s]: a window that had not begun by then (the
  /// machine still settling) would judge the fault, not the machine, so the check is given up.
  void detected(double t);

  /// The verdict so far (final once `checked`); call finish() at the end of the log.
  const EnvelopeResult& result() const { return res_; }
  void finish();

 private:
  void begin_hold(double t, const Model::Inputs& u);
  bool steady() const;  ///< the window's halves agree within 5 % of the tolerance and their noise
  void abandon();

  const LoadedCircuit& c_;
  Model model_;
  std::vector<double> sigma_;
  double window_;
  EnvelopeResult res_;
  Model::Inputs u_hold_{};
  bool holding_ = false;
  double t_from_ = 0.0;  ///< the window starts here (after the settle) [s]
  double t_last_ = 0.0;
  double t_detected_ = -1.0;  ///< the first detection [s]; < 0 before it
  bool abandoned_ = false;
  std::vector<double> sum_, bound_, half_sum_;  ///< per channel: the window's and its first half's sums
  std::vector<std::size_t> n_, half_n_;
};

}  // namespace hstmon::circuit_tools
