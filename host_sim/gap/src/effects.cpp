/// @file effects.cpp
/// Effect library and the extended-model simulator (see effects.hpp, docs/gap.md).
#include "hstmon_gap/effects.hpp"

#include <algorithm>
#include <cmath>

#include "hstmon/initial_state.hpp"
#include "hstmon/pump_curve.hpp"
#include "hstmon/signed_root.hpp"
#include "hstmon/circuit/thesis_circuit_model.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace hstmon::gap {

namespace {

// Fixed constants of the effect equations (docs/gap.md).
constexpr double kStribeckSpeed = 0.5;   // tanh regularisation speed of Coulomb terms [rad/s]
constexpr double kCrackWidth = 2e5;      // softplus width of the PRV cracking knee [Pa]
constexpr double kBeta = 1.5e9;          // bulk modulus of air-free oil [Pa]
constexpr double kPolytropic = 1.4;      // air polytropic index [-]
constexpr double kPatm = 1e5;            // atmosphere [Pa abs]
constexpr double kPumpLeakShare = 0.1;   // pump B loses 10 % of Q0 to leakage at cut-in [-]
constexpr int kSupplyIterations = 6;     // pump-curve/DCV fixed point, fixed: outputs smooth in the parameters

std::vector<EffectInfo> make_infos() {
  std::vector<EffectInfo> v;
  v.push_back({Effect::kCoulombFriction, "coulomb_friction",
               "Coulomb torque Tc*tanh(w/0.5 rad/s) on the motor shaft",
               {{"tc", "N*m", 1.0, 0.2, true}}, 0.0});
  v.push_back({Effect::kPressureTorqueLoss, "pressure_torque_loss",
               "torque loss eta*Dm*|Pmi-Pmo| (mechanical efficiency 1-eta)",
               {{"eta", "1", 0.05, 0.01, true}}, 0.0});
  v.push_back({Effect::kMotorLeakage, "motor_leakage",
               "extra motor leakage: cross-port conductance g_ipl, to-drain conductance g_lkg",
               {{"g_ipl", "m^3/(s*Pa)", 1e-11, 2e-12, true}, {"g_lkg", "m^3/(s*Pa)", 1e-11, 2e-12, true}},
               0.0});
  v.push_back({Effect::kPrvCracking, "prv_cracking",
               "PRV passes kp*sqrt(dP - p_crack) only above the cracking pressure",
               {{"p_crack", "Pa", 1e6, 2e5, true}}, 0.0});
  v.push_back({Effect::kSupplyFlowLimit, "supply_flow_limit",
               "pump B: pressure-compensated curve (PumpCurve) with flow q0 and droop band; dead-head = logged p_sup",
               {{"q0", "m^3/s", 1e-3, 2e-3, true}, {"band", "Pa", 1e6, 3e5, true}}, 0.0});
  v.push_back({Effect::kAirEntrainment, "air_entrainment",
               "effective bulk modulus of the Ppp volume K/(1 + xa*(beta/(n*p))*(p0/p)^(1/n))",
               {{"xa", "1", 0.1, 0.03, true}}, 0.01});
  v.push_back({Effect::kSensorLag, "sensor_lag", "first-order lag tau on the samples of p_mi, p_mo, p_pp",
               {{"tau", "s", 0.01, 0.005, true}}, 0.005});
  v.push_back({Effect::kSensorOffset, "sensor_offset", "constant offset on one channel (fitted channel)",
               {{"offset", "SI", 1e5, 0.0, false}}, 0.0});
  return v;
}

const std::vector<EffectInfo>& infos() {
  static const std::vector<EffectInfo> v = make_infos();
  return v;
}

double softplus(double z, double w) {
  return z > 0 ? z + w * std::log1p(std::exp(-z / w)) : w * std::log1p(std::exp(z / w));
}

// All effects flattened; zero = off.
struct Ext {
  double tc = 0;
  double eta = 0;
  double g_ipl = 0, g_lkg = 0;
  bool crack = false;
  double p_cr = 0;
  bool supply = false;
  double q0 = 0, band = 0;
  bool air = false;
  double xa = 0;
  double tau = 0;
  std::array<double, kChannels> offset{};
  TruthExtras extras{};
  std::vector<ImbalanceTerm> terms;
};

Ext flatten(const ExtendedModel& m) {
  Ext e;
  e.extras = m.extras;
  e.terms = m.terms;
  for (const auto& a : m.effects) {
    const auto& v = a.values;
    auto val = [&](std::size_t i) { return i < v.size() ? v[i] : 0.0; };
    switch (a.id) {
      case Effect::kCoulombFriction: e.tc += std::fabs(val(0)); break;
      case Effect::kPressureTorqueLoss: e.eta += std::fabs(val(0)); break;
      case Effect::kMotorLeakage: e.g_ipl += std::fabs(val(0)); e.g_lkg += std::fabs(val(1)); break;
      case Effect::kPrvCracking: e.crack = true; e.p_cr = std::fabs(val(0)); break;
      case Effect::kSupplyFlowLimit: e.supply = true; e.q0 = std::fabs(val(0)); e.band = std::fabs(val(1)); break;
      case Effect::kAirEntrainment: e.air = true; e.xa = std::fabs(val(0)); break;
      case Effect::kSensorLag: e.tau = std::fabs(val(0)); break;
      case Effect::kSensorOffset:
        if (a.channel >= 0 && a.channel < kChannels) e.offset[static_cast<std::size_t>(a.channel)] += val(0);
        break;
    }
  }
  return e;
}

// Inputs of one log row with what depends only on them.
struct Row {
  double Psupl = 0, Ps = 0, Pbp = 0, kp = 0;
  double t = 0;  // time since the first row, for discovered terms [s]
  bool pump = false;
  PumpCurve<double> curve;
  double q0 = 0, R = 0, q1 = 0, q2 = 0, c = 0, s3 = 0, Pc = 0, Pk = 0;
};

// Supply pressure at which pump B delivers flow q (inverse of the C¹ pump curve).
double pump_pressure(const Row& r, double q) {
  if (q >= r.q1) return r.R * (r.q0 - q);                               // region 1
  if (q >= r.q2) {                                                       // region 2
    const double s1 = -1.0 / r.R;
    const double d = r.q1 - q;                                           // ≥ 0
    return r.Pc + 2.0 * d / (-s1 + std::sqrt(s1 * s1 + 4.0 * r.c * d));
  }
  return r.Pk + (q - r.q2) / r.s3;                                       // region 3 (and beyond)
}

// The extended model's right-hand side: the thesis equations (Model: the engine's
// ThesisCircuitModel, or the hand-written ThesisReducedModel; motor leakage enters through
// their Rlkg, Ripl) plus the effects' terms. Mutable: the model holds the row's inputs.
template <class Model>
class Rhs {
 public:
  Rhs(const ThesisParams<double>& p, const Ext& e) : p_(p), e_(e) {
    ThesisParams<double> q = p;
    q.Rlkg = 1.0 / (1.0 / p.Rlkg + e.g_lkg);
    q.Ripl = 1.0 / (1.0 / p.Ripl + e.g_ipl);
    gl_ = 1.0 / q.Rlkg;
    gi_ = 1.0 / q.Ripl;
    model_.set_params(q);
  }

