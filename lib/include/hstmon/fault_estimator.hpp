#pragma once
/// @file fault_estimator.hpp
/// Fault identification over the steady operating points after a detection: for each
/// single-fault hypothesis, the fault size that best explains every steady window seen
/// since, and how well it does (a χ² over windows and channels). A fault table fixes
/// signs at one operating point; this fits the model itself at each point the machine
/// visits, so
///  - a residual sign that flips with the operating point (reverse drive) is what the
///    model predicts, not a contradiction;
///  - a fault that shows only at some points (a relief setting, seen only at high
///    pressure) is judged where it shows;
///  - faults whose signatures coincide at one point are told apart by how their effect
///    scales across points (a leak grows with pressure, a delivery loss with speed): one
///    size must fit every window, or the hypothesis loses;
///  - the winner comes with its size (a factor on the parameter, with an interval).
///
/// Hypotheses: a relative fault on a model parameter or a logged input (the machine's true
/// value is factor × the model's), and a constant offset on a sensor channel. A window is
/// a stretch of constant inputs, starting a settle time after the inputs (or the
/// episode) last changed; it holds the mean reading per channel. When it opens, the
/// model's steady outputs are solved at its inputs for every hypothesis at every factor
/// of a fixed grid (kGrid factors, log-spaced, 1 among them); its χ² against the mean
/// reading is then cheap to update as samples arrive. Between two grid factors the model's
/// outputs are taken as a straight line in ln(factor), so the χ² summed over windows is an
/// exact quadratic on each grid interval (its node values and Σ w·(y_g+1 − y_g)², kept per
/// interval): the best size is found where a hypothesis's outputs, not its steeply curved
/// χ², are interpolated — a leak 6× the model's sits between grid factors 4.5 and 9 and is
/// fitted there, not missed. Windows add up in χ²; a window's
/// weight per channel is 1/s², s² = σ²/min(n, n_cap) + (k_model·bound)²: the model
/// bound (parameter uncertainty) at that point stands for the model error the fit cannot
/// remove, and the cap for noise that is not white.
///
/// Motion: a window's readings are also fitted with a straight line in time. Where a
/// channel moves over the window by more than k_drift times what noise gives such a line,
/// half that motion is added to s (the mean of a slide stands for no steady value better
/// than that): a motor stalling under a load that a relief valve cannot hold is judged by
/// its direction, not by whichever hypothesis's steady state sits at the slide's mean. A
/// window that moves by more than k_drift times its scale also marks the episode: the
/// machine did something at held inputs that no steady state explains, so steady windows
/// that show nothing afterwards (a relief setting below a pressure not reached again)
/// give kUnsteady, not kNoFault, and do not end the episode.
///
/// Baseline: when the caller knows the readings at the same inputs before the fault (a
/// stretch the machine held still before the detection; set_baseline()), a window at those
/// inputs compares the change since then with the change each hypothesis predicts. The
/// model's own error at that point is the same before and after the fault and cancels, so
/// such a window's weight is 1/(σ²/n + var_baseline + min(k_sensitivity·observed change,
/// k_model·bound)²) instead: the noise and the baseline's own scatter, and a share of the
/// change for the machine's sensitivity differing from the model's (never more than the
/// model error a window without a baseline allows). The share is of the observed change,
/// the same for every hypothesis, so χ² stays a quadratic in the predicted change. It
/// isolates where the model bound alone would leave every hypothesis consistent. A channel
/// whose baseline residual exceeds half the model bound sat far from the model before the
/// fault (a valve the model has cracked and the machine has not, or a ±ε machine near the
/// bound's edge): its change is judged with a model error of half the bound (at least
/// k_model's share), whatever the change. A window kept from before the episode (the
/// onset weighting, below) allows a model error of its own residual, up to the bound.
/// Where the readings at a window's inputs were never taken before the fault (it began in
/// an input ramp), a prediction of them from the machine's healthy windows elsewhere
/// (set_expected) stands in for the baseline, its variance the prediction's.
/// An episode found as a step at held inputs starts with the machine already settled for
/// the detector's recent blocks (start()'s settled_for), so a detection just before an
/// input change still gets its window.
///
/// Verdict, over the windows of the episode: a hypothesis is consistent when its best χ²
/// lies within Δ = k_delta·max(1, χ²_best/dof) of the best one (dof = channel samples
/// compared, one per channel and window); the fault is present while the no-fault χ²
/// (every factor 1) exceeds the best by k_present·max(1, χ²_best/dof); a best χ²/dof above
/// k_unexplained that removes less than 1 − explained_share of the no-fault χ² is "no single
/// hypothesis fits" (one that removes more is the fault, in a machine the model describes
/// only roughly: a relief valve's spool and characteristic).
///
/// Timing: a fault starts at some moment unknown, as likely at any time as at another, and
/// stays. Before an episode the estimator keeps its last kPast steady windows (observe()),
/// the nominal model's verdict on the machine then, the window open at the detection last
/// (it may hold the onset, as any window may). A hypothesis at its fitted size that
/// would have moved the readings of an earlier window cannot have begun before it; one that
/// would not have shown there (a leak into a line held at charge pressure, a relief setting
/// below a pressure not reached yet) can have been present since the data began. Each
/// consistent hypothesis's χ² is therefore weighed by the likelihood of the earlier windows
/// averaged over its onset time (the onset a nuisance, uniform since the data or the last
/// episode began): the same for hypotheses that agree on those windows, a factor of the
/// onset spans' ratio apart where one of them would have shown. When every consistent
/// hypothesis outside the best one's group is k_onset_odds times less likely, the verdict
/// is isolated; the others stay listed.
///
/// Nothing here allocates or throws; the steady solves (kHyp·kGrid per window opening, and
/// the consistent hypotheses at the earlier windows per verdict) run at an input change or a
/// verdict, never per tick.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "hstmon/model_bound.hpp"
#include "hstmon/param_fault.hpp"
#include "hstmon/status.hpp"

