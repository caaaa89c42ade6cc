#include "hstmon_circuit/fault_fit_diagnosis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <deque>

#include "hstmon/circuit/circuit_bound.hpp"
#include "hstmon/circuit/setting_shift.hpp"
#include "hstmon/fault_estimator.hpp"
#include "hstmon/held_step_detector.hpp"
#include "hstmon_circuit/healthy_record.hpp"
#include "hstmon_host/circuit_units.hpp"

namespace hstmon::circuit_tools {

namespace {

using Model = host::HostCircuitModel;
using Estimator = FaultEstimator<Model, 64, 8>;
using StepDetector = HeldStepDetector<double, Model::kOutputs>;

// How long the inputs must have held still before a detection for it to name a point where
// the fault showed [s]: longer than a logged ramp's rows (1–10 ms), shorter than any hold.
constexpr double kHeldBeforeDetection = 0.1;

// "−15 % (−17 … −13 %)": a factor as a relative change with its interval.
std::string percent(double f, double lo, double hi) {
  return fmt::format("{:+.0f} % ({:+.0f} … {:+.0f} %)", 100.0 * (f - 1.0), 100.0 * (lo - 1.0), 100.0 * (hi - 1.0));
}

// Hypotheses among the first `shown` fits that fit every window alike (the same χ² and the
// same factor: one product, or one law between the same nodes) act as one for these
// sensors, and are said so: "R_ip-, R_im- act as one here (...)".
std::string same_fit_classes(const Estimator& est, int shown) {
  std::string text;
  std::vector<bool> used(static_cast<std::size_t>(shown), false);
  for (int a = 0; a < shown; ++a) {
    if (used[static_cast<std::size_t>(a)]) continue;
    std::string group = est.fit(a).name;
    int members = 1;
    for (int b = a + 1; b < shown; ++b) {
      if (est.acts_as_one(a, b)) {
        used[static_cast<std::size_t>(b)] = true;
        group += std::string(", ") + est.fit(b).name;
        ++members;
      }
    }
    if (members > 1) text += (text.empty() ? "" : "; ") + group;
  }
  if (text.empty()) return text;
  return text + ": each group acts as one at every point seen (the same change on every sensor), so no sensor here "
                "tells its members apart";
}

// Why an isolation by timing names the first: "R_ip-, R_im- (after 21.6 s) would have shown
// in the steady stretches before the detection had they begun earlier; R_ext_b- fits any
// start since 0 s".
std::string timing_reason(const Estimator& est) {
  std::string others;
  double lead = 0.0;  // the likeliest of the others, relative to the first
  for (int r = 1; r < est.consistent(); ++r) {
    if (est.acts_as_one(0, r)) continue;
    others += fmt::format("{}{} (after {:.3g} s)", others.empty() ? "" : ", ", est.fit(r).name, est.onset_from(r));
    lead = std::fmax(lead, est.weight(r));
  }
  const std::string odds = lead > 1e-6 ? fmt::format("{:.0f} times as likely or more", 1.0 / lead) : "far likelier";
  return fmt::format("isolated by timing: {} would have shown in the steady stretches before the detection had "
                     "they begun earlier; {} fits any start since {:.3g} s, {}",
                     others, est.fit(0).name, est.onset_from(0), odds);
}

}  // namespace

struct FaultFitDiagnosis::Impl {
  const LoadedCircuit& c;
  std::deque<std::string> names;  // stable addresses for the hypotheses' names
  std::vector<FaultHypothesis> hyps;
  std::vector<double> nominal;    // per hypothesis: the parameter's or input's nominal value [SI]
  Estimator est;
  bool ok = false;
  StepDetector step;
  std::unique_ptr<HealthyRecord> record;  ///< the machine as its healthy windows showed it
  Model::Inputs u_hold{};  ///< the inputs the detector's blocks were read at
  bool holding = false;
  double t_settled = 0.0;          ///< the hold's settle ends [s]
  double t_hold = 0.0;             ///< the inputs have held at u_hold since [s]
  /// The episode's fault showed at these held inputs (the detection's); false when it was
  /// detected while the inputs moved.
  bool seen_held = false;
  Model::Inputs u_seen{};
  // The inputs the estimator was last given the record's prediction at, since t_expected.
  Model::Inputs u_expected{};
  double t_expected = 0.0;
  bool expected_done = false;
  std::vector<double> y_hat_held;  ///< the model's outputs once settled (empty before) [SI]

  explicit Impl(const LoadedCircuit& circuit) : c(circuit) {}

  const char* keep(std::string s) {
    names.push_back(std::move(s));
    return names.back().c_str();
  }