  void set_row(Row& r) const {
    r.pump = false;
    if (!e_.supply) return;
    PumpCurveParams<double> pc;
    pc.Q0 = std::max(e_.q0, 1e-9);
    pc.Pmax = std::max(r.Psupl, 1e4);
    const double band = std::clamp(e_.band, 1e3, 0.9 * pc.Pmax);
    pc.Pc = pc.Pmax - band;
    pc.Pk = pc.Pmax - 0.25 * band;
    pc.R = pc.Pc / (kPumpLeakShare * pc.Q0);
    if (!r.curve.make(pc)) return;
    r.pump = true;
    r.q0 = pc.Q0;
    r.R = pc.R;
    r.Pc = pc.Pc;
    r.Pk = pc.Pk;
    r.q1 = r.curve.q_cutin();
    r.q2 = r.curve.q_knee();
    r.c = r.curve.parabola();
    r.s3 = r.curve.slope(pc.Pk + 1.0);
  }

  // f = (dPpp/dt, dωm/dt); y = true outputs (Pmi, Pmo, Ppp, ωm).
  void operator()(const Row& r, const double* x, double* f, double* y) const {
    const double w = x[1];
    ThesisInputs<double> in;
    in.Psupl = r.Psupl;
    in.Ps = r.Ps;
    in.Pbp = r.Pbp;
    in.kp = r.kp;
    if (r.pump) {
      // Supply pressure where pump B's curve meets the DCV inlet flow (fixed count:
      // outputs stay smooth in the parameters).
      in.Psupl = pump_pressure(r, p_.Dm * w);
      for (int i = 0; i < kSupplyIterations; ++i) {
        model_.set_inputs(in);
        double Pmi = 0, Pmo = 0;
        model_.dcv_pressures(w, Pmi, Pmo);
        in.Psupl = pump_pressure(r, p_.Dm * w + Pmi * gl_ + (Pmi - Pmo) * gi_);
      }
    }
    if (!(in.Psupl == model_.inputs().Psupl && in.Ps == model_.inputs().Ps && in.Pbp == model_.inputs().Pbp &&
          in.kp == model_.inputs().kp)) {
      model_.set_inputs(in);
    }
    typename Model::Output out;
    const typename Model::State d = model_.derivative(typename Model::State(x[0], w), &out);
    f[0] = d[0];
    f[1] = d[1];
    const double dP = x[0] - r.Pbp;
    if (e_.crack) {
      const double dPeff = softplus(dP - e_.p_cr, kCrackWidth) - softplus(-dP - e_.p_cr, kCrackWidth);
      f[0] += p_.K * r.kp * (signed_root(dP, p_.dp_t_prv) - signed_root(dPeff, p_.dp_t_prv));
    }
    if (e_.air) {
      const double pa = std::max(x[0] + kPatm, 1e4);
      f[0] /= 1.0 + e_.xa * (kBeta / (kPolytropic * pa)) * std::pow(kPatm / pa, 1.0 / kPolytropic);
    }
    if (e_.tc != 0 || e_.eta != 0) {
      const double th = std::tanh(w / kStribeckSpeed);
      f[1] -= (e_.tc * th + e_.eta * p_.Dm * std::fabs(out[kChPmi] - out[kChPmo]) * th) / p_.J;
    }
    if (e_.extras.g_pp != 0) f[0] -= p_.K * e_.extras.g_pp * x[0];
    if (!e_.terms.empty()) add_terms(r, out, f);
    if (e_.extras.windage != 0) f[1] -= e_.extras.windage * w * std::fabs(w) / p_.J;
    if (y != nullptr) {
      for (int c = 0; c < kChannels; ++c) y[c] = out[c];
    }
  }