namespace hstmon {

/// What a hypothesis changes.
enum class HypothesisKind : std::uint8_t {
  kParam = 0,   ///< a model parameter × factor
  kInput = 1,   ///< a logged input × factor (the machine's true value differs from the log)
  kSensor = 2,  ///< a constant offset on one channel's reading
};

/// One single-fault hypothesis of the estimator. Names follow the fault table:
/// `<name>+` / `<name>-` by the fitted factor's side, `sensor_<channel>` for a sensor.
struct FaultHypothesis {
  const char* plus = nullptr;   ///< name when the factor is > 1 (sensor: the sensor row's name)
  const char* minus = nullptr;  ///< name when the factor is < 1 (sensor: same as plus)
  HypothesisKind kind = HypothesisKind::kParam;
  std::int16_t index = 0;       ///< parameter, input or channel index
  /// kParam: parameters that move by the same amount as this one, nominal·(factor − 1)
  /// (a setting's companions: a relief's full-open pressure with its cracking pressure,
  /// circuit/setting_shift.hpp); -1 marks an unused entry.
  std::int16_t with[kMaxCompanions] = {-1, -1};
};

/// How long model m takes to settle at inputs u: `taus` of its slowest time constants at
/// its steady state there, within [lo, hi]; hi where it has no steady state [s]. Sets m's
/// inputs to u.
template <class Model, typename T = typename Model::Scalar>
T settle_time(Model& m, const typename Model::Inputs& u, T taus, T lo, T hi) noexcept {
  m.set_inputs(u);
  typename Model::State xs;
  T wait = hi;
  if (m.valid() && m.steady_state(xs)) {
    const T rate = m.slowest_rate(xs);
    if (rate > T(0)) wait = taus / rate;
  }
  return std::fmin(std::fmax(wait, lo), hi);
}

/// Whether every input of b lies within `rel` of a's value (exactly, where a's is 0).
template <class Inputs, typename T>
bool inputs_within(const Inputs& a, const Inputs& b, T rel) noexcept {
  // NOLINTNEXTLINE(bugprone-sizeof-expression): a.v is an array (element count), not a pointer
  for (int i = 0; i < static_cast<int>(sizeof(a.v) / sizeof(a.v[0])); ++i) {
    const T d = std::fabs(b.v[i] - a.v[i]);
    if (!(d <= rel * std::fabs(a.v[i]) + T(1e-12) * (T(1) + std::fabs(a.v[i])))) return false;
  }
  return true;
}

/// Verdict of the estimator.
enum class EstimateVerdict : std::uint8_t {
  kNone = 0,         ///< no window yet in this episode
  kNoFault = 1,      ///< the no-fault model fits as well as any hypothesis
  kIsolated = 2,     ///< one hypothesis consistent
  kAmbiguous = 3,    ///< several consistent
  kUnexplained = 4,  ///< the best hypothesis still misses by far (several faults, or outside the model)
  kUnsteady = 5,     ///< no steady window shows a fault, but one saw the machine move at held inputs
};

/// The fit of one hypothesis.
template <typename T>
struct HypothesisFit {
  std::int16_t hyp = -1;  ///< index into the hypothesis list
  T chi2 = T(0);          ///< best χ² over the episode's windows [-]
  T factor = T(1);        ///< fitted factor (param/input) [-], or offset (sensor) [channel unit]
  T lo = T(1), hi = T(1); ///< interval of the factor or offset (Δχ² = 1, scaled by χ²_best/dof) [same]
  const char* name = nullptr;
};

/// @tparam Model  a parametric model: Params::v[], Inputs::v[], set_params, set_inputs,
///                steady_state(State&), outputs(State), slowest_rate(State), valid(),
///                kOutputs; and ModelBound<Model> with Uncertainty
/// @tparam MaxHyp hypotheses the object holds
/// @tparam Ranked fits kept in rank order
template <class Model, int MaxHyp = 64, int Ranked = 8>
class FaultEstimator {
 public:
  using T = typename Model::Scalar;
  using Inputs = typename Model::Inputs;
  using Output = typename Model::Output;
  using Bound = ModelBound<Model>;
  using Uncertainty = typename Bound::Uncertainty;
  using Fit = HypothesisFit<T>;
  static constexpr int kChannels = Model::kOutputs;
  /// The factor grid in ln(factor): dense near 0 (a few % faults), out to ×20 and ×1/20.
  static constexpr int kGrid = 35;
  static constexpr int kRanked = Ranked;

  /// Settings; times in s, k_* dimensionless.
  struct Config {
    T settle_min = T(0.1);      ///< shortest wait after an input change or a detection [s]
    T settle_max = T(3);        ///< longest wait (a near-undamped mode at rest) [s]
    T settle_taus = T(3);       ///< wait in slowest time constants at the new point [-]
    T window_min = T(0.2);      ///< samples needed before a window counts [s]
    T decide_every = T(0.5);    ///< re-decide during a long window [s]
    T n_cap = T(100);           ///< samples whose noise averages out at most [-]
    T k_model = T(0.25);        ///< share of the model bound counted as model error [-]
    T k_delta = T(9);           ///< χ² lead that separates hypotheses [-]
    T k_present = T(25);        ///< χ² lead of the best fault over no fault that says a fault is there [-]
    T k_unexplained = T(50);    ///< χ²/dof of the best fit beyond which none fits [-] …
    T explained_share = T(0.1); ///< … unless it leaves less than this share of the no-fault χ² [-]
    T input_tolerance = T(0.01); ///< relative input change that starts a new window [-]
    T k_sensitivity = T(0.1);   ///< share of the observed change counted as model error in a baselined window [-]
    T k_baseline_far = T(0.5);  ///< a baseline residual beyond this share of the bound: that much model error [-]
    T k_back = T(4);            ///< change since the baseline, in standard errors, that is not back [-]
    T k_onset_odds = T(10);     ///< timing odds of the best group over every other that isolate [-]
    T past_settle_taus = T(1);  ///< wait before a window of the record before an episode [time constants]
    /// A window's trend counts beyond this many of its noise spread, and marks the episode
    /// beyond this many of its scale in the fit [-].
    T k_drift = T(4);
  };
  /// Steady windows kept from before an episode (the oldest dropped first).
  static constexpr int kPast = 16;

  /// @param model  the monitor's model (description, parameters and nominal inputs set), copied
  /// @param hyps   count hypotheses, borrowed (must outlive the estimator)
  /// @param sigma  noise σ per channel [channel unit]
  /// @param eps    the model bound's parameter uncertainty
  /// @return false on a bad argument (then nothing is estimated)
  bool configure(const Model& model, const FaultHypothesis* hyps, int count, const T* sigma, unsigned measured,
                 const Uncertainty& eps, const Config& c) noexcept {
    if (hyps == nullptr || count <= 0 || count > MaxHyp) return false;
    model_ = model;
    nominal_ = model.params();
    hyps_ = hyps;
    count_ = count;
    measured_ = measured;
    for (int i = 0; i < kChannels; ++i) sigma_[i] = sigma[i] > T(0) ? sigma[i] : T(1);
    eps_ = eps;
    cfg_ = c;
    for (int g = 0; g < kGrid; ++g) factor_[g] = std::exp(grid_log(g));
    configured_ = true;
    reset();
    return true;
  }

  /// Offers the nominal model's steady outputs y0 and model bound at inputs u, computed
  /// elsewhere on this estimator's model, nominal parameters and uncertainty (a monitor's,
  /// at its last input change): a window at exactly these inputs takes them instead of
  /// solving the same steady states again. The caller vouches that they are the numbers
  /// this estimator would compute (the host replay checks it: test_compiled_replay).
  /// @param y0     steady outputs at u [channel unit]
  /// @param bound  model bound at u per channel [channel unit]
  void offer_nominal(const Inputs& u, const T* y0, const T* bound) noexcept {
    offer_u_ = u;
    for (int i = 0; i < kN; ++i) {
      offer_y0_[i] = y0[i];
      offer_bound_[i] = bound[i];
    }
    offered_ = true;
  }
  /// True when the nominal steady outputs and bound at exactly u are on offer (offer_nominal).
  bool offers_nominal(const Inputs& u) const noexcept { return offered_ && offer_u_ == u; }

  /// Forgets the episode (windows, fits, verdict); the next window opens after a settle.
  void reset() noexcept {
    for (int k = 0; k < count_; ++k) {
      chi_[k] = Curve{};
      floor_[k] = T(0);
    }
    for (int i = 0; i < kChannels; ++i) sens_a_[i] = sens_b_[i] = T(0);
    chi0_ = T(0);
    dof_ = 0;
    windows_ = 0;
    moved_ = false;
    open_ = false;
    armed_ = false;
    verdict_ = EstimateVerdict::kNone;
    by_timing_ = false;
    n_ranked_ = 0;
    last_chi0_w_ = last_dof_w_ = T(0);
    base_.valid = 0;
    base_use_ = base_far_ = 0;
    expected_.valid = 0;
  }

