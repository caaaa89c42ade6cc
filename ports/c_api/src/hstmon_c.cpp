// C API over the float thesis monitor (ports/c_api/include/hstmon_c.h): observer, sensor
// checks, residual evaluator and fault matcher (hstmon::ModelMonitor). A thin layer: copies
// between plain C structs and the core's types, placement-new into the caller's buffer;
// all numerics stay in lib/.
//
// Its model is a build choice; the code below is the same for both:
// - by default the hand-written specialisation of the thesis equations
//   (ThesisReducedModel), which test_thesis_circuit proves equal to the engine on
//   thesis.json (outputs and derivatives to 1e-15, steady states, observers over a start
//   and a kp step): its 128-byte model and static steady solve keep this monitor within the
//   Cortex-M4F budgets (1.5 KiB RAM, 512 B stack), which the engine's 0.7 KB model does not;
// - with HSTMON_C_THESIS_ENGINE defined, the engine's ThesisCircuitModel (thesis.json
//   compiled), for hosts and targets with room (the hstmon_c_engine library;
//   c_api.test_c_api_engine runs the C test on it).
// A circuit's C API on the engine is hstmon_circuit_c.h.
#include "hstmon_c.h"

#include <cstddef>
#include <cstdint>
#include <new>

#include "c_api_copy.hpp"

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/model_monitor.hpp"
#include "hstmon/residual_bounds.hpp"
#include "hstmon/status.hpp"
#if defined(HSTMON_C_THESIS_ENGINE)
#include "hstmon/circuit/thesis_circuit_model.hpp"
#else
#include "hstmon/thesis_reduced.hpp"
#endif

namespace {

// Firmware sizes: every row of the table, 2 queued events of 1 candidate each (the full
// ranking is read live with hstmon_candidates()), so one monitor stays within the M4F's
// 1.5 KiB.
// No usual tick: every tick on the observer's general path, as on the Cortex-M4F (which
// has none), so a C API monitor computes the same bits on every target (qemu_bitexact).
#if defined(HSTMON_C_THESIS_ENGINE)
using ThesisModel = hstmon::ThesisCircuitModel<float>;
#else
using ThesisModel = hstmon::ThesisReducedModel<float>;
#endif
using Mon = hstmon::ModelMonitor<ThesisModel, HSTMON_MAX_FAULTS, HSTMON_EVENT_QUEUE,
                                 HSTMON_EVENT_CANDIDATES, false>;
using Model = Mon::Model;
using Obs = Mon::Obs;

// True when each core enumerator has the value of the C constant in the same place.
template <class Core, std::size_t N>
constexpr bool same_values(const Core (&core)[N], const int (&c)[N]) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    if (static_cast<int>(core[i]) != c[i]) return false;
  }
  return true;
}

}  // namespace

// The object behind the opaque handle.
struct hstmon_monitor {
  Mon mon;
};

static_assert(hstmon::kThesisSignatureCount <= HSTMON_MAX_FAULTS, "the table must fit: raise HSTMON_MAX_FAULTS");
// The C enums mirror the core's; a renumbering there must fail here.
static_assert(same_values({hstmon::MatchStatus::kNominal, hstmon::MatchStatus::kDetected,
                           hstmon::MatchStatus::kIsolated, hstmon::MatchStatus::kAmbiguous,
                           hstmon::MatchStatus::kUnexplained},
                          {HSTMON_MATCH_NOMINAL, HSTMON_MATCH_DETECTED, HSTMON_MATCH_ISOLATED, HSTMON_MATCH_AMBIGUOUS,
                           HSTMON_MATCH_UNEXPLAINED}),
              "hstmon_match differs from hstmon::MatchStatus");
static_assert(same_values({hstmon::MatchEventKind::kDetected, hstmon::MatchEventKind::kIsolated,
                           hstmon::MatchEventKind::kAmbiguous, hstmon::MatchEventKind::kUnexplained,
                           hstmon::MatchEventKind::kCleared},
                          {HSTMON_EVENT_DETECTED, HSTMON_EVENT_ISOLATED, HSTMON_EVENT_AMBIGUOUS,
                           HSTMON_EVENT_UNEXPLAINED, HSTMON_EVENT_CLEARED}),
              "hstmon_event_kind differs from hstmon::MatchEventKind");
static_assert(
    same_values({hstmon::kHealthInputNonFinite, hstmon::kHealthMeasNonFinite, hstmon::kHealthSubstepsClipped,
                 hstmon::kHealthStateNonFinite, hstmon::kHealthStateOutOfBounds, hstmon::kHealthAlgebraicDiverged},
                {HSTMON_HEALTH_INPUT_NON_FINITE, HSTMON_HEALTH_MEAS_NON_FINITE, HSTMON_HEALTH_SUBSTEPS_CLIPPED,
                 HSTMON_HEALTH_STATE_NON_FINITE, HSTMON_HEALTH_STATE_OUT_OF_BOUNDS, HSTMON_HEALTH_ALGEBRAIC_DIVERGED}),
    "health bits differ from hstmon::HealthFlag");

