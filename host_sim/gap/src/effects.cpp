/// @file effects.cpp
/// Effect library and the extended-model simulator (see effects.hpp, docs/gap.md).
#include "hstmon_gap/effects.hpp"

#include <algorithm>
#include <cmath>

#include "hstmon/pump_curve.hpp"
#include "hstmon/signed_root.hpp"
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
constexpr int kDcvIterations = 6;        // fixed: outputs stay smooth in the parameters

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
  v.push_back({Effect::kSensorLag, "sensor_lag", "first-order lag tau on p_mi, p_mo, p_pp",
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
};

Ext flatten(const ExtendedModel& m) {
  Ext e;
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

class Rhs {
 public:
  Rhs(const ThesisParams<double>& p, const Ext& e) : p_(p), e_(e) {
    gl_ = 1.0 / p.Rlkg + e.g_lkg;
    gi_ = 1.0 / p.Ripl + e.g_ipl;
    inv_kf_ = 1.0 / p.kf;
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
    const double qm = p_.Dm * w;
    double Psup = r.pump ? pump_pressure(r, qm) : r.Psupl;
    double dp = signed_square(qm * inv_kf_, p_.dp_t_dcv);
    double Pmi = Psup - dp, Pmo = r.Ps + dp;
    for (int i = 0; i < kDcvIterations; ++i) {
      const double q_ipl = (Pmi - Pmo) * gi_;
      const double q_in = qm + Pmi * gl_ + q_ipl;
      const double q_out = qm + q_ipl - Pmo * gl_;
      if (r.pump) Psup = pump_pressure(r, q_in);
      Pmi = Psup - signed_square(q_in * inv_kf_, p_.dp_t_dcv);
      Pmo = r.Ps + signed_square(q_out * inv_kf_, p_.dp_t_dcv);
    }
    double dPprv = x[0] - r.Pbp;
    if (e_.crack) dPprv = softplus(dPprv - e_.p_cr, kCrackWidth) - softplus(-dPprv - e_.p_cr, kCrackWidth);
    const double q_prv = r.kp * signed_root(dPprv, p_.dp_t_prv);
    double K = p_.K;
    if (e_.air) {
      const double pa = std::max(x[0] + kPatm, 1e4);
      K /= 1.0 + e_.xa * (kBeta / (kPolytropic * pa)) * std::pow(kPatm / pa, 1.0 / kPolytropic);
    }
    const double dpm = Pmi - Pmo;
    const double th = std::tanh(w / kStribeckSpeed);
    const double torque = p_.Dm * dpm - (p_.Rf + p_.Rbl) * w - e_.tc * th - e_.eta * p_.Dm * std::fabs(dpm) * th -
                          p_.Dp * (x[0] - r.Pbp);
    f[0] = K * (p_.Dp * w - q_prv);
    f[1] = torque / p_.J;
    if (y != nullptr) {
      y[0] = Pmi;
      y[1] = Pmo;
      y[2] = x[0];
      y[3] = w;
    }
  }

 private:
  ThesisParams<double> p_;
  Ext e_;
  double gl_ = 0, gi_ = 0, inv_kf_ = 0;
};

// One ROS2 step (Verwer et al. 1999; order 2 for any Jacobian approximation, L-stable).
// Returns the true outputs at the start of the step in y0.
bool ros2_step(const Rhs& f, const Row& r, double* x, double h, double* y0) {
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

SimResult simulate(const ExtendedModel& model, const InputSeries& u, const SimOptions& opt) {
  SimResult res;
  const std::size_t n = u.size();
  if (n == 0 || u.Psupl.size() != n || u.Ps.size() != n || u.Pbp.size() != n || u.kp.size() != n) {
    res.error = "input series empty or of unequal length";
    return res;
  }
  if (!ThesisReducedModel<double>::params_valid(model.nominal)) {
    res.error = "invalid nominal parameters";
    return res;
  }
  const Ext e = flatten(model);
  const Rhs f(model.nominal, e);
  auto row_at = [&](std::size_t k) {
    Row r;
    r.Psupl = u.Psupl[k];
    r.Ps = u.Ps[k];
    r.Pbp = u.Pbp[k];
    r.kp = u.kp[k];
    f.set_row(r);
    return r;
  };

  // Start: nominal steady state of the first row, then preroll with the effects.
  Row r = row_at(0);
  ThesisReducedModel<double> nom(model.nominal);
  ThesisInputs<double> in0;
  in0.Psupl = r.Psupl;
  in0.Ps = r.Ps;
  in0.Pbp = r.Pbp;
  in0.kp = r.kp;
  nom.set_inputs(in0);
  ThesisReducedModel<double>::State xs;
  if (!nom.steady_state(xs)) xs = nom.rest_state();
  double x[2] = {xs[0], xs[1]};
  double y[kChannels];
  const double hp = 2e-3;
  for (double t = 0; t < opt.preroll; t += hp) {
    if (!ros2_step(f, r, x, hp, y)) {
      res.error = "simulation failed in the preroll";
      return res;
    }
  }
  double fdummy[2];
  f(r, x, fdummy, y);
  double lag[3] = {y[0], y[1], y[2]};
  const bool use_lag = e.tau > 1e-9;

  res.y.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) r = row_at(k);
    // Output at t_k.
    f(r, x, fdummy, y);
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
    // Fine steps first; in long intervals (slow loggers) the transient has died out after
    // 0.1 s and the L-stable scheme takes 5 ms steps. The schedule depends only on the
    // sample times, so outputs stay smooth in the parameters.
    const double fine = dt > 0.2 ? 0.1 : dt;
    const int m1 = std::max(1, static_cast<int>(std::ceil(fine / opt.max_step - 1e-9)));
    const int m2 = dt > 0.2 ? std::max(1, static_cast<int>(std::ceil((dt - fine) / 5e-3 - 1e-9))) : 0;
    for (int s = 0; s < m1 + m2; ++s) {
      const double h = s < m1 ? fine / m1 : (dt - fine) / m2;
      if (!ros2_step(f, r, x, h, y)) {
        res.error = "simulation failed";
        return res;
      }
      if (use_lag) {
        const double alpha = -std::expm1(-h / e.tau);
        for (int c = 0; c < 3; ++c) lag[c] += alpha * (y[c] - lag[c]);
      }
    }
  }
  res.ok = true;
  return res;
}

}  // namespace hstmon::gap