  /// The model's error at inputs u before the fault: the mean residual (reading less the
  /// model's steady output) per channel [channel unit] and the variance of that mean
  /// [channel unit²]; bit i of valid: channel i has one. Call after start(); a window at
  /// inputs within the tolerance of u then counts the change since.
  void set_baseline(const Inputs& u, const T* offset, const T* var, unsigned valid) noexcept {
    base_.set(u, offset, var, valid);
  }

  /// What the machine would read at inputs u had the fault not come, predicted from its
  /// readings elsewhere before it (a record of its healthy steady windows): the mean
  /// residual per channel [channel unit] and the variance of that prediction [channel
  /// unit²]; bit i of valid: channel i has one. A window at u with no baseline of its own
  /// (set_baseline) counts the change since that, as it would since a baseline. It says
  /// nothing about the fault's going (back_to_baseline): it was never read.
  void set_expected(const Inputs& u, const T* offset, const T* var, unsigned valid) noexcept {
    expected_.set(u, offset, var, valid);
  }

  /// How long the machine takes to settle at inputs u: settle_taus slowest time constants
  /// of the nominal model there, within [settle_min, settle_max] [s].
  T settle_time(const Inputs& u) noexcept {
    model_.set_params(nominal_);
    return hstmon::settle_time(model_, u, cfg_.settle_taus, cfg_.settle_min, cfg_.settle_max);
  }

  /// Starts an episode at t: windows from now on (after a settle) count.
  /// @param settled_for how long the machine has already run at u with the change in
  ///        before t (a step found at held inputs: the detector's recent blocks) [s]; the
  ///        settle is shortened by it
  void start(T t, const Inputs& u, T settled_for = T(0)) noexcept {
    reset();
    // The window open at the detection may hold the onset, and the onset weighting allows
    // for one inside a window; it is also the last evidence on when a rival could have begun
    // (a leak that showed there since the window opened began before it). Its samples all
    // precede t, where the episode's windows start, so none counts twice.
    close_past();
    pre_armed_ = pre_open_ = false;
    t_detect_ = t;
    if (!origin_set_) {
      t_origin_ = t;
      origin_set_ = true;
    }
    for (int k = 0; k < kH; ++k) past_cached_[k] = false;
    begin_settle(t, u);
    t_open_ = std::fmax(t, t_open_ - std::fmax(T(0), settled_for));
  }

  /// Feeds one sample while no episode runs: the windows kept as the machine's record
  /// before a fault (the onset weighting). The first call sets the time the data begin.
  /// r: the observer's residuals, measured − model [channel unit] (the residual, not the
  /// reading: the model's own transient cancels, so a window opens after past_settle_taus
  /// time constants, not settle_taus); valid: bit i = r[i] is one.
  void observe(T t, const Inputs& u, const T* r, unsigned valid) noexcept {
    if (!configured_) return;
    if (!origin_set_) {
      t_origin_ = t;
      origin_set_ = true;
    }
    if (!pre_armed_ || !inputs_close(pre_u_, u)) {
      close_past();
      pre_armed_ = true;
      pre_open_ = false;
      pre_u_ = u;
      model_.set_params(nominal_);
      pre_t_open_ = t + hstmon::settle_time(model_, u, cfg_.past_settle_taus, cfg_.settle_min, cfg_.settle_max);
      return;
    }
    if (t < pre_t_open_) return;
    if (!pre_open_) {
      if (!nominal_at(u, pre_y0_, pre_bound_)) {
        pre_t_open_ = t + cfg_.settle_max;  // no steady state here: try again later
        return;
      }
      pre_open_ = true;
      pre_t_first_ = t;
      for (int i = 0; i < kN; ++i) {
        pre_sum_[i] = T(0);
        pre_n_[i] = 0;
      }
    }
    for (int i = 0; i < kChannels; ++i) {
      if (((valid & measured_) >> i & 1u) == 0) continue;
      pre_sum_[i] += r[i];
      pre_n_[i] += 1;
    }
    pre_t_last_ = t;
  }

  /// Forgets the windows before now: a fault episode ended at t, and its windows held the
  /// fault. The next onset is weighed from t.
  void forget_past(T t) noexcept {
    n_past_ = 0;
    first_past_ = 0;
    pre_armed_ = pre_open_ = false;
    t_origin_ = t;
    origin_set_ = true;
  }

  /// Feeds one sample while an episode runs. Returns true when the verdict was re-decided.
  /// @param y      readings [channel unit]; valid: bit i = channel i read
  bool add(T t, const Inputs& u, const T* y, unsigned valid) noexcept {
    if (!configured_) return false;
    if (!armed_) {
      begin_settle(t, u);
      return false;
    }
    if (!inputs_close(u_win_, u)) {
      const bool decided = close_window();
      begin_settle(t, u);
      return decided;
    }
    if (t < t_open_) return false;
    if (!open_ && !open_window(u)) {
      t_open_ = t + cfg_.settle_max;  // no steady state here: try again later
      return false;
    }
    const T tau = t - t_first_;
    for (int i = 0; i < kChannels; ++i) {
      if (((valid & measured_) >> i & 1u) == 0) continue;
      sum_[i] += y[i];
      n_[i] += 1;
      sum_t_[i] += tau;
      sum_tt_[i] += tau * tau;
      sum_ty_[i] += tau * y[i];
    }
    t_last_ = t;
    if (t - t_first_ >= cfg_.window_min && t - t_decided_ >= cfg_.decide_every) {
      t_decided_ = t;
      decide(true);
      return true;
    }
    return false;
  }

  /// Closes the window at the end of the data. Returns true when the verdict was re-decided.
  bool finish() noexcept { return close_window(); }

