#include "hstmon_circuit/circuit_sim.hpp"

#include "hstmon/circuit/stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "hstmon_circuit/circuit_faults.hpp"
#include "hstmon_sensors/sensor_chain.hpp"
#include "hstmon_sim/stiff_integrator.hpp"

namespace hstmon::circuit_tools {

namespace {

using Model = host::HostCircuitModel;

// Two instants closer than this [s] are the same instant (a step on a sample, a row on a step).
constexpr double kSameInstant = 1e-12;

// The rows to write: o.sample_times checked, or start_time + k/rate for k < duration·rate.
std::vector<double> sample_times_of(const CircuitSimOptions& o) {
  if (!(o.duration > 0.0 && std::isfinite(o.duration)) || !(o.rate > 0.0 && std::isfinite(o.rate))) {
    throw std::runtime_error("duration and rate must be > 0");
  }
  if (!std::isfinite(o.start_time)) throw std::runtime_error("the start time must be finite");
  std::vector<double> sample_times = o.sample_times;
  if (sample_times.empty()) {
    if (o.duration * o.rate > 1e7) throw std::runtime_error("more than 10 million samples: lower --duration or --rate");
    const auto samples = static_cast<std::size_t>(std::llround(o.duration * o.rate));
    sample_times.reserve(samples);
    for (std::size_t k = 0; k < samples; ++k) sample_times.push_back(o.start_time + static_cast<double>(k) / o.rate);
    return sample_times;
  }
  if (sample_times.size() > 10000000) throw std::runtime_error("more than 10 million samples: lower --duration");
  for (std::size_t k = 0; k < sample_times.size(); ++k) {
    if (!std::isfinite(sample_times[k]) || sample_times[k] < o.start_time ||
        (k > 0 && !(sample_times[k] > sample_times[k - 1]))) {
      throw std::runtime_error("sample times must rise from the start time");
    }
  }
  return sample_times;
}

// The inputs and parameters over the run: the nominal values, the steps in time order on
// top, and the input profile's rows (an input leaves the profile from its first step on).
// An input fault scales what the machine gets, not what the log records.
class Stimulus {
 public:
  Stimulus(const LoadedCircuit& c, const CircuitSimOptions& o)
      : file_(c.file),
        nominal_(c.values.params),
        prof_(o.profile),
        ramps_(prof_.any() && prof_.hold == InputHold::kLinear && prof_.t.size() >= 2),
        steps_(o.steps),
        n_inputs_(c.file.inputs.size()),
        held_(c.values.inputs),
        follows_(n_inputs_, false),
        fault_(n_inputs_, 1.0),
        params_(c.values.params) {
    if (prof_.any() && !(o.start_time >= prof_.t.front())) {
      throw std::runtime_error("the run starts before the input profile's first row");
    }
    sort_steps(steps_);
    for (std::size_t i = 0; i < n_inputs_; ++i) follows_[i] = prof_.drives(i);
    seg_ = prof_.any() ? prof_.segment(o.start_time) : 0;
    next_row_ = prof_.any() ? seg_ + 1 : prof_.t.size();
    apply_steps_until(o.start_time);
    params_changed_ = false;  // the run starts on them
  }

