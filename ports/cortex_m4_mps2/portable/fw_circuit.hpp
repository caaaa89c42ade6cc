#pragma once
/// @file fw_circuit.hpp
/// The circuit engine in firmware: the circuit comes from a header generated at build time
/// (hstmon-circuit-header; default lib/circuit/include/hstmon/generated/thesis_circuit.hpp), and
/// the float Observer<CircuitModel> runs it. Portable (no registers, no libc I/O, no
/// heap): the Cortex-M4F images and a host float build compile the same code, so their
/// residuals can be compared bit for bit (tests/firmware, firmware.circuit_bitexact).
///
/// Another circuit: generate its header into an include directory and build with
/// HSTMON_FW_CIRCUIT=<name> (the header <name>.hpp, namespace hstmon::generated::<name>;
/// CMake cache variable HSTMON_FW_CIRCUIT, docs/firmware.md).
///
/// With HSTMON_FW_COMPILED=1 the model is the circuit's compiled model instead (the header
/// <name>_compiled.hpp from `hstmon-circuit-header --compiled`, circuit::CompiledModel): the
/// same numbers as the interpreter bit for bit, at a fraction of the instructions per tick
/// (docs/circuits.md, "Compiled circuits"). The footprint and replay images use it.

#include <cstdint>

#include "fw_replay.hpp"
#include "hstmon/circuit/circuit_model.hpp"
#include "hstmon/observer.hpp"

#ifndef HSTMON_FW_CIRCUIT
#define HSTMON_FW_CIRCUIT thesis_circuit
#endif
#ifndef HSTMON_FW_COMPILED
#define HSTMON_FW_COMPILED 0
#endif
#define HSTMON_FW_STR2(x) #x
#define HSTMON_FW_STR(x) HSTMON_FW_STR2(x)
#define HSTMON_FW_CAT2(a, b) a##b
#define HSTMON_FW_CAT(a, b) HSTMON_FW_CAT2(a, b)
#if HSTMON_FW_COMPILED
#include HSTMON_FW_STR(hstmon/generated/HSTMON_FW_CAT(HSTMON_FW_CIRCUIT, _compiled).hpp)
#else
#include HSTMON_FW_STR(hstmon/generated/HSTMON_FW_CIRCUIT.hpp)
#endif

namespace hstmon::fw {

/// The generated circuit's namespace (description, capacity, values).
namespace gen = ::hstmon::generated::HSTMON_FW_CIRCUIT;

/// The observer's tick [s]: HSTMON_FW_TICK where the build sets one (an image at another
/// rate than the header was generated for), else the header's kTick. Either way within the
/// ticks the header's stiff mask holds for (gen::kTickMin … kTickMax).
#ifdef HSTMON_FW_TICK
inline constexpr double kTick = HSTMON_FW_TICK;
#else
inline constexpr double kTick = gen::kTick;
#endif
static_assert(kTick >= gen::kTickMin && kTick <= gen::kTickMax,
              "HSTMON_FW_TICK lies outside the ticks the generated header's stiff mask holds for; regenerate the "
              "header at this tick");

/// The engine's model of the generated circuit, in float, sized by its tight capacity:
/// compiled (HSTMON_FW_COMPILED) or interpreted.
#if HSTMON_FW_COMPILED
using CircuitFwModel = gen::CompiledModel<float>;
#else
using CircuitFwModel = circuit::CircuitModel<float, gen::Cap>;
#endif
/// The observer on it: the general tick on Arm M-profile; on hosts the compiled model's
/// fused usual tick, bit for bit the same (firmware.circuit_bitexact compares the two on a
/// whole log: every tick of its host replay is a usual tick).
using CircuitFwObserver = Observer<CircuitFwModel>;

/// The generated parameter values, rounded to float [SI].
CircuitFwModel::Params circuit_params() noexcept;
/// The generated nominal inputs, rounded to float [SI].
CircuitFwModel::Inputs circuit_inputs() noexcept;

/// Configures obs with the generated circuit (bound in place: no model copy on the
/// stack) at tick kTick and no output injection.
/// @return kOk, or why not (kInvalidParams when the description or values are rejected)
Status configure_circuit_observer(CircuitFwObserver& obs) noexcept;

/// Replays `log` through the circuit observer at kTick — one tick per log row, plus
/// ticks with inputs held and no measurement until the model clock reaches the row —
/// after a reset from the first row's measured states. Writes one line per row,
/// `trace <row> <health> <r0> … <rN-1>` (residuals in %a hex, exact), then
/// `{"type":"circuit_firmware","circuit":…,"rows":…,"ticks":…,"health":…,"residual_digest":"…"}`
/// (FNV-1a 64 over every row's residual bits and health). The log's columns map onto the
/// circuit by LogSignal: the inputs, in order, from p_sup, p_s, p_bp, kp and the channels
/// from p_mi, p_mo, p_pp, w_m (the thesis circuit's; a missing column holds the nominal input).
/// @param obs  the observer (static storage: it is large for a stack)
/// @return the health bits OR-ed over the replay; ~0 if the observer could not be configured
std::uint32_t circuit_replay_trace(CircuitFwObserver& obs, const LogView& log, Sink out) noexcept;

}  // namespace hstmon::fw