  EstimateVerdict verdict() const noexcept { return verdict_; }
  /// Windows closed in this episode (the open one not counted).
  int windows() const noexcept { return windows_; }
  /// Fits in rank order, best first (consistent ones first; count: ranked()).
  int ranked() const noexcept { return n_ranked_; }
  const Fit& fit(int r) const noexcept { return ranked_[r]; }
  /// Consistent hypotheses (a prefix of the ranking).
  int consistent() const noexcept { return n_consistent_; }
  /// Likelihood of fit r relative to the first, with the onset weighting [-] (1 for r = 0).
  T weight(int r) const noexcept { return weight_[r]; }
  /// The earliest time fit r can have begun without moving an earlier window's readings [s].
  T onset_from(int r) const noexcept { return onset_from_[r]; }
  /// The verdict is isolated by timing: other hypotheses fit the windows since the
  /// detection, but would have shown in the windows before it had they begun earlier.
  bool isolated_by_timing() const noexcept { return by_timing_; }
  /// Hypotheses consistent with all the evidence: consistent() when the windows alone
  /// decide; when the verdict is isolated by timing, only the best one and those that act
  /// as one with it (the others would have shown before the detection).
  int supported() const noexcept {
    if (!by_timing_) return n_consistent_;
    int n = 0;
    for (int r = 0; r < n_consistent_; ++r) n += (r == 0 || acts_as_one(0, r)) ? 1 : 0;
    return n;
  }
  /// The inputs of the window the verdict was last decided on (the open one, or the one
  /// closed by an input change).
  const Inputs& decided_at() const noexcept { return decided_u_; }
  /// Whether the window the verdict was last decided on reads as the machine did before the
  /// fault: at the baseline's inputs, every channel with a baseline within k_back standard
  /// errors (noise, motion, the baseline's scatter) of it. The model's error cancels in that
  /// change whatever its size, so this holds where the model bound is too wide to judge the
  /// no-fault model (a baseline far from the model counts too). True without a baseline at
  /// those inputs; false once that window's sums are gone (a later window has opened).
  bool back_to_baseline() const noexcept {
    if (base_.valid == 0 || !inputs_close(base_.u, decided_u_)) return true;
    if (!inputs_close(u_win_, decided_u_)) return false;
    for (int i = 0; i < kN; ++i) {
      if (((base_.valid >> i) & 1u) == 0 || n_[i] == 0) continue;
      const T change = sum_[i] / static_cast<T>(n_[i]) - y0_[i] - base_.mean[i];
      const T var = moving_mean_noise(i) + base_.var[i];
      if (change * change > cfg_.k_back * cfg_.k_back * var) return false;
    }
    return true;
  }
  /// Fits r and q change every window alike (the same χ² and factor): no sensor tells them apart.
  bool acts_as_one(int r, int q) const noexcept {
    const Fit& a = ranked_[r];
    const Fit& b = ranked_[q];
    return std::fabs(a.chi2 - b.chi2) <= T(1e-9) * std::fmax(T(1), a.chi2) &&
           std::fabs(a.factor - b.factor) <= T(1e-6) * std::fabs(a.factor);
  }
  /// χ² of the no-fault model and of the best fit over the episode; compared samples [-].
  T chi2_nominal() const noexcept { return chi0_all_; }
  T chi2_best() const noexcept { return n_ranked_ > 0 ? best_chi_ : chi0_all_; }
  int dof() const noexcept { return dof_all_; }
  /// χ²/dof of the no-fault model on the latest window alone (0 before any) [-].
  T latest_nominal_chi2_per_dof() const noexcept { return last_dof_w_ > T(0) ? last_chi0_w_ / last_dof_w_ : T(0); }

 private:
  static constexpr int kN = kChannels > 0 ? kChannels : 1;
  static constexpr int kH = MaxHyp;
  static constexpr std::size_t kNz = static_cast<std::size_t>(kN);      ///< array extent
  static constexpr std::size_t kHz = static_cast<std::size_t>(MaxHyp);  ///< array extent
  static constexpr std::size_t kGz = static_cast<std::size_t>(kGrid);   ///< array extent

  static T grid_log(int g) noexcept {
    // |ln f| steps: 0, 0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.375, 0.45, 0.525, 0.6, 0.7,
    // 0.85, 1, 1.5, 2.2, 3.
    constexpr T kSteps[18] = {T(0),    T(0.02),  T(0.05), T(0.1), T(0.15), T(0.2), T(0.25), T(0.3), T(0.375),
                              T(0.45), T(0.525), T(0.6),  T(0.7), T(0.85), T(1),   T(1.5),  T(2.2), T(3)};
    const int j = g - kGrid / 2;
    return j < 0 ? -kSteps[-j] : kSteps[j];
  }

  // χ² of one hypothesis over ln(factor): its values at the grid factors and, per grid
  // interval, gap = Σ w·(y_g+1 − y_g)² (HUGE where either end has no steady state). With
  // the outputs linear in x on an interval, χ²(t) = χ_g + t·(χ_g+1 − χ_g − gap) + t²·gap,
  // t = (x − x_g)/(x_g+1 − x_g) ∈ [0, 1]: exact for that interpolation, and convex.
  struct Curve {
    T chi[kGz] = {};
    T gap[kGz] = {};  ///< [g]: interval g … g+1; the last entry is unused
  };
  bool inputs_close(const Inputs& a, const Inputs& b) const noexcept { return inputs_within(a, b, cfg_.input_tolerance); }

  void begin_settle(T t, const Inputs& u) noexcept {
    armed_ = true;
    open_ = false;
    u_win_ = u;
    t_open_ = t + settle_time(u);
  }

  // The nominal model's steady outputs at u and its model bound there (0 where it has none).
  bool nominal_at(const Inputs& u, Output& y0, T (&bound)[kNz]) noexcept {
    model_.set_params(nominal_);
    model_.set_inputs(u);
    if (offers_nominal(u)) {
      y0 = offer_y0_;
      for (int i = 0; i < kN; ++i) bound[i] = offer_bound_[i];
      return true;
    }
    typename Model::State xs;
    if (!model_.valid() || !model_.steady_state(xs)) return false;
    y0 = model_.outputs(xs);
    if (Bound::compute(model_, eps_, bound) != Status::kOk) {
      for (int i = 0; i < kN; ++i) bound[i] = T(0);
    }
    return true;
  }

  // The window observed before an episode, closed into the ring (the oldest dropped).
  void close_past() noexcept {
    if (!pre_open_) return;
    pre_open_ = false;
    if (pre_t_last_ - pre_t_first_ < cfg_.window_min) return;
    if (n_past_ == kPast) {
      first_past_ = (first_past_ + 1) % kPast;
      --n_past_;
    }
    PastWindow& w = past_[(first_past_ + n_past_) % kPast];
    ++n_past_;
    w.u = pre_u_;
    w.t0 = pre_t_first_;
    w.t1 = pre_t_last_;
    w.valid = 0;
    for (int i = 0; i < kN; ++i) {
      w.y0[i] = pre_y0_[i];
      if (pre_n_[i] == 0) continue;
      const T n = std::fmin(static_cast<T>(pre_n_[i]), cfg_.n_cap);
      w.mean[i] = pre_sum_[i] / static_cast<T>(pre_n_[i]);
      // The model error here: a share of the bound, or, up to the whole bound, what the
      // machine read (a ±ε machine sits anywhere within it); else the machine's own offset
      // would time whichever hypothesis happens to move the channel its way.
      const T err = std::fmax(cfg_.k_model * pre_bound_[i], std::fmin(std::fabs(w.mean[i]), pre_bound_[i]));
      w.var[i] = sigma_[i] * sigma_[i] / n + err * err;
      w.valid |= 1u << i;
    }
  }