static_assert(sizeof(hstmon_monitor) <= HSTMON_MONITOR_STORAGE_BYTES,
              "raise HSTMON_MONITOR_STORAGE_BYTES in hstmon_c.h");
static_assert(alignof(hstmon_monitor) <= HSTMON_MONITOR_ALIGN, "raise HSTMON_MONITOR_ALIGN in hstmon_c.h");
static_assert(sizeof(hstmon_monitor_storage) >= HSTMON_MONITOR_STORAGE_BYTES &&
                  alignof(hstmon_monitor_storage) >= alignof(hstmon_monitor),
              "hstmon_monitor_storage must hold a monitor");
static_assert(HSTMON_CH_PMI == static_cast<int>(hstmon::kChPmi) && HSTMON_CH_PMO == static_cast<int>(hstmon::kChPmo) && HSTMON_CH_PPP == static_cast<int>(hstmon::kChPpp) &&
                  HSTMON_CH_WM == static_cast<int>(hstmon::kChWm) && HSTMON_CHANNELS == Model::kOutputs,
              "channel order differs from hstmon::ThesisChannel");

// Rarely run paths (create, reset, read, events) are cold for GCC and Clang: optimised
// for size (most of the C API's flash) and kept off the tick path; hstmon_step and what it
// inlines stay at the build's -O2.
#if defined(__GNUC__)
#define HSTMON_C_RARE __attribute__((cold))
#else
#define HSTMON_C_RARE
#endif

namespace {

hstmon_status to_c(hstmon::Status s) noexcept { return static_cast<hstmon_status>(s); }

hstmon::ThesisInputs<float> to_core(const hstmon_inputs& u) noexcept {
  hstmon::ThesisInputs<float> v;
  v.Psupl = u.p_sup;
  v.Ps = u.p_s;
  v.Pbp = u.p_bp;
  v.kp = u.kp;
  return v;
}

hstmon::ThesisParams<float> to_core(const hstmon_params& p) noexcept {
  hstmon::ThesisParams<float> v;
  v.Dm = p.Dm;
  v.Dp = p.Dp;
  v.Rlkg = p.Rlkg;
  v.Ripl = p.Ripl;
  v.Rf = p.Rf;
  v.Rbl = p.Rbl;
  v.kf = p.kf;
  v.J = p.J;
  v.K = p.K;
  v.dp_t_dcv = p.dp_t_dcv;
  v.dp_t_prv = p.dp_t_prv;
  return v;
}

// Construction and configuration in separate frames (noinline): the temporaries of the
// members' constructors and of the configuration are never on the stack together, and
// Monitor::reconfigure sets the observer and the table on the freshly constructed monitor,
// whose other parts keep their default configurations (no Monitor::Config next to the
// model), which keeps hstmon_create's stack depth within the 512-byte budget on the M4F.
__attribute__((noinline)) HSTMON_C_RARE hstmon_monitor* construct(void* buf) noexcept {
  return new (buf) hstmon_monitor{};  // placement: no allocation
}

__attribute__((noinline)) HSTMON_C_RARE hstmon::Status configure(hstmon_monitor& m, const hstmon::ThesisParams<float>& p,
                                                               const hstmon_config& c) noexcept {
  Obs::Config oc;  // the rest (evaluator, sensor checks, matcher, uncertainty): defaults, as `hstmon replay`
  oc.tick = c.tick_s;
  oc.lambda_h_max = c.lambda_h_max;
  oc.max_substeps = c.max_substeps;
  return m.mon.reconfigure(p, oc, hstmon::kThesisSignatures, hstmon::kThesisSignatureCount);
}

}  // namespace

