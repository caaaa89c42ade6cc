// C API over one circuit's float monitor (ports/c_api/include/hstmon_circuit_c.h). The
// circuit and its fault table are generated headers chosen at compile time
// (HSTMON_C_CIRCUIT, HSTMON_C_SIGNATURES: names under hstmon/generated/; with
// HSTMON_C_COMPILED the circuit's compiled model, <HSTMON_C_CIRCUIT>_compiled.hpp); the monitor's
// setup is the firmware's (circuit/generated_setup.hpp). A thin layer: copies between
// plain C structs and the core's types; all numerics stay in lib/.
#include "hstmon_circuit_c.h"

#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>

#include "c_api_copy.hpp"

#include "hstmon/circuit/circuit_monitor.hpp"
#include "hstmon/circuit/generated_setup.hpp"
#include "hstmon/status.hpp"

#ifndef HSTMON_C_CIRCUIT
#error "HSTMON_C_CIRCUIT must name the generated circuit header (e.g. paper_circuit)"
#endif
#ifndef HSTMON_C_SIGNATURES
#error "HSTMON_C_SIGNATURES must name the generated fault table (e.g. paper_signatures)"
#endif
#ifndef HSTMON_C_COMPILED
#define HSTMON_C_COMPILED 0
#endif
#define HSTMON_C_STR2(x) #x
#define HSTMON_C_STR(x) HSTMON_C_STR2(x)
#define HSTMON_C_CAT2(a, b) a##b
#define HSTMON_C_CAT(a, b) HSTMON_C_CAT2(a, b)
#if HSTMON_C_COMPILED
// A path, not an expression: clang-format would space its slashes.
// clang-format off
#include HSTMON_C_STR(hstmon/generated/HSTMON_C_CAT(HSTMON_C_CIRCUIT, _compiled).hpp)
// clang-format on
#else
#include HSTMON_C_STR(hstmon/generated/HSTMON_C_CIRCUIT.hpp)
#endif
#include HSTMON_C_STR(hstmon/generated/HSTMON_C_SIGNATURES.hpp)

namespace {

namespace gen = ::hstmon::generated::HSTMON_C_CIRCUIT;
namespace sig = ::hstmon::generated::HSTMON_C_SIGNATURES;

// The firmware's monitor (fw_circuit_monitor.hpp): the circuit's compiled model or its
// tight capacity's interpreter, exactly the table's rows, 4 queued events, 8 candidates per event.
#if HSTMON_C_COMPILED
using Mon = hstmon::circuit::CompiledCircuitMonitor<float, gen::Kernel, sig::kSignatureCount, 4, 8>;
#else
using Mon = hstmon::circuit::CircuitMonitor<float, gen::Cap, sig::kSignatureCount, 4, 8>;
#endif
using Model = Mon::Model;
using Obs = Mon::Obs;
constexpr int kCh = gen::Cap::kChannels;
constexpr int kIn = gen::Cap::kInputs;

static_assert(sig::kChannels == kCh, "the fault table and the circuit header must come from the same circuit");
static_assert(kCh <= HSTMON_CIRCUIT_MAX_CHANNELS, "a circuit has at most 8 channels");
static_assert(kIn <= HSTMON_CIRCUIT_MAX_INPUTS, "raise HSTMON_CIRCUIT_MAX_INPUTS in hstmon_circuit_c.h");

constexpr hstmon::circuit::GeneratedValues<gen::Cap> kValues{&gen::kCircuit, gen::kParams,  gen::kNoiseSigma,
                                                             gen::kRangeLo,  gen::kRangeHi, gen::kUncertainty,
                                                             gen::kTick};

}  // namespace

// The object behind the opaque handle, in the caller's buffer: the monitor and the model
// its setup solves on.
struct hstmon_circuit_monitor {
  Mon mon;
  Model scratch;
};

// A buffer is dropped or reused without a destructor call.
static_assert(std::is_trivially_destructible<hstmon_circuit_monitor>::value, "the monitor must need no destructor");
static_assert(alignof(hstmon_circuit_monitor) <= HSTMON_CIRCUIT_MONITOR_ALIGN,
              "raise HSTMON_CIRCUIT_MONITOR_ALIGN in hstmon_circuit_c.h");
// MONITOR_BYTES of hstmon_add_circuit_c_api() too small: the template argument in the
// compiler's message is the size this circuit's monitor needs [bytes].
template <std::size_t kNeeded, std::size_t kGiven>
struct MonitorFitsStorage {
  static_assert(kNeeded <= kGiven, "raise MONITOR_BYTES of hstmon_add_circuit_c_api() to kNeeded");
  static constexpr bool value = true;
};
static_assert(MonitorFitsStorage<sizeof(hstmon_circuit_monitor), HSTMON_CIRCUIT_MONITOR_BYTES>::value, "");