  // Hypothesis k at `factor` in each earlier window (chronological), as the two sums that
  // give its χ² less the nominal model's when a share f of the window lies after the
  // onset: Δχ²(f) = f²·a − 2f·b, a = Σ Δ²/var, b = Σ r·Δ/var (Δ its predicted change, r the
  // window's mean residual). A window where k has no steady state counts as far off.
  void past_misfit(int k, T factor, T (&a)[kPast], T (&b)[kPast]) noexcept {
    const FaultHypothesis& h = hyps_[k];
    typename Model::State xs;
    for (int j = 0; j < n_past_; ++j) {
      const PastWindow& w = past_[(first_past_ + j) % kPast];
      T delta[kNz] = {};
      bool ok = true;
      if (h.kind == HypothesisKind::kSensor) {
        if (h.index >= 0 && h.index < kN) delta[h.index] = factor;
      } else {
        typename Model::Params p = nominal_;
        Inputs v = w.u;
        if (h.kind == HypothesisKind::kParam) {
          apply_param_fault(p, nominal_, h.index, h.with, factor);
        } else {
          v.v[h.index] *= factor;
        }
        model_.set_params(p);
        model_.set_inputs(v);
        ok = model_.valid() && model_.steady_state(xs);
        if (ok) {
          const Output y = model_.outputs(xs);
          for (int i = 0; i < kN; ++i) delta[i] = y[i] - w.y0[i];
        }
      }
      a[j] = b[j] = T(0);
      for (int i = 0; i < kN; ++i) {
        if (((w.valid >> i) & 1u) == 0) continue;
        a[j] += delta[i] * delta[i] / w.var[i];
        b[j] += w.mean[i] * delta[i] / w.var[i];
      }
      if (!ok) {
        a[j] = T(1e6);
        b[j] = T(0);
      }
    }
    model_.set_params(nominal_);
  }

  // ln of the mean over f in (0, 1) of exp(−½·(f²·a − 2f·b)/scale): an onset inside a
  // window, at any point of it alike (midpoint rule); `share`: the largest f whose misfit
  // stays within the consistency margin.
  T inside_log_mean(T a, T b, T scale, T& share) const noexcept {
    constexpr int kSteps = 16;
    T term[kSteps];
    T top = -T(HUGE_VAL);
    share = T(0);
    for (int s = 0; s < kSteps; ++s) {
      const T f = (static_cast<T>(s) + T(0.5)) / static_cast<T>(kSteps);
      const T d = (f * f * a - T(2) * f * b) / scale;
      if (d <= cfg_.k_delta) share = f;
      term[s] = -T(0.5) * d;
      top = std::fmax(top, term[s]);
    }
    if ((a - T(2) * b) / scale <= cfg_.k_delta) share = T(1);
    T sum = T(0);
    for (int s = 0; s < kSteps; ++s) sum += std::exp(term[s] - top);
    return top + std::log(sum / static_cast<T>(kSteps));
  }

  // ln of the earlier windows' likelihood under hypothesis k at `factor`, averaged over its
  // onset (uniform from t_origin_ to the detection; the common ln of that span left out),
  // relative to the nominal model's; `from`: the earliest onset after which no window moves
  // by more than the consistency margin [s].
  T onset_log_mass(int k, T factor, T scale, T& from) noexcept {
    T (&a)[kPast] = past_a_[k];
    T (&b)[kPast] = past_b_[k];
    if (!past_cached_[k] || std::fabs(std::log(factor / past_factor_[k])) > T(1e-3)) {
      past_misfit(k, factor, a, b);
      past_factor_[k] = factor;
      past_cached_[k] = true;
    }
    from = t_origin_;
    // suffix[j]: the misfit of windows j… wholly after the onset.
    T suffix[kPast + 1];
    suffix[n_past_] = T(0);
    for (int j = n_past_ - 1; j >= 0; --j) suffix[j] = suffix[j + 1] + (a[j] - T(2) * b[j]) / scale;
    // Onset segments: in the gap before window j (windows j… after it), inside window j
    // (a share of j, and j+1… after it), and after the last window (none after it).
    T terms[2 * kPast + 1];
    int n = 0;
    T t_prev = t_origin_;
    for (int j = 0; j < n_past_; ++j) {
      const PastWindow& w = past_[(first_past_ + j) % kPast];
      if (w.t0 > t_prev) terms[n++] = std::log(w.t0 - t_prev) - T(0.5) * suffix[j];
      if (w.t1 > w.t0) {
        T share = T(0);
        terms[n++] = std::log(w.t1 - w.t0) + inside_log_mean(a[j], b[j], scale, share) - T(0.5) * suffix[j + 1];
        if (share < T(1)) from = std::fmax(from, w.t1 - share * (w.t1 - w.t0));
      }
      t_prev = std::fmax(t_prev, w.t1);
    }
    terms[n++] = std::log(std::fmax(t_detect_ - t_prev, T(1e-3)));
    T top = terms[0];
    for (int j = 1; j < n; ++j) top = std::fmax(top, terms[j]);
    T sum = T(0);
    for (int j = 0; j < n; ++j) sum += std::exp(terms[j] - top);
    return top + std::log(sum);
  }

  // Weighs the consistent fits by their onset (class comment) and re-ranks them; the
  // verdict becomes isolated when the best group leads every other by k_onset_odds.
  void weigh_onsets(T best, T scale) noexcept {
    T score[static_cast<std::size_t>(Ranked)] = {};
    for (int r = 0; r < n_consistent_; ++r) {
      score[r] = -T(0.5) * (ranked_[r].chi2 - best) / scale +
                 onset_log_mass(ranked_[r].hyp, ranked_[r].factor, scale, onset_from_[r]);
    }
    // Insertion sort of the consistent prefix by score, best first (stable).
    for (int r = 1; r < n_consistent_; ++r) {
      const Fit f = ranked_[r];
      const T s = score[r], from = onset_from_[r];
      int q = r;
      while (q > 0 && score[q - 1] < s) {
        ranked_[q] = ranked_[q - 1];
        score[q] = score[q - 1];
        onset_from_[q] = onset_from_[q - 1];
        --q;
      }
      ranked_[q] = f;
      score[q] = s;
      onset_from_[q] = from;
    }
    bool apart = n_consistent_ > 1;
    bool any_other = false;
    for (int r = 0; r < n_consistent_; ++r) {
      weight_[r] = std::exp(score[r] - score[0]);
      if (r == 0 || acts_as_one(0, r)) continue;
      any_other = true;
      if (weight_[r] * cfg_.k_onset_odds > T(1)) apart = false;
    }
    if (apart && any_other) {
      verdict_ = EstimateVerdict::kIsolated;
      by_timing_ = true;
    }
  }

