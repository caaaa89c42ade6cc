#pragma once
/// @file envelope_check.hpp
/// Does the model describe this machine at all? A fault is a change from a machine the
/// model describes; a machine that sits far outside what the model reaches from the first
/// steady stretch of its log is another machine (or this one badly parameterised), and
/// naming a fault on it would be a guess. The check: the first stretch of held inputs that
/// lasts a settle (3 slowest time constants at its inputs, as the fault estimator's) plus
/// `window` seconds; over that window, per channel, the mean residual against twice the
/// matcher's own tolerance 2·(model bound + 2σ). Beyond it on any channel: out of envelope.
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

  /// The verdict so far (final once `checked`); call finish() at the end of the log.
  const EnvelopeResult& result() const { return res_; }
  void finish();

 private:
  void begin_hold(double t, const Model::Inputs& u);

  const LoadedCircuit& c_;
  Model model_;
  std::vector<double> sigma_;
  double window_;
  EnvelopeResult res_;
  Model::Inputs u_hold_{};
  bool holding_ = false;
  double t_from_ = 0.0;  ///< the window starts here (after the settle) [s]
  double t_last_ = 0.0;
  std::vector<double> sum_, bound_;
  std::vector<std::size_t> n_;
};

}  // namespace hstmon::circuit_tools