  void add(HypothesisKind kind, int index, const std::string& base, double value) {
    if (hyps.size() >= 64) return;
    FaultHypothesis h;
    h.kind = kind;
    h.index = static_cast<std::int16_t>(index);
    if (kind == HypothesisKind::kParam) {
      const circuit::SettingCompanions with = circuit::setting_companions(c.file.circuit, index);
      for (int j = 0; j < kMaxCompanions; ++j) h.with[j] = with.index[j];
    }
    if (kind == HypothesisKind::kSensor) {
      h.plus = h.minus = keep("sensor_" + base);
    } else {
      h.plus = keep(base + "+");
      h.minus = keep(base + "-");
    }
    hyps.push_back(h);
    nominal.push_back(value);
  }

  // The size of fit f in words: the parameter's new value and its change, or the offset.
  std::string size_text(const HypothesisFit<double>& f) const {
    const FaultHypothesis& h = hyps[static_cast<std::size_t>(f.hyp)];
    const double v0 = nominal[static_cast<std::size_t>(f.hyp)];
    if (h.kind == HypothesisKind::kSensor) {
      const host::CircuitSensor& s = c.file.sensors[static_cast<std::size_t>(h.index)];
      const host::DisplayUnit d = host::display_unit(s.quantity, s.unit);
      return fmt::format("offset {:+.3g} {} ({:+.3g} … {:+.3g})", d.of(f.factor), d.unit, d.of(f.lo), d.of(f.hi));
    }
    const std::string base = std::string(h.plus).substr(0, std::string(h.plus).size() - 1);
    const host::DisplayUnit d = h.kind == HypothesisKind::kParam
                                    ? host::display_unit(c.file.params[static_cast<std::size_t>(h.index)].quantity)
                                    : host::display_unit(c.file.inputs[static_cast<std::size_t>(h.index)].quantity,
                                                         c.file.inputs[static_cast<std::size_t>(h.index)].unit);
    return fmt::format("{} {}, {}", base, d.text(v0 * f.factor), percent(f.factor, f.lo, f.hi));
  }
};

FaultFitDiagnosis::FaultFitDiagnosis(const LoadedCircuit& c, const Model& model, unsigned measured, bool record)
    : impl_(std::make_unique<Impl>(c)) {
  Impl& m = *impl_;
  for (std::size_t k = 0; k < c.file.params.size(); ++k) {
    if (moves_steady_state(c.file.params[k])) m.add(HypothesisKind::kParam, static_cast<int>(k), c.file.params[k].name, c.values.params.v[k]);
  }
  for (std::size_t i = 0; i < c.file.inputs.size(); ++i) {
    if (c.values.inputs.v[i] != 0.0) m.add(HypothesisKind::kInput, static_cast<int>(i), c.file.inputs[i].name, c.values.inputs.v[i]);
  }
  double sigma[Model::kOutputs] = {};
  for (std::size_t ch = 0; ch < c.file.sensors.size() && ch < static_cast<std::size_t>(Model::kOutputs); ++ch) {
    sigma[ch] = sensor_sigma(c.file.sensors[ch]);
    if (((measured >> ch) & 1u) != 0) m.add(HypothesisKind::kSensor, static_cast<int>(ch), c.file.sensors[ch].name, 0.0);
  }
  Estimator::Config cfg;
  m.ok = m.est.configure(model, m.hyps.data(), static_cast<int>(m.hyps.size()), sigma, measured, circuit_uncertainty(c), cfg);
  m.step.configure(sigma, measured, StepDetector::Config{});
  HealthyRecord::Config rc;
  rc.on = record;
  m.record = std::make_unique<HealthyRecord>(model, circuit_uncertainty(c), sigma, measured, rc);
}

FaultFitDiagnosis::~FaultFitDiagnosis() = default;

void FaultFitDiagnosis::emit(host::ReplayEvent e, std::vector<host::ReplayEvent>& out) {
  status_ = e.event == "cleared" ? "nominal" : e.event;
  out.push_back(std::move(e));
}

void FaultFitDiagnosis::on_matcher_event(const host::ReplayEvent& e, double t, const Model::Inputs& u, bool sensor_flag,
                                         std::vector<host::ReplayEvent>& out) {
  Estimator& est = impl_->est;
  if (e.event == "detected") {
    if (active_) return;  // our episode goes on: the matcher cleared while the fault persisted
    start_episode(t, u);
    emit(e, out);
    return;
  }
  if (e.event == "cleared") {
    if (!active_) return;
    // Withheld until a steady window has judged it (a matcher clear follows an input
    // change, where the bound jumps), and while the windows say a fault is there.
    if (!sensor_lock_ && impl_->ok && !gone()) return;
    end_episode(t);
    emit(e, out);
    return;
  }
  // isolated / ambiguous / unexplained: the matcher's word stands for a sensor flag, and
  // until the estimator has a window that shows the fault.
  if (sensor_flag) sensor_lock_ = true;
  if (sensor_lock_ || est.verdict() == EstimateVerdict::kNone || est.verdict() == EstimateVerdict::kUnsteady) {
    last_key_.clear();
    emit(e, out);
  }
}

// The evidence says the fault has gone: no fault fits the episode's windows better than none,
// the latest of them at the inputs where the fault was detected, and there the readings are
// back where they were before it (a step found at held inputs is measured against that
// baseline, not against the bound, and so is its going). Elsewhere a fault may just not show
// (a wider model bound there, or a fault that acts less): a pump-curve fault seen at one valve
// opening hides inside the bound at the next, and stays.
bool FaultFitDiagnosis::gone() const {
  const Impl& m = *impl_;
  if (m.est.verdict() != EstimateVerdict::kNoFault) return false;
  if (!m.seen_held) return true;
  return inputs_within(m.u_seen, m.est.decided_at(), 1e-4) && m.est.back_to_baseline();
}

// The episode ends at t (cleared): its windows held the fault, so the record of the
// machine before the next one starts here.
void FaultFitDiagnosis::end_episode(double t) {
  active_ = false;
  impl_->holding = false;
  impl_->est.reset();
  impl_->est.forget_past(t);
  last_key_.clear();
}

// An episode from t: the estimator's windows start after a settle, and if the inputs have
// held still since before the step detector's reference, those readings are its baseline.
void FaultFitDiagnosis::start_episode(double t, const Model::Inputs& u, double settled_for) {
  Impl& m = *impl_;
  active_ = true;
  sensor_lock_ = false;
  last_key_.clear();
  if (!m.ok) return;
  m.est.start(t, u, settled_for);
  // Inputs held for kHeldBeforeDetection name the point where the fault showed; inputs
  // that moved until then (a ramp, a measured input that scatters) name none.
  m.seen_held = m.holding && inputs_within(m.u_hold, u, 1e-4) && t - m.t_hold >= kHeldBeforeDetection;
  m.u_seen = u;
  double offset[Model::kOutputs] = {}, var[Model::kOutputs] = {};
  const unsigned have = m.holding ? m.step.reference(offset, var) : 0u;
  if (have != 0) {
    m.est.set_baseline(m.u_hold, offset, var, have);
  } else if (m.holding && inputs_within(m.u_hold, u, 1e-4)) {
    // No reading at these inputs before the fault: the healthy record's prediction of them.
    const unsigned expected = m.record->predicted(offset, var);
    if (expected != 0) m.est.set_expected(m.u_hold, offset, var, expected);
  }
  m.u_expected = u;
  m.t_expected = t;
  m.expected_done = true;
  m.record->drop();
}

// During an episode, at each new hold of the inputs: the healthy record's prediction of the
// readings there, so that the estimator's window at them measures the change since.
void FaultFitDiagnosis::expect(double t, const Model::Inputs& u) {
  Impl& m = *impl_;
  if (!inputs_within(m.u_expected, u, 1e-4)) {
    m.u_expected = u;
    m.t_expected = t;
    m.expected_done = false;
  }
  if (m.expected_done || t - m.t_expected < kHeldBeforeDetection) return;
  m.expected_done = true;
  double mean[Model::kOutputs] = {}, var[Model::kOutputs] = {};
  const unsigned have = m.record->expected_at(u, mean, var);
  if (have != 0) m.est.set_expected(u, mean, var, have);
}

// While no episode runs: a step in the residuals at held inputs starts one. (The
// residuals, not the readings: after a start from rest the readings creep towards their
// steady state for seconds, and the model's creep follows theirs.)
void FaultFitDiagnosis::watch(const Row& row, const Model::Inputs& u, std::vector<host::ReplayEvent>& out) {
  Impl& m = *impl_;
  const double t = row.t;
  // Held means held: near a valve's kink a machine 2 % off the model answers a 0.7 %
  // speed change by bars where the model moves by nothing. So any input change beyond
  // 1e-4 of its value ends the hold (a measured input that scatters more keeps this
  // detector off; the matcher still watches).
  bool same = m.holding && inputs_within(m.u_hold, u, 1e-4);
  // The model may still move at held inputs (a slow mode the settle time did not cover);
  // the machine's own move may then differ from the model's by as much. So the hold also
  // ends when the model's output leaves its settled value by the detector's share of the
  // bound.
  if (same && t >= m.t_settled && row.y_hat != nullptr && row.bound != nullptr) {
    if (m.y_hat_held.empty()) {
      m.y_hat_held.assign(row.y_hat, row.y_hat + m.c.file.sensors.size());
    } else {
      const double share = m.step.config().k_bound;
      for (std::size_t ch = 0; same && ch < m.y_hat_held.size(); ++ch) {
        same = std::fabs(row.y_hat[ch] - m.y_hat_held[ch]) <= share * std::fabs(row.bound[ch]);
      }
    }
  }
  if (!same) {
    m.u_hold = u;
    m.holding = true;
    m.t_hold = t;
    m.t_settled = t + m.est.settle_time(u);
    m.y_hat_held.clear();
    m.step.hold(m.t_settled);
    m.record->begin(u, m.t_settled);
  }
  const unsigned valid = row.r_valid & row.valid;
  host::ReplayEvent e;
  e.t = t;
  e.event = "detected";
  if (m.step.add(t, row.r, valid, row.bound)) {
    std::string where;
    for (std::size_t ch = 0; ch < m.c.file.sensors.size(); ++ch) {
      if (((m.step.step_mask() >> ch) & 1u) != 0) where += (where.empty() ? "" : ", ") + m.c.file.sensors[ch].name;
    }
    e.why = "a step in " + where + " while the inputs held still";
    // The detector has seen its recent blocks after the step: the machine has settled for
    // that long already (a detection just before an input change still gets its window).
    start_episode(t, u, m.step.recent_span());
    emit(std::move(e), out);
    return;
  }
  if (m.record->add(t, row.y, row.valid)) {
    e.why = fmt::format(
        "the readings at these inputs are not what the machine's {} healthy steady window(s) "
        "predict here (chi2 {:.0f} over {} channels)",
        m.record->windows(), m.record->chi2(), m.record->dof());
    start_episode(t, u, m.record->settled_for(t));
    emit(std::move(e), out);
  }
}

void FaultFitDiagnosis::on_row(const Row& row, const Model::Inputs& u, std::vector<host::ReplayEvent>& out) {
  if (!impl_->ok) return;
  if (row.steady_y != nullptr && row.bound_u != nullptr && row.bound != nullptr &&
      !impl_->est.offers_nominal(*row.bound_u)) {
    impl_->est.offer_nominal(*row.bound_u, row.steady_y, row.bound);
  }
  if (!active_) {
    impl_->est.observe(row.t, u, row.r, row.r_valid & row.valid);
    watch(row, u, out);
    return;
  }
  if (sensor_lock_) return;
  const double t = row.t;
  expect(t, u);
  if (!impl_->est.add(t, u, row.y, row.valid)) return;
  if (gone() && row.matcher_quiet) {
    // No fault fits better than none where the fault showed, and the residuals are quiet.
    host::ReplayEvent e;
    e.t = t;
    e.event = "cleared";
    end_episode(t);
    emit(std::move(e), out);
    return;
  }
  decide(t, out);
}

void FaultFitDiagnosis::finish(double t, std::vector<host::ReplayEvent>& out) {
  if (!active_ || !impl_->ok || sensor_lock_) return;
  if (impl_->est.finish()) decide(t, out);
}

void FaultFitDiagnosis::decide(double t, std::vector<host::ReplayEvent>& out) {
  const Estimator& est = impl_->est;
  host::ReplayEvent e;
  e.t = t;
  switch (est.verdict()) {
    case EstimateVerdict::kIsolated: e.event = "isolated"; break;
    case EstimateVerdict::kAmbiguous: e.event = "ambiguous"; break;
    case EstimateVerdict::kUnexplained: e.event = "unexplained"; break;
    default: return;  // no window yet, or none says a fault: the last verdict stands
  }
  // Every hypothesis that fits the windows is listed; `consistent` counts those the timing
  // does not rule out too (an isolation by timing lists its rivals after it, weighed down).
  const int shown = e.event == "unexplained" ? std::min(3, est.ranked()) : est.consistent();
  e.consistent = e.event == "unexplained" ? 0 : est.supported();
  std::string key = e.event;
  for (int r = 0; r < shown; ++r) {
    const HypothesisFit<double>& f = est.fit(r);
    host::ReplayCandidate cand;
    cand.fault = f.name;
    // Relative likelihood of the hypothesis against the best one (with its onset's, when weighed).
    cand.score = est.weight(r);
    cand.size = f.factor;
    cand.size_lo = f.lo;
    cand.size_hi = f.hi;
    cand.size_text = impl_->size_text(f);
    key += "," + cand.fault;
    e.candidates.push_back(std::move(cand));
  }
  e.why = same_fit_classes(est, shown);
  if (est.isolated_by_timing()) e.why = timing_reason(est) + (e.why.empty() ? "" : "; " + e.why);
  if (key == last_key_) return;
  last_key_ = key;
  emit(std::move(e), out);
}

std::vector<std::string> FaultFitDiagnosis::notes() const {
  std::vector<std::string> n;
  if (!impl_->ok) n.push_back("fault identification off: no hypotheses");
  return n;
}

}  // namespace hstmon::circuit_tools