  // Applies every step at or before t [s].
  void apply_steps_until(double t) {
    while (next_ < steps_.size() && steps_[next_].t <= t + kSameInstant) {
      const InputStep& st = steps_[next_];
      if (st.input_fault) {
        fault_[static_cast<std::size_t>(st.input)] = st.factor;
      } else if (st.param >= 0) {
        apply_param_fault(file_, params_, nominal_, static_cast<std::size_t>(st.param), st.factor);
        params_changed_ = true;
      } else {
        held_.v[st.input] = st.value;
        follows_[static_cast<std::size_t>(st.input)] = false;
      }
      ++next_;
    }
  }
  // Moves to the profile segment of the last row at or before t [s].
  void pass_rows_until(double t) {
    while (next_row_ < prof_.t.size() && prof_.t[next_row_] <= t + kSameInstant) seg_ = next_row_++;
  }
  bool step_due(double t) const { return next_ < steps_.size() && steps_[next_].t <= t + kSameInstant; }
  // The next step or profile row [s], each a hard stop of the integration; infinity: none.
  double next_break() const {
    double b = INFINITY;
    if (next_ < steps_.size()) b = steps_[next_].t;
    if (next_row_ < prof_.t.size()) b = std::min(b, prof_.t[next_row_]);
    return b;
  }
  // The inputs the log records at time t [s] in the current segment.
  Model::Inputs logged_at(double t) const {
    Model::Inputs u = held_;
    for (std::size_t i = 0; i < n_inputs_; ++i) {
      if (follows_[i]) u.v[i] = prof_.value(i, t, seg_);
    }
    return u;
  }
  // The inputs the machine gets at time t [s]: the logged ones, input faults applied.
  Model::Inputs inputs_at(double t) const {
    Model::Inputs u = logged_at(t);
    for (std::size_t i = 0; i < n_inputs_; ++i) u.v[i] *= fault_[i];
    return u;
  }
  // The current segment's slopes of the machine's inputs [unit/s]; zero where an input
  // does not follow the profile.
  std::vector<double> slopes() const {
    std::vector<double> s(n_inputs_, 0.0);
    for (std::size_t i = 0; i < n_inputs_; ++i) {
      if (follows_[i]) s[i] = prof_.slope(i, seg_) * fault_[i];
    }
    return s;
  }
  // The current segment's length [s]; 1 for the last.
  double segment_length() const { return seg_ + 1 < prof_.t.size() ? prof_.t[seg_ + 1] - prof_.t[seg_] : 1.0; }
  // True once: the parameters changed since the last call.
  bool take_params_changed() {
    const bool changed = params_changed_;
    params_changed_ = false;
    return changed;
  }

  bool ramps() const { return ramps_; }
  std::size_t n_inputs() const { return n_inputs_; }
  const Model::Params& params() const { return params_; }

 private:
  const host::CircuitFile& file_;
  const Model::Params& nominal_;
  const InputProfile& prof_;
  bool ramps_;  // linear profile: inputs ramp between rows
  std::vector<InputStep> steps_;
  std::size_t n_inputs_;
  Model::Inputs held_;  // nominal, then stepped; the profile's inputs on top
  std::vector<bool> follows_;
  std::vector<double> fault_;  // input faults: the machine's input over the logged one [-]
  Model::Params params_;
  bool params_changed_ = false;
  std::size_t next_ = 0;  // the next step
  std::size_t seg_ = 0;   // the profile's current segment
  std::size_t next_row_ = 0;
};

// What a transducer sees at a sample that falls on a step: no transducer follows the
// microseconds in which the volumes far faster than the sampling settle (a flow
// reversing through a valve the instant its supply drops). At such a sample those
// volumes (the ones an observer at this period takes quasi-steady) are read at their
// settled pressures, the other states as they are.
class SettledReadout {
 public:
  SettledReadout(const LoadedCircuit& c, const Model& full, const Model::Params& p, const Model::Inputs& u,
                 double period)
      : desc_(c.file.circuit) {
    desc_.stiff_mask = circuit::auto_stiff_mask<double>(desc_, p, u, period);
    if (desc_.stiff_mask == 0) return;
    model_.emplace(desc_, p, u);
    if (model_->error() != circuit::CircuitError::kOk || !model_->valid()) {
      model_.reset();
      return;
    }
    for (int j = 0; j < model_->n_states(); ++j) {
      for (int s = 0; s < full.n_states(); ++s) {
        if (full.state_z(s) == model_->state_z(j)) from_full_.push_back(s);
      }
    }
  }
  SettledReadout(const SettledReadout&) = delete;  // the model points at desc_
  SettledReadout& operator=(const SettledReadout&) = delete;
  bool usable() const { return model_ && static_cast<int>(from_full_.size()) == model_->n_states(); }
  // The outputs with the fast volumes settled; x: the full model's state.
  Model::Output outputs(const Model::Params& p, const Model::Inputs& u, const std::vector<double>& x) {
    model_->set_params(p);
    model_->set_inputs(u);
    Model::State xs = Model::State::Zero();
    for (std::size_t j = 0; j < from_full_.size(); ++j) {
      xs[static_cast<int>(j)] = x[static_cast<std::size_t>(from_full_[j])];
    }
    return model_->outputs(xs);
  }