 private:
  // Discovered terms: imbalance Σ c·φ of the Ppp flow balance or the torque balance;
  // derivative terms scale the compliance or the inertia.
  void add_terms(const Row& r, const typename Model::Output& out, double* f) const {
    TermInputs ti;
    ti.Pmi = out[kChPmi];
    ti.Pmo = out[kChPmo];
    ti.Ppp = out[kChPpp];
    ti.w = out[kChWm];
    ti.t = r.t;
    ti.Psupl = r.Psupl;
    ti.Ps = r.Ps;
    ti.Pbp = r.Pbp;
    ti.kp = r.kp;
    double q = 0, cq = 0, T = 0, cT = 0;
    for (const auto& term : e_.terms) {
      const bool flow = term.equation == 2;
      if (term.derivative) {
        (flow ? cq : cT) += term.coefficient;
      } else if (term.value) {
        (flow ? q : T) += term.coefficient * term.value(ti);
      }
    }
    f[0] = (f[0] - p_.K * q) / (1.0 + p_.K * cq);
    f[1] = (f[1] - T / p_.J) / (1.0 + cT / p_.J);
  }

  ThesisParams<double> p_;
  Ext e_;
  double gl_ = 0, gi_ = 0;
  mutable Model model_;
};

// One ROS2 step (Verwer et al. 1999; order 2 for any Jacobian approximation, L-stable).
// Returns the true outputs at the start of the step in y0.
template <class Model>
bool ros2_step(const Rhs<Model>& f, const Row& r, double* x, double h, double* y0) {
  constexpr double g = 1.0 + 0.70710678118654752;
  double f0[2], fp[2], J[2][2];
  f(r, x, f0, y0);
  for (int j = 0; j < 2; ++j) {
    const double d = 1e-7 * std::max(std::fabs(x[j]), j == 0 ? 1e6 : 10.0);
    double xp[2] = {x[0], x[1]};
    xp[j] += d;
    f(r, xp, fp, nullptr);
    J[0][j] = (fp[0] - f0[0]) / d;
    J[1][j] = (fp[1] - f0[1]) / d;
  }
  const double a = 1.0 - g * h * J[0][0], b = -g * h * J[0][1];
  const double c = -g * h * J[1][0], d = 1.0 - g * h * J[1][1];
  const double det = a * d - b * c;
  if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
  auto solve = [&](const double* rhs, double* k) {
    k[0] = (d * rhs[0] - b * rhs[1]) / det;
    k[1] = (a * rhs[1] - c * rhs[0]) / det;
  };
  double k1[2], k2[2], x1[2], f1[2], rhs2[2];
  solve(f0, k1);
  x1[0] = x[0] + h * k1[0];
  x1[1] = x[1] + h * k1[1];
  f(r, x1, f1, nullptr);
  rhs2[0] = f1[0] - 2.0 * k1[0];
  rhs2[1] = f1[1] - 2.0 * k1[1];
  solve(rhs2, k2);
  x[0] += h * (1.5 * k1[0] + 0.5 * k2[0]);
  x[1] += h * (1.5 * k1[1] + 0.5 * k2[1]);
  return std::isfinite(x[0]) && std::isfinite(x[1]);
}

}  // namespace