namespace {

Model::Inputs to_core(const float* u) noexcept {
  Model::Inputs v;
  for (int i = 0; i < kIn; ++i) v.v[i] = u[i];
  return v;
}

Obs::Measurement to_core(const hstmon_circuit_sample& s) noexcept {
  Obs::Measurement m;
  for (int i = 0; i < kCh; ++i) m.y[i] = s.y[i];
  m.valid = s.valid;
  return m;
}

hstmon_status start_from(hstmon_circuit_monitor& m, const hstmon_circuit_sample& s, uint8_t* how_out) noexcept {
  const Model::Inputs u0 = to_core(s.u);
  hstmon::Status st = hstmon::circuit::configure_from_generated(m.mon, m.scratch, kValues, u0, sig::kSignatures,
                                                                sig::kSignatureCount);
  if (st != hstmon::Status::kOk) return static_cast<hstmon_status>(st);
  hstmon::InitialState how = hstmon::InitialState::kRest;
  st = hstmon::circuit::start_from_first_sample(m.mon, m.scratch, kValues, u0, to_core(s), how);
  if (st == hstmon::Status::kOk && how_out != nullptr) *how_out = static_cast<uint8_t>(how);
  return static_cast<hstmon_status>(st);
}

template <typename T>
T at_or(const T* a, int i, int n, T dflt) noexcept {
  return i >= 0 && i < n ? a[i] : dflt;
}

}  // namespace

extern "C" {

const char* hstmon_circuit_name(void) { return HSTMON_C_STR(HSTMON_C_CIRCUIT); }
float hstmon_circuit_tick(void) { return static_cast<float>(gen::kTick); }
int hstmon_circuit_channels(void) { return gen::kCircuit.n_channels; }
int hstmon_circuit_inputs(void) { return gen::kCircuit.n_inputs; }
int hstmon_circuit_faults(void) { return sig::kSignatureCount; }

const char* hstmon_circuit_channel_column(int i) {
  return at_or<const char*>(gen::kChannelColumns, i, gen::kCircuit.n_channels, nullptr);
}
const char* hstmon_circuit_input_column(int i) {
  return at_or<const char*>(gen::kInputColumns, i, gen::kCircuit.n_inputs, nullptr);
}
double hstmon_circuit_channel_unit_scale(int i) {
  return at_or(gen::kChannelUnitScale, i, gen::kCircuit.n_channels, 0.0);
}
double hstmon_circuit_input_unit_scale(int i) { return at_or(gen::kInputUnitScale, i, gen::kCircuit.n_inputs, 0.0); }

void hstmon_circuit_nominal_inputs(float* u) {
  if (u == nullptr) return;
  for (int i = 0; i < gen::kCircuit.n_inputs; ++i) u[i] = static_cast<float>(gen::kInputs[i]);
}

hstmon_status hstmon_circuit_create(void* buf, size_t size, const hstmon_circuit_sample* first,
                                    hstmon_circuit_monitor** out, uint8_t* start) {
  if (out != nullptr) *out = nullptr;
  if (first == nullptr || out == nullptr || !hstmon::c_api::buffer_fits<hstmon_circuit_monitor>(buf, size)) {
    return HSTMON_INVALID_CONFIG;
  }
  auto* m = new (buf) hstmon_circuit_monitor();
  const hstmon_status s = start_from(*m, *first, start);
  if (s == HSTMON_OK) *out = m;
  return s;
}

hstmon_status hstmon_circuit_reset_steady(hstmon_circuit_monitor* m, const float* u) {
  if (m == nullptr || u == nullptr) return HSTMON_INVALID_INPUTS;
  return static_cast<hstmon_status>(m->mon.reset_steady(to_core(u)));
}

size_t hstmon_circuit_monitor_size(void) { return sizeof(hstmon_circuit_monitor); }

hstmon_status hstmon_circuit_restart(hstmon_circuit_monitor* m, const hstmon_circuit_sample* s, uint8_t* start) {
  if (m == nullptr || s == nullptr) return HSTMON_INVALID_CONFIG;
  return start_from(*m, *s, start);
}

uint32_t hstmon_circuit_step(hstmon_circuit_monitor* m, const hstmon_circuit_sample* s) {
  if (m == nullptr) return 0;
  if (s == nullptr) {  // no sample: inputs held, nothing measured
    (void)m->mon.step(0.0f, m->mon.observer().model().inputs(), Obs::Measurement{});
  } else {
    (void)m->mon.step(s->t_s, to_core(s->u), to_core(*s));
  }
  return m->mon.health();
}

void hstmon_circuit_read(const hstmon_circuit_monitor* m, hstmon_circuit_report* r) {
  if (m == nullptr || r == nullptr) return;
  const Obs& obs = m->mon.observer();
  for (int i = 0; i < HSTMON_CIRCUIT_MAX_CHANNELS; ++i) {
    r->residual[i] = i < kCh ? obs.residual()[i] : 0.0f;
    r->estimate[i] = i < kCh ? obs.estimate()[i] : 0.0f;
  }
  r->residual_valid = obs.residual_valid();
  r->substeps = obs.substeps();
  r->last_health = obs.last_health();
  r->health = obs.health();
  r->ticks = obs.ticks();
}

hstmon_match hstmon_circuit_match_status(const hstmon_circuit_monitor* m) {
  return m != nullptr ? static_cast<hstmon_match>(m->mon.matcher().status()) : HSTMON_MATCH_NOMINAL;
}

int hstmon_circuit_candidates(const hstmon_circuit_monitor* m, hstmon_candidate* out, int max) {
  return m != nullptr ? hstmon::c_api::copy_candidates(m->mon.matcher(), out, max) : 0;
}

int hstmon_circuit_pop_event(hstmon_circuit_monitor* m, hstmon_event* out) {
  return m != nullptr ? hstmon::c_api::pop_event(m->mon, out) : 0;
}

uint32_t hstmon_circuit_events_dropped(const hstmon_circuit_monitor* m) {
  return m != nullptr ? m->mon.matcher().events_dropped() : 0u;
}

}  // extern "C"