  // The model's steady outputs for every hypothesis and factor at the window's inputs.
  bool open_window(const Inputs& u) noexcept {
    if (!nominal_at(u, y0_, bound_)) return false;
    for (int i = 0; i < kN; ++i) model_err_[i] = cfg_.k_model * bound_[i];
    typename Model::State xs;
    // A channel whose pre-fault residual lay beyond k_baseline_far of the model bound sat
    // far from the model (a relief valve the model has cracked and the machine has not,
    // or a ±ε machine near its bound's edge): its sensitivities may differ from the
    // model's, so its change since the baseline is judged with a model error of that share
    // of the bound, not a share of the observed change. (Fitted without its baseline, the
    // machine's own offset read as evidence for whichever fault moves the channel its way:
    // a p_pp transmitter's bias isolated as kp−, tests/circuit test_far_channel_bias. With
    // k_baseline_far at the whole bound the test stand's machine with a shut relief valve
    // lost its leak from the set: CircuitMonitor.MachineWithShutReliefValve….)
    // The readings before the fault at these inputs, else the prediction of them.
    const bool seen = base_.valid != 0 && inputs_close(base_.u, u);
    const bool expected = !seen && expected_.valid != 0 && inputs_close(expected_.u, u);
    const Reference& ref = seen ? base_ : expected_;
    const unsigned valid = seen || expected ? ref.valid : 0u;
    base_use_ = 0;
    base_far_ = 0;
    for (int i = 0; i < kN; ++i) {
      if (((valid >> i) & 1u) == 0) continue;
      base_use_ |= 1u << i;
      if (std::fabs(ref.mean[i]) <= cfg_.k_baseline_far * bound_[i]) continue;
      base_far_ |= 1u << i;
      model_err_[i] = std::fmax(model_err_[i], cfg_.k_baseline_far * bound_[i]);
    }
    for (int i = 0; i < kN; ++i) {
      offset_[i] = baselined(i) ? ref.mean[i] : T(0);
      win_base_var_[i] = baselined(i) ? ref.var[i] : T(0);
    }
    for (int k = 0; k < count_; ++k) {
      const FaultHypothesis& h = hyps_[k];
      for (int g = 0; g < kGrid; ++g) {
        ok_[k][g] = true;
        if (h.kind == HypothesisKind::kSensor || g == kGrid / 2) {
          for (int i = 0; i < kN; ++i) ys_[k][g][i] = y0_[i];
          continue;
        }
        typename Model::Params p = nominal_;
        Inputs v = u;
        if (h.kind == HypothesisKind::kParam) {
          apply_param_fault(p, nominal_, h.index, h.with, factor_[g]);
        } else {
          v.v[h.index] *= factor_[g];
        }
        model_.set_params(p);
        model_.set_inputs(v);
        ok_[k][g] = model_.valid() && model_.steady_state(xs);
        const Output yk = ok_[k][g] ? model_.outputs(xs) : y0_;
        for (int i = 0; i < kN; ++i) ys_[k][g][i] = yk[i];
      }
    }
    model_.set_params(nominal_);
    for (int i = 0; i < kN; ++i) {
      sum_[i] = sum_t_[i] = sum_tt_[i] = sum_ty_[i] = T(0);
      n_[i] = 0;
    }
    open_ = true;
    t_first_ = t_last_ = t_open_;
    t_decided_ = t_open_;
    return true;
  }

  bool baselined(int i) const noexcept { return ((base_use_ >> i) & 1u) != 0; }

  // σ² of channel i's window mean less the model's prediction: the noise and the model
  // error; with a baseline, the noise, the baseline's scatter and the share of the observed
  // change (never more than the model error) that a sensitivity off the model's may make.
  // change: the window's mean less the baseline's model error, less the model's output.
  T variance(int i, T change) const noexcept {
    const T noise = moving_mean_noise(i);
    if (!baselined(i)) return noise + model_err_[i] * model_err_[i];
    const bool far = ((base_far_ >> i) & 1u) != 0;
    const T share = far ? model_err_[i] : std::fmin(cfg_.k_sensitivity * std::fabs(change), model_err_[i]);
    return noise + win_base_var_[i] + share * share;
  }

  // The open window's mean on channel i as a steady value: its noise variance and half its
  // motion (drift()) squared [channel unit²].
  T moving_mean_noise(int i) const noexcept {
    const T motion = T(0.5) * drift(i);
    return mean_noise(i) + motion * motion;
  }

  // The noise variance of the open window's mean on channel i [channel unit²].
  T mean_noise(int i) const noexcept {
    const T n = std::fmin(static_cast<T>(n_[i]), cfg_.n_cap);
    return sigma_[i] * sigma_[i] / n;
  }

  // True when some channel of the open window moves by more than k_drift times its scale
  // in the fit without the motion (noise of the mean and model error).
  bool window_moved() const noexcept {
    for (int i = 0; i < kN; ++i) {
      if (n_[i] == 0) continue;
      const T scale = std::sqrt(mean_noise(i) + model_err_[i] * model_err_[i]);
      if (drift(i) > cfg_.k_drift * scale) return true;
    }
    return false;
  }

  // How far channel i's readings move over the open window by their least-squares line,
  // beyond what noise alone gives such a line (k_drift of its spread) [channel unit]. A
  // window's mean stands for a steady value only to within half of it: a machine still
  // sliding at held inputs (a motor stalling under a load that a relief valve cannot hold)
  // is not at any steady state, and its mean favours whichever hypothesis's steady state
  // happens to sit there.
  T drift(int i) const noexcept {
    if (n_[i] < 8) return T(0);
    const T n = static_cast<T>(n_[i]);
    const T den = n * sum_tt_[i] - sum_t_[i] * sum_t_[i];
    if (!(den > T(0))) return T(0);
    const T span = t_last_ - t_first_;
    const T d = std::fabs(n * sum_ty_[i] - sum_t_[i] * sum_[i]) / den * span;
    const T noise = cfg_.k_drift * sigma_[i] * std::sqrt(n / den) * span;
    return d > noise ? d : T(0);
  }

  // The open window's χ² per hypothesis and factor (and the spread between neighbouring
  // factors' outputs, Curve::gap), added to the closed windows' sums.
  void window_terms(Curve (&chi)[kHz], T& chi0, T (&sa)[kNz], T (&sb)[kNz], int& dof) const noexcept {
    for (int k = 0; k < count_; ++k) chi[k] = chi_[k];
    chi0 = chi0_;
    dof = dof_;
    for (int i = 0; i < kN; ++i) {
      sa[i] = sens_a_[i];
      sb[i] = sens_b_[i];
    }
    T w[kNz] = {}, mean[kNz] = {};
    for (int i = 0; i < kN; ++i) {
      if (n_[i] == 0) continue;
      mean[i] = sum_[i] / static_cast<T>(n_[i]) - offset_[i];  // the baseline's model error removed
      const T r = mean[i] - y0_[i];
      w[i] = T(1) / variance(i, r);
      chi0 += w[i] * r * r;
      sa[i] += w[i];
      sb[i] += w[i] * r;
      ++dof;
    }
    for (int k = 0; k < count_; ++k) {
      if (hyps_[k].kind == HypothesisKind::kSensor) continue;
      for (int g = 0; g < kGrid; ++g) {
        if (!ok_[k][g]) {
          chi[k].chi[g] = T(HUGE_VAL);
          continue;
        }
        T s = T(0), d = T(0);
        const bool next = g + 1 < kGrid && ok_[k][g + 1];
        for (int i = 0; i < kN; ++i) {
          const T r = mean[i] - ys_[k][g][i];
          s += w[i] * r * r;
          if (next) d += w[i] * (ys_[k][g + 1][i] - ys_[k][g][i]) * (ys_[k][g + 1][i] - ys_[k][g][i]);
        }
        chi[k].chi[g] += s;
        if (g + 1 < kGrid) chi[k].gap[g] = next ? chi[k].gap[g] + d : T(HUGE_VAL);
      }
    }
  }

  bool close_window() noexcept {
    if (!open_) return false;
    open_ = false;
    bool any = false;
    for (int i = 0; i < kN; ++i) any = any || n_[i] > 0;
    if (!any || t_last_ - t_first_ < cfg_.window_min) return false;
    moved_ = moved_ || window_moved();
    T c0_before = chi0_;
    int d_before = dof_;
    window_terms(scratch_, chi0_, sens_a_, sens_b_, dof_);
    add_window_floors(scratch_, floor_);
    for (int k = 0; k < count_; ++k) chi_[k] = scratch_[k];
    last_chi0_w_ = chi0_ - c0_before;
    last_dof_w_ = static_cast<T>(dof_ - d_before);
    ++windows_;
    decide(false);
    return true;
  }