 private:
  host::HostCircuit desc_;  // the circuit with the fast volumes quasi-steady
  std::optional<Model> model_;
  std::vector<int> from_full_;  // full-model state index of each settled-model state
};

// The full equations: every volume a state.
host::HostCircuit full_equations(const host::HostCircuit& circuit) {
  host::HostCircuit desc = circuit;
  desc.stiff_mask = 0;
  return desc;
}

// The circuit's full equations integrated through the stimulus. With ramping inputs the
// integrated state has one more entry: the time since the segment's anchor, tau
// (dtau/dt = 1), the inputs u_anchor + tau·slope.
class Trajectory {
 public:
  Trajectory(const LoadedCircuit& c, const CircuitSimOptions& o, Stimulus& stim)
      : stim_(stim),
        u_(stim.inputs_at(o.start_time)),
        desc_(full_equations(c.file.circuit)),
        full_(desc_, stim.params(), u_),
        n_(full_.n_states()),
        m_(stim.ramps() ? n_ + 1 : n_),
        t0_(o.start_time) {
    if (full_.error() != circuit::CircuitError::kOk || !full_.valid()) {
      throw std::runtime_error("circuit " + c.file.name + ": the values do not make a physical circuit");
    }
    Model::State x0 = full_.rest_state();
    if (!o.from_rest && !full_.steady_state(x0)) {
      throw std::runtime_error("circuit " + c.file.name +
                               ": no steady state for the inputs at the start (try --start rest)");
    }
    settled_.emplace(c, full_, stim.params(), u_, 1.0 / o.rate);
    std::vector<double> abs_tol(static_cast<std::size_t>(m_));
    for (int s = 0; s < n_; ++s) {
      abs_tol[static_cast<std::size_t>(s)] = full_.state_z(s) < Model::kNodes ? 1e-7 * full_.pressure_envelope()
                                                                              : 1e-7 * full_.speed_envelope();
    }
    if (stim.ramps()) abs_tol[static_cast<std::size_t>(n_)] = 1e-9;
    x_.assign(x0.data(), x0.data() + n_);
    if (stim.ramps()) x_.push_back(0.0);
    if (n_ > 0) ref_.emplace(abs_tol, 1e-9, 1e-7);
    anchor_ = u_;
    restart(0.0);
  }
  Trajectory(const Trajectory&) = delete;  // the integrator's functions point at this, the model at desc_
  Trajectory& operator=(const Trajectory&) = delete;

  // Integrates to the sample at ts [s] on the run's clock, meeting every step and profile
  // row on the way, and returns the outputs there.
  Model::Output sample(double ts) {
    const bool stepped_here = cross_breaks_until(ts);
    advance_to(ts);
    u_ = stim_.inputs_at(ts);
    full_.set_inputs(u_);
    Model::Output y = full_.outputs(to_state(x_.data()));
    if (stepped_here && settled_->usable()) y = settled_->outputs(stim_.params(), u_, x_);
    return y;
  }

