#pragma once
/// @file effects.hpp
/// Library of unmodelled effects for the thesis HST model, and the host-side simulator of
/// an *extended* model: the thesis model (equations 2.5–2.8, DCV side quasi-steady; on the
/// engine or its hand-written specialisation, ThesisImpl) plus any set of switchable
/// effects, each with a few parameters.
/// docs/gap.md gives the equations of every effect.
///
/// Public types are std::vector based (lib/ defines EIGEN_NO_MALLOC for its users).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hstmon/circuit/thesis_impl.hpp"
#include "hstmon/thesis_params.hpp"

namespace hstmon::gap {

/// The effects of the library.
enum class Effect : int {
  kCoulombFriction = 0,   ///< Coulomb (+ optional Stribeck) torque on the shaft
  kPressureTorqueLoss,    ///< torque loss ∝ motor pressure difference (mechanical efficiency)
  kMotorLeakage,          ///< realistic internal (cross-port) + external motor leakage
  kPrvCracking,           ///< PRV passes flow only above a cracking pressure
  kSupplyFlowLimit,       ///< pump B: finite pressure-compensated flow (hstmon::PumpCurve)
  kAirEntrainment,        ///< pressure-dependent effective bulk modulus of the Ppp volume
  kSensorLag,             ///< first-order lag on the pressure channels
  kSensorOffset,          ///< constant offset on one channel (which one is fitted)
};
inline constexpr int kEffectCount = 8;

/// One parameter of an effect. The fitter works on x = value / scale.
struct ParamInfo {
  std::string name;   ///< key in JSON ("tc")
  std::string unit;   ///< SI unit ("N*m")
  double scale;       ///< typical magnitude [unit]
  double init;        ///< start value of a fit [unit]
  bool positive;      ///< the model uses |value|
};

/// Static description of an effect.
struct EffectInfo {
  Effect id;
  std::string name;          ///< "coulomb_friction"
  std::string description;   ///< one line
  std::vector<ParamInfo> params;
  /// Time scale [s] below which the effect only shows in transients; 0 = visible in steady
  /// state. With a sample period much longer than this the data cannot identify it.
  double transient_time_scale;
};

/// Description of effect e.
const EffectInfo& effect_info(Effect e);
/// All effects, in library order.
const std::vector<Effect>& all_effects();
/// Effect with this name, if any.
std::optional<Effect> effect_from_name(std::string_view name);

/// Channels of the thesis rig (same order as hstmon::ThesisChannel).
inline constexpr int kChannels = 4;
/// Canonical column names of the channels ("p_mi", "p_mo", "p_pp", "w_m").
const std::array<const char*, kChannels>& channel_names();

/// One active effect with its parameter values (SI, order as effect_info(id).params).
/// `channel` selects the channel of kSensorOffset (0 p_mi, 1 p_mo, 2 p_pp, 3 w_m).
struct ActiveEffect {
  Effect id = Effect::kCoulombFriction;
  std::vector<double> values;
  int channel = 2;
};

/// Active effect with its default (start) parameter values.
ActiveEffect default_effect(Effect e, int channel = 2);

/// Terms outside the library, for truth logs only (tests of discovery): the analysis never
/// fits them.
struct TruthExtras {
  double g_pp = 0;     ///< leakage conductance from the loading-pump node to drain [m³/(s·Pa)]
  double windage = 0;  ///< shaft torque −windage·ωm·|ωm| [N·m·s²/rad²]
};

/// What a term of a balance equation may depend on (SI), at one instant.
struct TermInputs {
  double Pmi = 0, Pmo = 0, Ppp = 0, w = 0;  ///< outputs
  double dPpp = 0, dw = 0;                  ///< state derivatives (used by `derivative` terms only)
  double t = 0;                             ///< time since the log's first row [s]
  double Psupl = 0, Ps = 0, Pbp = 0, kp = 0;
};

/// A term added to a balance equation's imbalance (discovery, docs/gap.md): the model's
/// imbalance of `equation` (kEqFlowPp = 2 or kEqTorque = 3) becomes Σ coefficient·value.
/// `derivative` terms multiply the equation's own state derivative (value unused).
struct ImbalanceTerm {
  int equation = 2;
  double coefficient = 0;
  std::function<double(const TermInputs&)> value;
  bool derivative = false;
};

/// The extended model: nominal thesis parameters + active effects.
struct ExtendedModel {
  ThesisParams<double> nominal{};
  std::vector<ActiveEffect> effects;
  TruthExtras extras{};
  std::vector<ImbalanceTerm> terms;  ///< discovered terms (state equations only)
};

/// How simulate() chooses its initial state.
enum class StartRule : int {
  kFirstSample = 0,  ///< from the first measured sample by hstmon::choose_initial_state (replay's rule)
  kRest,             ///< at rest (truth logs of a start-up)
  kSteady,           ///< at the steady state of the first row with the effects (truth logs)
};

/// Inputs per log row, held until the next row (zero-order hold), and what the first row
/// measured. SI.
struct InputSeries {
  std::vector<double> t, Psupl, Ps, Pbp, kp;
  std::array<double, kChannels> y0{};  ///< first measured sample (Pmi, Pmo, Ppp [Pa], ωm [rad/s])
  std::uint8_t y0_valid = 0;           ///< bit c set: channel c of y0 was measured
  StartRule start = StartRule::kFirstSample;
  /// Where in the interval before a row whose inputs step the step takes effect, as a
  /// fraction of the interval back from that row: 0 = at the row (the row shows the new
  /// setting, its outputs not yet moved), 1 = at the row before (the row before still shows
  /// the old setting). run_gap estimates it per log from the nominal run.
  double step_lead = 0;
  std::size_t size() const noexcept { return t.size(); }
};

/// True when the inputs step between rows k − 1 and k (a change beyond 0.5 % of kp, or of
/// 0.5 % of a pressure, at least 500 Pa): a transient starts there. A slow ramp is no step.
bool input_step(const InputSeries& u, std::size_t k);

/// Settings of simulate().
/// Which implementation of the thesis equations the extended model integrates
/// (SimOptions::thesis). Both are the same equations: test_gap_model holds their rates
/// equal to 1e-9 and a simulate() run with four effects to 8e-7 of each channel's scale.
///  - kSpecialised: the hand-written ThesisReducedModel (lib/thesis_reduced.hpp), whose
///    closed-form DCV solve and O(1) input change make the fits' inner loop about 7× faster
///    than on the engine (the eight blind single-effect searches of test_gap: 31 s against
///    217 s, bench/RESULTS.md). The default.
///  - kEngine: the engine's thesis circuit (ThesisCircuitModel: thesis.json compiled), the
///    model the thesis monitor runs.
using hstmon::ThesisImpl;

struct SimOptions {
  double max_step = 2.5e-4;  ///< largest internal step [s] (ROS2, fixed per log interval)
  double transient_step = 2.5e-5;  ///< step within transient_window of the start or an input change [s]
  double transient_window = 0.025;  ///< [s]
  double preroll = 1.0;      ///< time held at the first row's inputs before t0 [s]
  ThesisImpl thesis = ThesisImpl::kSpecialised;  ///< the thesis equations' implementation
};

/// Outputs sampled at the log rows: y[k] = (Pmi, Pmo, Ppp [Pa], ωm [rad/s]) at t[k].
struct SimResult {
  std::vector<std::array<double, kChannels>> y;
  bool ok = false;
  std::string error;  ///< set when !ok
  std::string start;  ///< how the initial state was chosen: "measured", "rest" or "steady"
};

/// Simulates the extended model open loop through the logged inputs. Starts by u.start:
/// from the first sample (choose_initial_state: measured Ppp and ωm, else rest or steady —
/// an offset fitted on a state channel is taken off its reading), at rest, or at the
/// steady state (nominal steady state + preroll with the effects). Linearly implicit 2-stage Rosenbrock (ROS2, L-stable) with a finite-difference
/// Jacobian on (Ppp, ωm); the step is fixed per log interval, so outputs are smooth in the
/// effect parameters (what a finite-difference Levenberg–Marquardt needs).
SimResult simulate(const ExtendedModel& model, const InputSeries& u, const SimOptions& opt = {});

/// Rates (dPpp/dt, dωm/dt) and, if y is given, true outputs of the extended model at state
/// x = (Ppp, ωm) under inputs u: what simulate() integrates. With no effects this is the
/// thesis model's derivative (the test holds it there, on both implementations).
std::array<double, 2> extended_rates(const ExtendedModel& model, const ThesisInputs<double>& u,
                                     const std::array<double, 2>& x, std::array<double, kChannels>* y = nullptr,
                                     ThesisImpl thesis = ThesisImpl::kSpecialised);

}  // namespace hstmon::gap
