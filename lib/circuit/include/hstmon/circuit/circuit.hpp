#pragma once
/// @file circuit.hpp
/// A hydraulic circuit as plain data: nodes, shafts, elements and sensor channels, with
/// every number referred to a parameter or an input by index. The host reader
/// (ports/host circuit_file.hpp) fills one from a JSON file; firmware can hold one as a
/// constexpr object in flash. The description has no scalar type, so one description
/// serves the float and the double model alike. docs/circuits.md gives the laws.

#include <cstdint>

#include "hstmon/circuit/capacity.hpp"

namespace hstmon::circuit {

/// Where a number comes from.
enum class RefKind : std::uint8_t {
  kNone = 0,   ///< not given: the field's documented default
  kParam = 1,  ///< params.v[index], fixed between set_params calls
  kInput = 2,  ///< inputs.v[index], may change every tick
};

/// A reference to a parameter or an input (2 bytes).
struct Ref {
  RefKind kind = RefKind::kNone;
  std::uint8_t index = 0;
};

/// Ref to parameter i.
constexpr Ref param_ref(int i) noexcept { return Ref{RefKind::kParam, static_cast<std::uint8_t>(i)}; }
/// Ref to input i.
constexpr Ref input_ref(int i) noexcept { return Ref{RefKind::kInput, static_cast<std::uint8_t>(i)}; }

/// Kind of a pressure node.
enum class NodeKind : std::uint8_t {
  kVolume = 0,    ///< a fluid volume: a state, or quasi-steady if stiff
  kBoundary = 1,  ///< a held pressure (tank, supply, booster, a pressure source)
};

/// A pressure node. A volume's capacitance is K [Pa/m³] (dP/dt = K·ΣQ, the thesis's
/// form) if K is given, else beta/volume (bulk modulus [Pa] over volume [m³]).
struct Node {
  NodeKind kind = NodeKind::kVolume;
  Ref K{};         ///< volume: bulk stiffness K [Pa/m³]
  Ref beta{};      ///< volume, when K is not given: bulk modulus β [Pa]
  Ref volume{};    ///< volume, when K is not given: volume V [m³]
  Ref pressure{};  ///< boundary: its pressure [Pa, gauge]; default 0
};

/// A rotating shaft: J·dω/dt = Σ torques, or a speed given by an input or parameter.
struct Shaft {
  Ref J{};              ///< inertia [kg·m²] (free shafts)
  Ref speed{};          ///< driven shafts: the speed [rad/s]
  bool driven = false;  ///< true: speed from `speed`, not a state
};

/// Kind of an element. Flows run from port a to port b [m³/s]; torques act on `shaft`.
enum class ElementKind : std::uint8_t {
  kOrifice = 0,     ///< Q = k·opening·sq(pa − pb), sq the regularised signed root
  kLaminar = 1,     ///< Q = (pa − pb)/R
  kFlowSource = 2,  ///< Q = q, whatever the pressures
  kMachine = 3,     ///< pump or motor: Q = ε·D·ω, torque on the shaft ε·D·(pa − pb)
  kCompPump = 4,    ///< pressure-compensated pump: Q = Q_B(pb − pa), the 3-region curve
  kPoppet = 5,      ///< relief or check valve: Q = k·x·sq(pa − pb), x the poppet opening
  kTorque = 6,      ///< a load torque τ on the shaft: torque −τ
  kFriction = 7,    ///< viscous friction c on the shaft: torque −c·ω
};

/// Meaning of Element::r[] per kind (the slot index). Orifice and poppet take their
/// coefficient k [m³/(s·√Pa)] from kK, or else from Cd·A·√(2/ρ) (kArea [m²], kCd [-],
/// kRho [kg/m³]).
enum Slot : int {
  kK = 0, kArea = 1, kCd = 2, kRho = 3,
  kOpening = 4,    ///< orifice: opening [-], default 1, clamped at 0
  kDpT = 5,        ///< orifice, poppet: laminar transition ΔP_t [Pa], default 1e3
  kCrack = 6,      ///< poppet: cracking pressure difference [Pa], default 0
  kFull = 7,       ///< poppet: pressure difference where fully open [Pa], > crack
  kR = 0,          ///< laminar: resistance [Pa·s/m³]
  kQ = 0,          ///< flow source: flow [m³/s]
  kD = 0,          ///< machine: displacement [m³/rad]
  kFraction = 1,   ///< machine: displacement fraction ε [-], default 1
  kQ0 = 0, kRleak = 1, kPc = 2, kPk = 3, kPmax = 4,  ///< compensated pump: PumpCurveParams
  kTau = 0,        ///< torque: τ [N·m]
  kC = 0,          ///< friction: c [N·m·s/rad]
};

/// Number of number slots in an element.
constexpr int kSlots = 8;

/// One element (after lowering: a directional valve is four orifices).
struct Element {
  ElementKind kind = ElementKind::kLaminar;
  std::uint8_t a = 0;            ///< port a: node index
  std::uint8_t b = 0;            ///< port b: node index
  std::int8_t shaft = -1;        ///< machine, torque, friction: shaft index
  /// Orifice only: 0 the opening is the kOpening value; +1 it is max(s, 0) and −1
  /// max(−s, 0) for s the kOpening value (a directional valve's spool position).
  std::int8_t opening_sign = 0;
  Ref r[kSlots]{};               ///< the numbers, by Slot
};

/// What a sensor channel measures.
enum class ChannelKind : std::uint8_t {
  kPressure = 0,  ///< pressure of node `index` [Pa]
  kSpeed = 1,     ///< speed of shaft `index` [rad/s]
  kFlow = 2,      ///< flow a→b of element `index` [m³/s]
};

/// One sensor channel: an output of the model.
struct Channel {
  ChannelKind kind = ChannelKind::kPressure;
  std::uint8_t index = 0;
};

/// A circuit. Counts say how much of each array is used.
template <class Cap>
struct Circuit {
  using Capacity = Cap;
  std::uint8_t n_nodes = 0, n_shafts = 0, n_elements = 0, n_channels = 0, n_inputs = 0, n_params = 0;
  /// Envelope: largest pressure difference [Pa] and shaft speed [rad/s] the machine can
  /// reach. It bounds the guaranteed orifice conductances (stiffness.hpp) and the
  /// plausible states (twice the envelope).
  Ref pressure_max{};
  Ref speed_max{};
  /// Bit i: volume node i is taken quasi-steady (stiffness.hpp's auto_stiff_mask sets it).
  std::uint32_t stiff_mask = 0;
  Node nodes[kExtent<Cap::kNodes>]{};
  Shaft shafts[kExtent<(Cap::kShafts > 0 ? Cap::kShafts : 1)>]{};
  Element elements[kExtent<Cap::kElements>]{};
  Channel channels[kExtent<Cap::kChannels>]{};
};

/// Why a description cannot be used (validate()).
enum class CircuitError : std::uint8_t {
  kOk = 0,
  kCounts,          ///< a count exceeds its capacity
  kBadRef,          ///< a Ref's index is beyond n_params / n_inputs
  kBadPort,         ///< an element port is not a node, or both ports are one node
  kBadShaft,        ///< an element's shaft is missing or not a shaft
  kMissingNumber,   ///< a required number is not given (K or β and V, J, k or A·Cd·ρ, ...)
  kStiffNotVolume,  ///< the stiff mask names a boundary or an unused node
  kTooManyStates,   ///< more states than Cap::kStates, or more unknowns than Cap::kUnknowns
  kBadChannel,      ///< a channel names no node, shaft or element
  kNoEnvelope,      ///< pressure_max or speed_max missing
  kUnbound,         ///< the model has not been given a description
};

/// True when c has an element whose conductance changes steeply at a pressure: a relief or
/// check valve (at its cracking pressure) or a pressure-compensated pump (at its curve's
/// corners). Within one RK4 step such an element can open where the step's start saw it
/// shut (Observer::kStageCheck).
template <class Cap>
constexpr bool has_pressure_thresholds(const Circuit<Cap>& c) noexcept {
  for (int e = 0; e < c.n_elements; ++e) {
    if (c.elements[e].kind == ElementKind::kPoppet || c.elements[e].kind == ElementKind::kCompPump) return true;
  }
  return false;
}

}  // namespace hstmon::circuit