 private:
  // Each step and row up to ts [s], met exactly by a hard stop; true if one is a jump at ts.
  bool cross_breaks_until(double ts) {
    bool stepped_here = false;
    for (double tb = stim_.next_break(); tb <= ts + kSameInstant; tb = stim_.next_break()) {
      advance_to(tb);
      const double t_now = ref_ ? ref_->time() : tb - t0_;
      bool jump = false;
      if (stim_.step_due(tb)) {
        stim_.apply_steps_until(tb);
        jump = true;
      }
      const std::vector<double> slope_before = stim_.ramps() ? stim_.slopes() : std::vector<double>{};
      const Model::Inputs before = stim_.inputs_at(tb);
      stim_.pass_rows_until(tb);
      u_ = stim_.inputs_at(tb);
      // A row where no input's value (step profile) or slope (linear) changes needs no
      // restart; a linear profile's value is continuous at a row.
      bool changed = false;
      for (std::size_t i = 0; i < stim_.n_inputs() && !stim_.ramps() && !changed; ++i) changed = u_.v[i] != before.v[i];
      jump = jump || changed;
      if (jump || (stim_.ramps() && stim_.slopes() != slope_before)) restart(t_now, !jump);
      stepped_here = stepped_here || (jump && std::fabs(tb - ts) <= kSameInstant);
    }
    return stepped_here;
  }
  // Integrates to t [s] on the run's clock (when later than the integrator's time).
  // The integrator's clock starts at 0: a log's clock may be far from it (a logger's Unix
  // time, 1.7e9 s, resolves only 2e-7 s), the time since the start never is.
  void advance_to(double t) {
    if (!ref_) return;
    if (t - t0_ > ref_->time()) ref_->advance_to(t - t0_);
    x_ = ref_->state();
  }
  Model::State to_state(const double* xs) const {
    Model::State s = Model::State::Zero();
    for (int i = 0; i < n_; ++i) s[i] = xs[i];
    return s;
  }
  Model::Inputs ramped(double tau) const {
    Model::Inputs v = anchor_;
    for (std::size_t i = 0; i < stim_.n_inputs(); ++i) v.v[i] += tau * slope_[i];
    return v;
  }
  // Restarts the integrator at t [s] since the start on the current inputs and parameters.
  // kink: the inputs meet the last segment's without a jump (a linear profile's row), so
  // the integrator goes on at its last step rather than from the first trial step.
  void restart(double t, bool kink = false) {
    if (stim_.take_params_changed()) full_.set_params(stim_.params());
    full_.set_inputs(u_);
    if (!ref_) return;
    if (!stim_.ramps()) {
      ref_->restart(
          t, x_.data(), [this](const double* xs, double* dx) { derivative(xs, dx); },
          [this](const double* xs, double* jac) { jacobian(xs, jac); });
      return;
    }
    anchor_ = u_;
    slope_ = stim_.slopes();
    sloped_ = std::any_of(slope_.begin(), slope_.end(), [](double v) { return v != 0.0; });
    seg_length_ = stim_.segment_length();
    x_[static_cast<std::size_t>(n_)] = 0.0;
    auto rhs = [this](const double* xs, double* dx) { ramp_derivative(xs, dx); };
    auto jac = [this](const double* xs, double* j) { ramp_jacobian(xs, j); };
    if (kink) {
      ref_->restart(t, x_.data(), rhs, jac, ref_->next_step());
    } else {
      ref_->restart(t, x_.data(), rhs, jac);
    }
  }
  void derivative(const double* xs, double* dx) {
    const Model::State d = full_.derivative(to_state(xs));
    for (int i = 0; i < n_; ++i) dx[i] = d[i];
  }
  void jacobian(const double* xs, double* jac) {
    Model::StateMatrix J;
    full_.jacobian(to_state(xs), J);
    for (int r = 0; r < n_; ++r) {
      for (int k = 0; k < n_; ++k) jac[r * n_ + k] = J(r, k);
    }
  }
  void ramp_derivative(const double* xs, double* dx) {
    if (sloped_) full_.set_inputs(ramped(xs[n_]));
    const Model::State d = full_.derivative(to_state(xs));
    for (int i = 0; i < n_; ++i) dx[i] = d[i];
    dx[n_] = 1.0;
  }
  void ramp_jacobian(const double* xs, double* jac) {
    const Model::State xs_state = to_state(xs);
    if (sloped_) full_.set_inputs(ramped(xs[n_]));
    Model::StateMatrix J;
    full_.jacobian(xs_state, J);
    for (int r = 0; r < m_; ++r) {
      for (int k = 0; k < m_; ++k) jac[r * m_ + k] = r < n_ && k < n_ ? J(r, k) : 0.0;
    }
    if (!sloped_) return;
    // d f / d tau = (d f / d u)·slope, by a forward difference along the ramp.
    const double h = 1e-6 * seg_length_;
    const Model::State f0 = full_.derivative(xs_state);
    full_.set_inputs(ramped(xs[n_] + h));
    const Model::State f1 = full_.derivative(xs_state);
    for (int r = 0; r < n_; ++r) jac[r * m_ + n_] = (f1[r] - f0[r]) / h;
  }

