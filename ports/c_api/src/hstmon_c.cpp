// C API over the float thesis observer (ports/c_api/include/hstmon_c.h). A thin layer:
// copies between plain C structs and the core's types, placement-new into the caller's
// buffer; all numerics stay in lib/.
#include "hstmon_c.h"

#include <cstdint>
#include <new>

#include "hstmon/observer.hpp"
#include "hstmon/status.hpp"
#include "hstmon/thesis_reduced.hpp"

namespace {

using Model = hstmon::ThesisReducedModel<float>;
using Obs = hstmon::Observer<Model>;

}  // namespace

// The object behind the opaque handle. Later stages of issue 4 (residual evaluation, the
// fault matcher) become members here and are stepped from hstmon_step(); the C structs
// grow fields, the calling pattern stays.
struct hstmon_monitor {
  Obs obs;
};

static_assert(sizeof(hstmon_monitor) <= HSTMON_MONITOR_STORAGE_BYTES,
              "raise HSTMON_MONITOR_STORAGE_BYTES in hstmon_c.h");
static_assert(alignof(hstmon_monitor) <= HSTMON_MONITOR_ALIGN, "raise HSTMON_MONITOR_ALIGN in hstmon_c.h");
static_assert(sizeof(hstmon_monitor_storage) >= HSTMON_MONITOR_STORAGE_BYTES &&
                  alignof(hstmon_monitor_storage) >= alignof(hstmon_monitor),
              "hstmon_monitor_storage must hold a monitor");
// The C enums mirror the core's; a renumbering there must fail here.
static_assert(HSTMON_HEALTH_INPUT_NON_FINITE == static_cast<int>(hstmon::kHealthInputNonFinite) &&
                  HSTMON_HEALTH_MEAS_NON_FINITE == static_cast<int>(hstmon::kHealthMeasNonFinite) &&
                  HSTMON_HEALTH_SUBSTEPS_CLIPPED == static_cast<int>(hstmon::kHealthSubstepsClipped) &&
                  HSTMON_HEALTH_STATE_NON_FINITE == static_cast<int>(hstmon::kHealthStateNonFinite) &&
                  HSTMON_HEALTH_STATE_OUT_OF_BOUNDS == static_cast<int>(hstmon::kHealthStateOutOfBounds) &&
                  HSTMON_HEALTH_ALGEBRAIC_DIVERGED == static_cast<int>(hstmon::kHealthAlgebraicDiverged),
              "health bits differ from hstmon::HealthFlag");
static_assert(HSTMON_CH_PMI == static_cast<int>(hstmon::kChPmi) && HSTMON_CH_PMO == static_cast<int>(hstmon::kChPmo) && HSTMON_CH_PPP == static_cast<int>(hstmon::kChPpp) &&
                  HSTMON_CH_WM == static_cast<int>(hstmon::kChWm) && HSTMON_CHANNELS == Model::kOutputs,
              "channel order differs from hstmon::ThesisChannel");

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

}  // namespace

extern "C" {

size_t hstmon_monitor_size(void) { return sizeof(hstmon_monitor); }

void hstmon_default_config(hstmon_config* cfg) {
  if (cfg == nullptr) return;
  const hstmon::ThesisParams<float> p;  // Table 2.2
  cfg->params = hstmon_params{p.Dm, p.Dp, p.Rlkg, p.Ripl, p.Rf, p.Rbl, p.kf, p.J, p.K, p.dp_t_dcv, p.dp_t_prv};
  const Obs::Config c;
  cfg->tick_s = c.tick;
  cfg->lambda_h_max = c.lambda_h_max;
  cfg->max_substeps = c.max_substeps;
}

void hstmon_default_inputs(hstmon_inputs* u) {
  if (u == nullptr) return;
  const hstmon::ThesisInputs<float> v;
  *u = hstmon_inputs{v.Psupl, v.Ps, v.Pbp, v.kp};
}

hstmon_status hstmon_create(void* buf, size_t size, const hstmon_config* cfg, hstmon_monitor** out) {
  if (out != nullptr) *out = nullptr;
  if (buf == nullptr || cfg == nullptr || out == nullptr || size < sizeof(hstmon_monitor) ||
      reinterpret_cast<std::uintptr_t>(buf) % alignof(hstmon_monitor) != 0) {
    return HSTMON_INVALID_CONFIG;
  }
  const hstmon::ThesisParams<float> p = to_core(cfg->params);
  if (!Model::params_valid(p)) return HSTMON_INVALID_PARAMS;
  Obs::Config oc;
  oc.tick = cfg->tick_s;
  oc.lambda_h_max = cfg->lambda_h_max;
  oc.max_substeps = cfg->max_substeps;
  // On refusal the handle stays NULL; the buffer holds nothing the caller may use.
  auto* m = new (buf) hstmon_monitor{};  // placement: no allocation
  const hstmon::Status s = m->obs.configure(Model(p), oc);
  if (s != hstmon::Status::kOk) {
    m->~hstmon_monitor();
    return to_c(s);
  }
  *out = m;
  return HSTMON_OK;
}

hstmon_status hstmon_reset_steady(hstmon_monitor* m, const hstmon_inputs* u) {
  if (m == nullptr || u == nullptr) return HSTMON_INVALID_INPUTS;
  return to_c(m->obs.reset_steady(to_core(*u)));
}

hstmon_status hstmon_reset_rest(hstmon_monitor* m, const hstmon_inputs* u) {
  if (m == nullptr || u == nullptr) return HSTMON_INVALID_INPUTS;
  return to_c(m->obs.reset_rest(to_core(*u)));
}

uint32_t hstmon_step(hstmon_monitor* m, const hstmon_sample* s) {
  if (m == nullptr) return 0;
  if (s == nullptr) {  // no sample: advance the model with the inputs held
    return m->obs.step(m->obs.model().inputs(), Obs::Measurement{});
  }
  Obs::Measurement meas;
  meas.y << s->y[0], s->y[1], s->y[2], s->y[3];
  meas.valid = s->valid;
  return m->obs.step(to_core(s->u), meas);
}

void hstmon_read(const hstmon_monitor* m, hstmon_report* r) {
  if (m == nullptr || r == nullptr) return;
  const auto& res = m->obs.residual();
  const auto& est = m->obs.estimate();
  for (int i = 0; i < HSTMON_CHANNELS; ++i) {
    r->residual[i] = res[i];
    r->estimate[i] = est[i];
  }
  r->residual_valid = m->obs.residual_valid();
  r->substeps = m->obs.substeps();
  r->last_health = m->obs.last_health();
  r->health = m->obs.health();
  r->ticks = m->obs.ticks();
}

uint32_t hstmon_health(const hstmon_monitor* m) { return m != nullptr ? m->obs.health() : 0u; }

}  // extern "C"