  static bool interval_ok(const Curve& c, int g) noexcept {
    return std::isfinite(c.chi[g]) && std::isfinite(c.chi[g + 1]) && std::isfinite(c.gap[g]);
  }
  static T at(const Curve& c, int g, T t) noexcept {
    return c.chi[g] + t * (c.chi[g + 1] - c.chi[g] - c.gap[g]) + t * t * c.gap[g];
  }
  static T x_at(int g, T t) noexcept { return grid_log(g) + t * (grid_log(g + 1) - grid_log(g)); }

  // The least χ² of a curve and where it lies (x = ln factor); on a grid node where no
  // interval around it is usable.
  struct Vertex {
    int g = kGrid / 2;  ///< the interval (or node) holding the least value
    T t = T(0), x = T(0), chi2 = T(0);
  };
  static Vertex vertex(const Curve& c) noexcept {
    Vertex v;
    v.chi2 = c.chi[v.g];
    for (int g = 0; g < kGrid; ++g) {
      if (c.chi[g] < v.chi2) {
        v.g = g;
        v.t = T(0);
        v.chi2 = c.chi[g];
      }
    }
    for (int g = 0; g + 1 < kGrid; ++g) {
      if (!interval_ok(c, g) || !(c.gap[g] > T(0))) continue;
      const T t = (c.chi[g] - c.chi[g + 1] + c.gap[g]) / (T(2) * c.gap[g]);
      if (!(t > T(0) && t < T(1))) continue;
      const T y = std::fmax(T(0), at(c, g, t));
      if (y < v.chi2) {
        v.g = g;
        v.t = t;
        v.chi2 = y;
      }
    }
    v.x = v.g + 1 < kGrid ? x_at(v.g, v.t) : grid_log(v.g);
    return v;
  }

  // Where the curve first reaches `level` walking from the vertex towards dir (−1 or +1),
  // as ln factor; the grid's end when it never does.
  static T crossing(const Curve& c, const Vertex& v, T level, int dir) noexcept {
    int g = v.g;
    T t = v.t;
    if (dir > 0 && (g + 1 >= kGrid)) return grid_log(kGrid - 1);
    if (dir < 0 && t <= T(0)) {
      if (g == 0) return grid_log(0);
      --g;
      t = T(1);
    }
    for (;;) {
      if (!interval_ok(c, g)) return grid_log(dir > 0 ? g : g + 1);
      // Roots of gap·τ² + (χ_g+1 − χ_g − gap)·τ + χ_g − level = 0 beyond t in dir.
      const T a = c.gap[g], b = c.chi[g + 1] - c.chi[g] - c.gap[g], k = c.chi[g] - level;
      T root = T(-1);
      if (a > T(0)) {
        const T disc = b * b - T(4) * a * k;
        if (disc >= T(0)) {
          const T sq = std::sqrt(disc);
          const T r = dir > 0 ? (-b + sq) / (T(2) * a) : (-b - sq) / (T(2) * a);
          root = r;
        }
      } else if (b != T(0)) {
        root = -k / b;
      }
      if (dir > 0 ? (root >= t && root <= T(1)) : (root <= t && root >= T(0))) return x_at(g, root);
      if (dir > 0) {
        if (g + 2 >= kGrid) return grid_log(kGrid - 1);
        ++g;
        t = T(0);
      } else {
        if (g == 0) return grid_log(0);
        --g;
        t = T(1);
      }
    }
  }

  // Best factor of hypothesis k from its χ² curve; the interval where χ² rises by
  // `scale`. A sum over windows whose valleys lie apart is no single valley: its least
  // value is kept at or above the sum of the windows' own least χ² (floor).
  Fit fit_param(int k, const Curve& c, T floor, T scale) const noexcept {
    Fit f;
    f.hyp = static_cast<std::int16_t>(k);
    const Vertex v = vertex(c);
    f.lo = std::exp(crossing(c, v, v.chi2 + scale, -1));
    f.hi = std::exp(crossing(c, v, v.chi2 + scale, +1));
    T node = c.chi[0];  // the least χ² at a grid factor: the floor never lifts the fit above it
    for (int g = 1; g < kGrid; ++g) node = std::fmin(node, c.chi[g]);
    f.chi2 = std::fmax(v.chi2, std::fmin(floor, node));
    f.factor = std::exp(v.x);
    f.name = f.factor >= T(1) ? hyps_[k].plus : hyps_[k].minus;
    return f;
  }

  // Offset δ on channel i: χ² = χ²_0 − b²/a, δ = b/a, interval ±√(scale/a).
  Fit fit_sensor(int k, T chi0, const T (&sa)[kNz], const T (&sb)[kNz], T scale) const noexcept {
    Fit f;
    f.hyp = static_cast<std::int16_t>(k);
    const int i = hyps_[k].index;
    f.name = hyps_[k].plus;
    if (i < 0 || i >= kN || !(sa[i] > T(0))) {
      f.chi2 = chi0;
      f.factor = f.lo = f.hi = T(0);
      return f;
    }
    f.factor = sb[i] / sa[i];
    f.chi2 = chi0 - sb[i] * sb[i] / sa[i];
    const T half = std::sqrt(scale / sa[i]);
    f.lo = f.factor - half;
    f.hi = f.factor + half;
    return f;
  }

  // Adds each hypothesis's least χ² in one window (sums − the closed windows' sums) to floor.
  void add_window_floors(const Curve (&sums)[kHz], T (&floor)[kHz]) const noexcept {
    for (int k = 0; k < count_; ++k) {
      if (hyps_[k].kind == HypothesisKind::kSensor) continue;
      Curve one;
      for (int g = 0; g < kGrid; ++g) {
        one.chi[g] = sums[k].chi[g] - chi_[k].chi[g];
        one.gap[g] = sums[k].gap[g] - chi_[k].gap[g];
      }
      floor[k] += vertex(one).chi2;
    }
  }

  // Ranks on the closed windows' sums, with the open window's terms added when asked.
  void decide(bool with_open) noexcept {
    decided_u_ = u_win_;
    if (!with_open) {
      rank(chi_, floor_, chi0_, sens_a_, sens_b_, dof_);
      return;
    }
    T sa[kNz], sb[kNz], chi0, floor[kHz];
    int dof;
    window_terms(scratch_, chi0, sa, sb, dof);
    for (int k = 0; k < count_; ++k) floor[k] = floor_[k];
    add_window_floors(scratch_, floor);
    rank(scratch_, floor, chi0, sa, sb, dof);
  }