const EffectInfo& effect_info(Effect e) { return infos()[static_cast<std::size_t>(e)]; }

const std::vector<Effect>& all_effects() {
  static const std::vector<Effect> v = [] {
    std::vector<Effect> r;
    for (int i = 0; i < kEffectCount; ++i) r.push_back(static_cast<Effect>(i));
    return r;
  }();
  return v;
}

std::optional<Effect> effect_from_name(std::string_view name) {
  for (const auto& i : infos()) {
    if (i.name == name) return i.id;
  }
  return std::nullopt;
}

const std::array<const char*, kChannels>& channel_names() {
  static const std::array<const char*, kChannels> n = {"p_mi", "p_mo", "p_pp", "w_m"};
  return n;
}

ActiveEffect default_effect(Effect e, int channel) {
  ActiveEffect a;
  a.id = e;
  a.channel = channel;
  for (const auto& p : effect_info(e).params) a.values.push_back(p.init);
  return a;
}

bool input_step(const InputSeries& u, std::size_t k) {
  if (k == 0 || k >= u.size()) return false;
  auto moved = [](double a, double b, double floor) {
    return std::fabs(a - b) > std::max(5e-3 * std::max(std::fabs(a), std::fabs(b)), floor);
  };
  return moved(u.kp[k], u.kp[k - 1], 0.0) || moved(u.Psupl[k], u.Psupl[k - 1], 500.0) ||
         moved(u.Ps[k], u.Ps[k - 1], 500.0) || moved(u.Pbp[k], u.Pbp[k - 1], 500.0);
}