  Stimulus& stim_;
  Model::Inputs u_;         // the inputs now
  host::HostCircuit desc_;  // the full equations' circuit, which full_ points at
  Model full_;
  int n_;      // the model's states
  int m_;      // integrated states: n_, one more (tau) with ramps
  double t0_;  // the run's clock at the start [s]
  std::optional<SettledReadout> settled_;
  std::vector<double> x_;
  std::optional<sim::StiffIntegrator> ref_;
  // The current segment's anchor inputs and slopes (ramps only).
  Model::Inputs anchor_;
  std::vector<double> slope_;
  double seg_length_ = 1.0;
  bool sloped_ = false;
};

// The sensor chain: the options' channels (a logger set-up) or the sensors section's white
// noise and range clipping with the transducers' lag and ADC (when asked); noise off when
// not asked for.
std::vector<sim::ChannelSpec> channel_specs(const LoadedCircuit& c, bool noise, const TransducerOptions& t,
                                            const std::vector<sim::ChannelSpec>& given) {
  if (!(t.lag >= 0.0) || !(t.pressure_step >= 0.0) || t.pressure_adc_bits < 0 || t.pressure_adc_bits > 52) {
    throw std::runtime_error("transducers: the lag and the pressure step are >= 0, the pressure ADC has 1 to 52 bits");
  }
  if (!given.empty()) {
    if (given.size() != c.file.sensors.size()) {
      throw std::runtime_error("the sensor set-up has " + std::to_string(given.size()) + " channels, circuit " +
                               c.file.name + " " + std::to_string(c.file.sensors.size()) + " sensors");
    }
    std::vector<sim::ChannelSpec> specs = given;
    if (!noise) {
      for (sim::ChannelSpec& ch : specs) ch.noise_std = 0.0;
    }
    return specs;
  }
  std::vector<sim::ChannelSpec> specs;
  for (const host::CircuitSensor& s : c.file.sensors) {
    sim::ChannelSpec ch;
    ch.name = s.name;
    ch.noise_std = noise ? s.noise : 0.0;
    ch.range_lo = s.lo;
    ch.range_hi = s.hi;
    ch.tau = t.lag;
    const bool ranged = std::isfinite(s.lo) && std::isfinite(s.hi) && s.hi > s.lo;
    if (s.quantity == host::CircuitQuantity::kPressure) {  // speed and flow: counters and meters, not an ADC
      if (t.pressure_adc_bits == 0) {
        ch.quant_step = t.pressure_step;
      } else if (ranged) {
        ch.quant_step = sim::adc_step(s.lo, s.hi, t.pressure_adc_bits);
      }
    }
    specs.push_back(ch);
  }
  return specs;
}

}  // namespace

CircuitLog simulate_circuit(const LoadedCircuit& c, const CircuitSimOptions& o) {
  const std::vector<double> sample_times = sample_times_of(o);
  Stimulus stim(c, o);
  Trajectory run(c, o, stim);
  const std::vector<sim::ChannelSpec> specs = channel_specs(c, o.noise, o.transducers, o.channels);
  sim::SensorChain chain(specs, o.seed);
  const std::size_t channels = specs.size();

  CircuitLog log;
  log.path = c.file.name + " (simulated)";
  log.inputs.assign(stim.n_inputs(), {});
  log.sensors.assign(channels, {});
  log.t.reserve(sample_times.size());
  std::vector<double> truth(channels), meas(channels);
  double t_last = o.start_time;
  for (std::size_t k = 0; k < sample_times.size(); ++k) {
    const double ts = sample_times[k];
    const Model::Output y = run.sample(ts);
    for (std::size_t ch = 0; ch < channels; ++ch) truth[ch] = y[static_cast<int>(ch)];
    if (k == 0) {
      chain.reset(truth.data());
    } else {
      chain.advance(truth.data(), ts - t_last);
    }
    chain.measure(meas.data());
    t_last = ts;
    log.t.push_back(ts);
    const Model::Inputs logged = stim.logged_at(ts);
    for (std::size_t i = 0; i < stim.n_inputs(); ++i) log.inputs[i].push_back(logged.v[i]);
    for (std::size_t ch = 0; ch < channels; ++ch) log.sensors[ch].push_back(meas[ch]);
  }
  return log;
}

}  // namespace hstmon::circuit_tools