extern "C" {

size_t hstmon_monitor_size(void) { return sizeof(hstmon_monitor); }

HSTMON_C_RARE void hstmon_default_config(hstmon_config* cfg) {
  if (cfg == nullptr) return;
  const hstmon::ThesisParams<float> p;  // Table 2.2
  cfg->params = hstmon_params{p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf, p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
  const Obs::Config c;  // the observer part of Mon::Config; the rest stays at its defaults
  cfg->tick_s = c.tick;
  cfg->lambda_h_max = c.lambda_h_max;
  cfg->max_substeps = c.max_substeps;
}

HSTMON_C_RARE void hstmon_default_inputs(hstmon_inputs* u) {
  if (u == nullptr) return;
  const hstmon::ThesisInputs<float> v;
  *u = hstmon_inputs{v.Psupl, v.Ps, v.Pbp, v.kp};
}

HSTMON_C_RARE hstmon_status hstmon_create(void* buf, size_t size, const hstmon_config* cfg, hstmon_monitor** out) {
  if (out != nullptr) *out = nullptr;
  if (cfg == nullptr || out == nullptr || !hstmon::c_api::buffer_fits<hstmon_monitor>(buf, size)) {
    return HSTMON_INVALID_CONFIG;
  }
  const hstmon::ThesisParams<float> p = to_core(cfg->params);
  // Invalid parameters: reconfigure() refuses them (kInvalidParams) before anything else.
  // On refusal the handle stays NULL; the buffer holds nothing the caller may use.
  hstmon_monitor* m = construct(buf);
  const hstmon::Status s = configure(*m, p, *cfg);
  if (s != hstmon::Status::kOk) {
    m->~hstmon_monitor();
    return to_c(s);
  }
  *out = m;
  return HSTMON_OK;
}

HSTMON_C_RARE hstmon_status hstmon_reset_measured(hstmon_monitor* m, const hstmon_sample* s, uint8_t* start) {
  if (m == nullptr || s == nullptr) return HSTMON_INVALID_INPUTS;
  Obs::Measurement meas;
  meas.y << s->y[0], s->y[1], s->y[2], s->y[3];
  meas.valid = s->valid;
  hstmon::InitialState how = hstmon::InitialState::kRest;
  const hstmon::Status st = m->mon.reset_measured(to_core(s->u), meas, &how);
  if (st == hstmon::Status::kOk && start != nullptr) *start = static_cast<uint8_t>(how);
  return to_c(st);
}

HSTMON_C_RARE hstmon_status hstmon_reset_steady(hstmon_monitor* m, const hstmon_inputs* u) {
  if (m == nullptr || u == nullptr) return HSTMON_INVALID_INPUTS;
  return to_c(m->mon.reset_steady(to_core(*u)));
}

HSTMON_C_RARE hstmon_status hstmon_reset_rest(hstmon_monitor* m, const hstmon_inputs* u) {
  if (m == nullptr || u == nullptr) return HSTMON_INVALID_INPUTS;
  return to_c(m->mon.reset_rest(to_core(*u)));
}

uint32_t hstmon_step(hstmon_monitor* m, const hstmon_sample* s) {
  if (m == nullptr) return 0;
  // No sample: advance the model with the inputs held (nothing valid, the matcher does not
  // run). One call site, so one copy of the step in the image and one frame under it.
  Obs::Measurement meas;
  hstmon::ThesisInputs<float> u = m->mon.observer().model().inputs();
  float t = 0.0f;
  if (s != nullptr) {
    meas.y << s->y[0], s->y[1], s->y[2], s->y[3];
    meas.valid = s->valid;
    u = to_core(s->u);
    t = s->t_s;
  }
  (void)m->mon.step(t, u, meas);
  return m->mon.health();
}

HSTMON_C_RARE void hstmon_read(const hstmon_monitor* m, hstmon_report* r) {
  if (m == nullptr || r == nullptr) return;
  const Obs& obs = m->mon.observer();
  const auto& res = obs.residual();
  const auto& est = obs.estimate();
  for (int i = 0; i < HSTMON_CHANNELS; ++i) {
    r->residual[i] = res[i];
    r->estimate[i] = est[i];
  }
  r->residual_valid = obs.residual_valid();
  r->substeps = obs.substeps();
  r->last_health = obs.last_health();
  r->health = obs.health();
  r->ticks = obs.ticks();
}

uint32_t hstmon_health(const hstmon_monitor* m) { return m != nullptr ? m->mon.observer().health() : 0u; }

hstmon_match hstmon_match_status(const hstmon_monitor* m) {
  return m != nullptr ? static_cast<hstmon_match>(m->mon.matcher().status()) : HSTMON_MATCH_NOMINAL;
}

HSTMON_C_RARE int hstmon_candidates(const hstmon_monitor* m, hstmon_candidate* out, int max) {
  return m != nullptr ? hstmon::c_api::copy_candidates(m->mon.matcher(), out, max) : 0;
}

HSTMON_C_RARE int hstmon_pop_event(hstmon_monitor* m, hstmon_event* out) {
  return m != nullptr ? hstmon::c_api::pop_event(m->mon, out) : 0;
}

uint32_t hstmon_events_dropped(const hstmon_monitor* m) {
  return m != nullptr ? m->mon.matcher().events_dropped() : 0u;
}

// The value is checked as an int before it becomes an enum: a C caller may pass any int.
const char* hstmon_match_name(int s) {
  return s >= HSTMON_MATCH_NOMINAL && s <= HSTMON_MATCH_UNEXPLAINED ? hstmon::to_string(static_cast<hstmon::MatchStatus>(s))
                                                                     : "?";
}

const char* hstmon_event_name(int k) {
  return k >= HSTMON_EVENT_DETECTED && k <= HSTMON_EVENT_CLEARED ? hstmon::to_string(static_cast<hstmon::MatchEventKind>(k))
                                                                  : "?";
}

}  // extern "C"