  void rank(const Curve (&chi)[kHz], const T (&floor)[kHz], T chi0, const T (&sa)[kNz], const T (&sb)[kNz],
            int dof) noexcept {
    chi0_all_ = chi0;
    dof_all_ = dof;
    if (dof == 0) return;
    // First pass for the best χ², which scales the intervals and the margins.
    T best = chi0;
    for (int k = 0; k < count_; ++k) {
      if (hyps_[k].kind == HypothesisKind::kSensor) {
        best = std::fmin(best, fit_sensor(k, chi0, sa, sb, T(1)).chi2);
      } else {
        best = std::fmin(best, vertex(chi[k]).chi2);
      }
    }
    const T per = best / static_cast<T>(dof);
    const T scale = std::fmax(T(1), per);
    n_ranked_ = 0;
    for (int k = 0; k < count_; ++k) {
      const Fit f = hyps_[k].kind == HypothesisKind::kSensor ? fit_sensor(k, chi0, sa, sb, scale)
                                                             : fit_param(k, chi[k], floor[k], scale);
      insert(f);
    }
    const T best_chi = n_ranked_ > 0 ? ranked_[0].chi2 : chi0;
    best_chi_ = best_chi;
    const T delta = cfg_.k_delta * scale;
    n_consistent_ = 0;
    while (n_consistent_ < n_ranked_ && ranked_[n_consistent_].chi2 <= best_chi + delta) ++n_consistent_;
    by_timing_ = false;
    for (int r = 0; r < n_ranked_; ++r) {
      weight_[r] = std::exp(-T(0.5) * (ranked_[r].chi2 - best_chi) / scale);
      onset_from_[r] = t_origin_;
    }
    if (chi0 <= best_chi + cfg_.k_present * scale) {
      // After a window where the machine moved at held inputs, that no steady window
      // shows a fault says only that none shows at these points, not that it has gone.
      verdict_ = moved_ || window_moved() ? EstimateVerdict::kUnsteady : EstimateVerdict::kNoFault;
    } else if (per > cfg_.k_unexplained && best_chi > cfg_.explained_share * chi0) {
      verdict_ = EstimateVerdict::kUnexplained;
    } else {
      verdict_ = n_consistent_ == 1 ? EstimateVerdict::kIsolated : EstimateVerdict::kAmbiguous;
      if (verdict_ == EstimateVerdict::kAmbiguous && n_past_ > 0) weigh_onsets(best_chi, scale);
    }
  }

  void insert(const Fit& f) noexcept {
    if (!std::isfinite(f.chi2)) return;
    int pos = n_ranked_;
    while (pos > 0 && ranked_[pos - 1].chi2 > f.chi2) --pos;
    if (pos >= Ranked) return;
    const int last = n_ranked_ < Ranked ? n_ranked_ : Ranked - 1;
    for (int j = last; j > pos; --j) ranked_[j] = ranked_[j - 1];
    ranked_[pos] = f;
    if (n_ranked_ < Ranked) ++n_ranked_;
  }

  Model model_{};
  typename Model::Params nominal_{};
  // What offer_nominal() gave: the nominal steady outputs and bound at offer_u_.
  bool offered_ = false;
  Inputs offer_u_{};
  Output offer_y0_{};
  T offer_bound_[kNz] = {};
  const FaultHypothesis* hyps_ = nullptr;
  int count_ = 0;
  unsigned measured_ = 0;
  T sigma_[kNz] = {};
  Uncertainty eps_{};
  Config cfg_{};
  bool configured_ = false;
  T factor_[kGz] = {};
  // Closed windows of the episode, summed.
  Curve chi_[kHz] = {};
  T floor_[kHz] = {};  ///< per hypothesis, the sum of each closed window's least χ² [-]
  T chi0_ = T(0);
  T sens_a_[kNz] = {}, sens_b_[kNz] = {};
  int dof_ = 0;
  int windows_ = 0;
  bool moved_ = false;  ///< a closed window of this episode saw the machine move at held inputs (window_moved)
  // The open window.
  bool armed_ = false, open_ = false;
  Inputs u_win_{};
  Inputs decided_u_{};  ///< decided_at()
  T t_open_ = T(0), t_first_ = T(0), t_last_ = T(0), t_decided_ = T(0);
  Output y0_{};
  T bound_[kNz] = {};      ///< the model bound at the open window's inputs [channel unit]
  T model_err_[kNz] = {};
  // The baseline (set_baseline) and whether the open window is at its inputs.
  // What the readings at inputs u were, or would be, without the fault: the mean residual
  // and its variance per channel; bit i of valid: channel i has one.
  struct Reference {
    Inputs u{};
    T mean[kNz] = {}, var[kNz] = {};
    unsigned valid = 0;
    void set(const Inputs& at, const T* offset, const T* variance, unsigned have) noexcept {
      u = at;
      valid = 0;
      for (int i = 0; i < kN; ++i) {
        if (((have >> i) & 1u) == 0 || !std::isfinite(offset[i]) || !(variance[i] >= T(0))) continue;
        mean[i] = offset[i];
        var[i] = variance[i];
        valid |= 1u << i;
      }
    }
  };
  Reference base_;         ///< read before the fault (set_baseline)
  Reference expected_;     ///< predicted from the healthy windows elsewhere (set_expected)
  unsigned base_use_ = 0;  ///< bit i: the open window fits channel i's change since the baseline
  unsigned base_far_ = 0;  ///< bit i: … one beyond k_baseline_far of the bound (judged as variance() says)
  T offset_[kNz] = {};  ///< the baseline's residual, per channel (0 without) [channel unit]
  T win_base_var_[kNz] = {};  ///< the variance of offset_ [channel unit²]
  T ys_[kHz][kGz][kNz] = {};
  Curve scratch_[kHz] = {};  ///< decide()'s sums with the open window
  bool ok_[kHz][kGz] = {};
  T sum_[kNz] = {};
  std::uint32_t n_[kNz] = {};
  T sum_t_[kNz] = {}, sum_tt_[kNz] = {},
    sum_ty_[kNz] = {};  ///< Σ τ, Σ τ², Σ τ·y over the open window (τ from t_first_)
  // The record before the episode (observe()): the window being observed, and the ring.
  struct PastWindow {
    Inputs u{};
    T t0 = T(0), t1 = T(0);  ///< first and last sample [s]
    T mean[kNz] = {};        ///< mean residual (measured − model) [channel unit]
    T var[kNz] = {};         ///< its variance: noise and model error [channel unit²]
    T y0[kNz] = {};          ///< the nominal model's steady output [channel unit]
    unsigned valid = 0;      ///< bit i: channel i read
  };
  bool origin_set_ = false;
  T t_origin_ = T(0);  ///< the earliest onset: the data's or the last episode's end [s]
  T t_detect_ = T(0);  ///< the episode's start [s]
  bool pre_armed_ = false, pre_open_ = false;
  Inputs pre_u_{};
  T pre_t_open_ = T(0), pre_t_first_ = T(0), pre_t_last_ = T(0);
  Output pre_y0_{};
  T pre_bound_[kNz] = {}, pre_sum_[kNz] = {};
  std::uint32_t pre_n_[kNz] = {};
  PastWindow past_[kPast]{};
  int n_past_ = 0, first_past_ = 0;
  // Per hypothesis, at past_factor_: its misfit's sums in each earlier window (past_misfit).
  T past_a_[kHz][kPast] = {}, past_b_[kHz][kPast] = {};
  T past_factor_[kHz] = {};
  bool past_cached_[kHz] = {};
  // Verdict.
  EstimateVerdict verdict_ = EstimateVerdict::kNone;
  Fit ranked_[static_cast<std::size_t>(Ranked)]{};
  T weight_[static_cast<std::size_t>(Ranked)] = {};
  T onset_from_[static_cast<std::size_t>(Ranked)] = {};
  bool by_timing_ = false;
  T best_chi_ = T(0);
  int n_ranked_ = 0, n_consistent_ = 0;
  T chi0_all_ = T(0);
  int dof_all_ = 0;
  T last_chi0_w_ = T(0), last_dof_w_ = T(0);
};

}  // namespace hstmon
