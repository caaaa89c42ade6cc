#pragma once
/// @file healthy_record.hpp
/// The machine as its healthy steady windows show it, and what that predicts elsewhere.
///
/// Every built machine sits somewhere inside its parameters' uncertainty, and the model
/// bound allows for all of it at every operating point. A fault smaller than the bound
/// then passes unseen wherever no earlier reading at the same inputs shows its step: one
/// that begins during an input ramp and shows at the point the ramp leads to (an 8 %
/// smaller motor on the paper's rig moves w_m by half its bound).
///
/// But each healthy window says where this machine sits. To first order its mean reading
/// less the model's steady output is the sum over the uncertain parameters of their
/// relative errors times their sensitivities there. The record keeps a Gaussian estimate
/// of those errors:
///  - prior: each uniform on ±ε (the bound's uncertainty), so σ = ε/√3;
///  - each window adds its sensitivities S (central differences at ±ε, once per window)
///    with weight 1/v per channel, v = σ²/min(n, n_cap) + (k_struct·bound)² + bend²: the
///    noise of the mean; a share of the bound for what a parameter picture misses (the
///    model's structure, coloured noise), independent between windows; and the bend, what
///    the straight line misses within ±ε there (a valve that a parameter, or all of them
///    at a corner, would open or shut: near it the line says little, and such a window
///    teaches and is judged little).
/// At a window's inputs it then predicts the healthy reading and its covariance,
/// S·Σ·Sᵀ + V. A window whose mean lies beyond k_chi2 in χ² (over its channels, with that
/// full covariance) is not the machine the record showed: something changed since.
///
/// It judges readings against the model's steady state, not the observer's residual: the
/// observer is the model's trajectory, and where its integration settles off the steady
/// state (a fixed-step tick across a valve's opening) that is the observer's error, not
/// the machine's.
///
/// Where the record has seen nothing like the point, the prediction's spread is the
/// prior's, and only a change beyond what the parameters allow shows. The first window it
/// judges must itself be a machine the parameters explain: if not (the model describes the
/// machine only roughly), nothing learnt would hold, and the record stays off.
///
/// Windows: a stretch of held inputs from a settle time after they last changed. One is
/// judged once it has test_min of samples and again every test_every, and it enters the
/// record when the inputs move on, if it had window_min of samples and was healthy.
/// Each new point costs 2 steady-state solves per uncertain parameter and 2 per channel.

#include <Eigen/Dense>
#include <vector>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon_host/circuit_file.hpp"

namespace hstmon::circuit_tools {

/// Settings; times in s, shares dimensionless.
struct HealthyRecordConfig {
  bool on = true;           ///< false: nothing recorded, predicted or detected
  double k_struct = 0.1;    ///< share of the model bound per window that a parameter picture misses [-]
  double n_cap = 100.0;     ///< samples whose noise averages out at most [-]
  double test_min = 0.3;    ///< samples a window needs before it is judged [s]
  double test_every = 0.1;  ///< re-judge an open window this often [s]
  double window_min = 0.5;  ///< samples a window needs to enter the record [s]
  double k_chi2 = 50.0;     ///< χ² over a window's channels beyond which it is a change [-]
};

class HealthyRecord {
 public:
  using Model = host::HostCircuitModel;
  using Inputs = Model::Inputs;
  using Uncertainty = circuit::CircuitUncertainty<double, host::CircuitCap>;
  using Config = HealthyRecordConfig;

  /// @param model     the monitor's model (nominal parameters; copied)
  /// @param eps       relative uncertainty per parameter (0: exact, not estimated)
  /// @param sigma     noise σ per channel [SI], Model::kOutputs of them
  /// @param measured  bit ch: channel ch is in the log
  HealthyRecord(const Model& model, const Uncertainty& eps, const double* sigma, unsigned measured,
                const Config& cfg = {});

  /// The inputs changed (or the hold restarted): the open window closes (into the record if
  /// it qualifies) and a new one opens at u from t_settled [s].
  void begin(const Inputs& u, double t_settled);
  /// One row at the held inputs: readings y [SI], valid bits.
  /// @return true when the open window, judged now, is not the machine the record shows
  bool add(double t, const double* y, unsigned valid);
  /// The open window is dropped, not recorded (an episode began: the machine is not healthy).
  void drop() { open_ = false; }

  /// Windows in the record [-].
  int windows() const { return windows_; }
  /// The open window's χ² and channels at its last judgement [-].
  double chi2() const { return chi2_; }
  int dof() const { return dof_; }
  /// How long the open window has been settled at t [s] (0 when none is open).
  double settled_for(double t) const { return open_ && t > t_settled_ ? t - t_settled_ : 0.0; }
  /// The reading less the model's steady output that the record predicts at the open
  /// window's inputs, per channel [SI], and the variance of that prediction [SI²].
  /// @return bit i: channel i has one (0 before the window's point is solved, or with an
  ///         empty record)
  unsigned predicted(double* mean, double* var) const;
  /// The same at inputs u, solved there: what the machine would read at u now had nothing
  /// changed since the record.
  unsigned expected_at(const Inputs& u, double* mean, double* var);

 private:
  /// One operating point of the nominal model.
  struct Point {
    bool ok = false;
    Eigen::VectorXd y0;     ///< steady outputs [SI]
    Eigen::MatrixXd s;      ///< channels × uncertain parameters [SI per unit relative error]
    Eigen::VectorXd bound;  ///< Σ_j of the larger output change at ±ε_j, per channel [SI]
    Eigen::VectorXd bend;   ///< what the line misses within ±ε, per channel [SI]
  };
  bool solve_point(const Inputs& u, Point& p);
  unsigned predict(const Point& p, double* mean, double* var) const;
  void close();
  void update_estimate();
  bool judge();
  /// The noise variance of the open window's mean on channel i [SI²].
  double noise_var(int i) const;
  /// What the parameter line does not explain on channel i at p [SI²].
  double unmodelled_var(const Point& p, int i) const;
  /// The open window's mean reading on channel i less the model's steady output there [SI].
  double residual(int i) const;

  Model model_;
  typename Model::Params nominal_{};
  std::vector<int> params_;    ///< the uncertain parameters' indices
  std::vector<double> eps_;    ///< their ε [-]
  std::vector<double> sigma_;  ///< per channel [SI]
  unsigned measured_ = 0;
  Config cfg_;
  int n_ch_ = 0;

  // The record: information matrix and score of the parameters' relative errors.
  Eigen::MatrixXd info_;
  Eigen::VectorXd score_;
  Eigen::LDLT<Eigen::MatrixXd> posterior_;  ///< info_ factored: its inverse is the errors' covariance
  Eigen::VectorXd delta_;                   ///< the errors' estimate, info_⁻¹·score_ [-]
  int windows_ = 0;
  bool off_ = false;  ///< the first window lay outside what the parameters explain

  // The open window.
  bool open_ = false;
  Inputs u_{};
  double t_settled_ = 0.0;
  double t_first_ = 0.0, t_last_ = 0.0, t_judged_ = 0.0;
  bool sampled_ = false;
  std::vector<double> sum_;
  std::vector<int> n_;
  Point point_;
  bool solved_ = false;  ///< point_ was attempted for this window
  double chi2_ = 0.0;
  int dof_ = 0;
};

}  // namespace hstmon::circuit_tools