namespace {

template <class Model>
SimResult simulate_on(const ExtendedModel& model, const InputSeries& u, const SimOptions& opt) {
  SimResult res;
  const std::size_t n = u.size();
  if (n == 0 || u.Psupl.size() != n || u.Ps.size() != n || u.Pbp.size() != n || u.kp.size() != n) {
    res.error = "input series empty or of unequal length";
    return res;
  }
  if (!Model::params_valid(model.nominal)) {
    res.error = "invalid nominal parameters";
    return res;
  }
  const Ext e = flatten(model);
  const Rhs<Model> f(model.nominal, e);
  auto row_at = [&](std::size_t k) {
    Row r;
    r.Psupl = u.Psupl[k];
    r.Ps = u.Ps[k];
    r.Pbp = u.Pbp[k];
    r.kp = u.kp[k];
    f.set_row(r);
    return r;
  };

  // Start (docs/gap.md): the first sample by the rule replay and identify use, or forced.
  Row r = row_at(0);
  Model nom(model.nominal);
  ThesisInputs<double> in0;
  in0.Psupl = r.Psupl;
  in0.Ps = r.Ps;
  in0.Pbp = r.Pbp;
  in0.kp = r.kp;
  nom.set_inputs(in0);
  typename Model::State xs = nom.rest_state();
  bool preroll = false;
  if (u.start == StartRule::kFirstSample) {
    typename Model::Output ym;
    for (int c = 0; c < kChannels; ++c) ym[c] = u.y0[static_cast<std::size_t>(c)] - e.offset[static_cast<std::size_t>(c)];
    const InitialState kind = choose_initial_state(nom, ym, u.y0_valid, xs);
    res.start = to_string(kind);
    preroll = kind == InitialState::kSteady;
  } else if (u.start == StartRule::kSteady) {
    if (!nom.steady_state(xs)) xs = nom.rest_state();
    res.start = "steady";
    preroll = true;
  } else {
    res.start = "rest";
  }
  double x[2] = {xs[0], xs[1]};
  double y[kChannels];
  const double hp = 2e-3;
  for (double t = 0; preroll && t < opt.preroll; t += hp) {
    if (!ros2_step(f, r, x, hp, y)) {
      res.error = "simulation failed in the preroll";
      return res;
    }
  }
  double fdummy[2];
  f(r, x, fdummy, y);
  double lag[3] = {y[0], y[1], y[2]};
  // A lagged transducer starts from what it read, not from the model's quasi-steady
  // pressures (at a start from rest Pmi is at supply at once, its reading is not).
  for (std::size_t c = 0; c < 3 && u.start == StartRule::kFirstSample; ++c) {
    if ((u.y0_valid >> c) & 1u) lag[c] = u.y0[c] - e.offset[c];
  }
  const bool use_lag = e.tau > 1e-9;

  res.y.resize(n);
  double t_change = u.t[0];
  bool switched_early = false;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) r = row_at(k);
    // Output at t_k.
    f(r, x, fdummy, y);
    if (use_lag && k > 0) {
      // The lag acts on the samples (a logger's first-order filter, exact for a held
      // input): the independent simulator's lagged logs follow this to their noise.
      const double alpha = -std::expm1(-(u.t[k] - u.t[k - 1]) / e.tau);
      for (int c = 0; c < 3; ++c) lag[c] += alpha * (y[c] - lag[c]);
    }
    auto& out = res.y[k];
    for (int c = 0; c < kChannels; ++c) {
      const double v = (use_lag && c < 3) ? lag[c] : y[c];
      out[static_cast<std::size_t>(c)] = v + e.offset[static_cast<std::size_t>(c)];
    }
    if (k + 1 == n) break;
    const double dt = u.t[k + 1] - u.t[k];
    if (!(dt > 0)) {
      res.error = "time not strictly increasing";
      return res;
    }
    // Step schedule: within transient_window of the start or of an input change, steps of
    // transient_step (the Ppp mode's time constant is ≈ 0.2 ms: ROS2 at 0.25 ms is stable
    // but 1 bar off in a kp step); then max_step; in long intervals (slow loggers) the
    // transient has died out after 0.1 s and the L-stable scheme takes 5 ms steps. The
    // schedule depends only on the sample times and inputs, so outputs stay smooth in the
    // parameters.
    if (input_step(u, k) && !(switched_early && k > 0)) t_change = u.t[k];
    switched_early = false;
    // Inputs between rows: a step at the next row takes effect step_lead of the interval
    // before it (loggers differ in whether a row shows the setting before or after a change
    // at its instant); otherwise the inputs are interpolated — a ramp logged row by row,
    // held, would put the model a sample behind.
    const bool slow = dt > 0.2;
    const bool next_step = !slow && input_step(u, k + 1);
    const bool ramp = !slow && !next_step &&
                      (u.kp[k + 1] != u.kp[k] || u.Psupl[k + 1] != u.Psupl[k] || u.Ps[k + 1] != u.Ps[k] ||
                       u.Pbp[k + 1] != u.Pbp[k]);
    const double t_switch = next_step ? (1.0 - std::clamp(u.step_lead, 0.0, 1.0)) * dt : dt;
    // Integrates [from, from + len) of this interval with the current row r.
    auto advance = [&](double from, double len) {
      const double fine = slow ? 0.1 : len;
      const double tr = std::clamp(t_change + opt.transient_window - (u.t[k] + from), 0.0, fine);
      const double seg_len[3] = {tr, fine - tr, len - fine};
      const double seg_step[3] = {std::min(opt.transient_step, opt.max_step), opt.max_step, 5e-3};
      double elapsed = from;
      for (int g = 0; g < 3; ++g) {
        if (seg_len[g] <= 1e-12 * dt) continue;
        const int m = std::max(1, static_cast<int>(std::ceil(seg_len[g] / seg_step[g] - 1e-9)));
        const double h = seg_len[g] / m;
        for (int s = 0; s < m; ++s) {
          r.t = u.t[k] + elapsed - u.t[0];
          if (ramp) {
            const double a = (elapsed + 0.5 * h) / dt;  // midpoint of the step
            r.Psupl = u.Psupl[k] + a * (u.Psupl[k + 1] - u.Psupl[k]);
            r.Ps = u.Ps[k] + a * (u.Ps[k + 1] - u.Ps[k]);
            r.Pbp = u.Pbp[k] + a * (u.Pbp[k + 1] - u.Pbp[k]);
            r.kp = u.kp[k] + a * (u.kp[k + 1] - u.kp[k]);
            f.set_row(r);
          }
          elapsed += h;
          if (!ros2_step(f, r, x, h, y)) return false;
        }
      }
      return true;
    };
    bool ok = advance(0.0, t_switch);
    if (ok && t_switch < dt * (1.0 - 1e-12)) {
      r = row_at(k + 1);
      t_change = u.t[k] + t_switch;
      switched_early = true;
      ok = advance(t_switch, dt - t_switch);
    }
    if (!ok) {
      res.error = "simulation failed";
      return res;
    }
  }
  res.ok = true;
  return res;
}

template <class Model>
std::array<double, 2> extended_rates_on(const ExtendedModel& model, const ThesisInputs<double>& u,
                                        const std::array<double, 2>& x, std::array<double, kChannels>* y) {
  const Rhs<Model> f(model.nominal, flatten(model));
  Row r;
  r.Psupl = u.Psupl;
  r.Ps = u.Ps;
  r.Pbp = u.Pbp;
  r.kp = u.kp;
  f.set_row(r);
  std::array<double, 2> d{};
  double out[kChannels];
  f(r, x.data(), d.data(), out);
  if (y != nullptr) {
    for (std::size_t c = 0; c < kChannels; ++c) (*y)[c] = out[c];
  }
  return d;
}

}  // namespace

SimResult simulate(const ExtendedModel& model, const InputSeries& u, const SimOptions& opt) {
  return opt.thesis == ThesisImpl::kEngine ? simulate_on<ThesisCircuitModel<double>>(model, u, opt)
                                           : simulate_on<ThesisReducedModel<double>>(model, u, opt);
}

std::array<double, 2> extended_rates(const ExtendedModel& model, const ThesisInputs<double>& u,
                                     const std::array<double, 2>& x, std::array<double, kChannels>* y,
                                     ThesisImpl thesis) {
  return thesis == ThesisImpl::kEngine ? extended_rates_on<ThesisCircuitModel<double>>(model, u, x, y)
                                       : extended_rates_on<ThesisReducedModel<double>>(model, u, x, y);
}

}  // namespace hstmon::gap
