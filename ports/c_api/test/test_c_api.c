/* C test of the hstmon C API, compiled as C11: the header must be plain C, and the
 * monitor must behave through it as through the C++ core (steady state gives zero
 * residuals, bad inputs and NaN are flagged and never propagate). Exit status 0 = pass. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hstmon_c.h"

static int failures = 0;

#define CHECK(cond)                                                   \
  do {                                                                \
    if (!(cond)) {                                                    \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
      ++failures;                                                     \
    }                                                                 \
  } while (0)

static hstmon_monitor_storage storage; /* static: no heap anywhere */

static hstmon_monitor* make_monitor(void) {
  hstmon_config cfg;
  hstmon_monitor* m = NULL;
  hstmon_default_config(&cfg);
  CHECK(hstmon_create(&storage, sizeof storage, &cfg, &m) == HSTMON_OK);
  CHECK(m != NULL);
  return m;
}

/* A sample whose measurements equal the monitor's current estimate. */
static hstmon_sample sample_at_estimate(const hstmon_monitor* m, const hstmon_inputs* u) {
  hstmon_report r;
  hstmon_sample s;
  int i;
  hstmon_read(m, &r);
  memset(&s, 0, sizeof s);
  s.u = *u;
  for (i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = r.estimate[i];
  s.valid = 0x0F;
  return s;
}

static void test_create(void) {
  hstmon_config cfg;
  hstmon_monitor* m = (hstmon_monitor*)&storage; /* must be reset to NULL on failure */
  hstmon_default_config(&cfg);
  CHECK(hstmon_monitor_size() > 0 && hstmon_monitor_size() <= HSTMON_MONITOR_STORAGE_BYTES);
  CHECK(hstmon_create(NULL, sizeof storage, &cfg, &m) == HSTMON_INVALID_CONFIG && m == NULL);
  CHECK(hstmon_create(&storage, hstmon_monitor_size() - 1, &cfg, &m) == HSTMON_INVALID_CONFIG);
  CHECK(hstmon_create(storage.bytes + 1, sizeof storage - 1, &cfg, &m) == HSTMON_INVALID_CONFIG);
  cfg.tick_s = 0.0f;
  CHECK(hstmon_create(&storage, sizeof storage, &cfg, &m) == HSTMON_INVALID_CONFIG && m == NULL);
  hstmon_default_config(&cfg);
  cfg.params.kf = -1.0f;
  CHECK(hstmon_create(&storage, sizeof storage, &cfg, &m) == HSTMON_INVALID_PARAMS && m == NULL);
  hstmon_default_config(&cfg);
  cfg.params.J = NAN;
  CHECK(hstmon_create(&storage, sizeof storage, &cfg, &m) == HSTMON_INVALID_PARAMS && m == NULL);
}

static void test_steady_state_zero_residuals(void) {
  hstmon_monitor* m = make_monitor();
  hstmon_inputs u;
  hstmon_sample s;
  hstmon_report r;
  int k, i;
  hstmon_default_inputs(&u);
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  s = sample_at_estimate(m, &u);
  CHECK(s.y[HSTMON_CH_WM] > 100.0f); /* running: ≈ 1678 rpm = 176 rad/s */
  for (k = 0; k < 1000; ++k) {
    s.t_s = (float)k * 1e-3f;
    CHECK(hstmon_step(m, &s) == 0u);
  }
  hstmon_read(m, &r);
  CHECK(r.ticks == 1000u && r.health == 0u && r.residual_valid == 0x0F && r.substeps == 1u);
  for (i = 0; i < HSTMON_CHANNELS; ++i) {
    /* float steady state: a few ulps of the value, never a drift */
    CHECK(fabsf(r.residual[i]) <= 1e-5f * fabsf(s.y[i]) + 1e-3f);
  }
}

static void test_bad_inputs_flagged(void) {
  hstmon_monitor* m = make_monitor();
  hstmon_inputs u, bad;
  hstmon_sample s;
  hstmon_report r;
  uint32_t h;
  hstmon_default_inputs(&u);
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  bad = u;
  bad.kp = -1e-8f;
  CHECK(hstmon_reset_steady(m, &bad) == HSTMON_INVALID_INPUTS);
  bad.kp = 0.0f;
  CHECK(hstmon_reset_steady(m, &bad) == HSTMON_NO_STEADY_STATE);
  s = sample_at_estimate(m, &u);
  s.u.kp = -1e-8f; /* a negative orifice coefficient is no input */
  h = hstmon_step(m, &s);
  CHECK((h & HSTMON_HEALTH_INPUT_NON_FINITE) != 0u);
  s.u = u;
  s.u.p_sup = INFINITY;
  CHECK((hstmon_step(m, &s) & HSTMON_HEALTH_INPUT_NON_FINITE) != 0u);
  s.u = u;
  CHECK(hstmon_step(m, &s) == 0u); /* last good inputs were held: still healthy */
  hstmon_read(m, &r);
  CHECK((r.health & HSTMON_HEALTH_INPUT_NON_FINITE) != 0u && r.last_health == 0u);
  CHECK(fabsf(r.residual[HSTMON_CH_WM]) < 1e-2f);
}

static void test_nan_measurement_flagged(void) {
  hstmon_monitor* m = make_monitor();
  hstmon_inputs u;
  hstmon_sample s;
  hstmon_report r;
  int i;
  hstmon_default_inputs(&u);
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  s = sample_at_estimate(m, &u);
  s.y[HSTMON_CH_PPP] = NAN;
  CHECK((hstmon_step(m, &s) & HSTMON_HEALTH_MEAS_NON_FINITE) != 0u);
  hstmon_read(m, &r);
  CHECK(r.residual_valid == (0x0F & ~(1u << HSTMON_CH_PPP)));
  CHECK(r.residual[HSTMON_CH_PPP] == 0.0f);
  for (i = 0; i < HSTMON_CHANNELS; ++i) CHECK(isfinite(r.residual[i]) && isfinite(r.estimate[i]));
  /* NaN everywhere, inputs too: flagged, state kept finite, monitor recovers */
  for (i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] = NAN;
  s.u.p_bp = NAN;
  CHECK((hstmon_step(m, &s) & (HSTMON_HEALTH_INPUT_NON_FINITE | HSTMON_HEALTH_MEAS_NON_FINITE)) ==
        (HSTMON_HEALTH_INPUT_NON_FINITE | HSTMON_HEALTH_MEAS_NON_FINITE));
  s = sample_at_estimate(m, &u);
  CHECK(hstmon_step(m, &s) == 0u);
  hstmon_read(m, &r);
  for (i = 0; i < HSTMON_CHANNELS; ++i) CHECK(isfinite(r.estimate[i]));
  /* valid mask 0: the model just advances */
  s.valid = 0;
  CHECK(hstmon_step(m, &s) == 0u);
  hstmon_read(m, &r);
  CHECK(r.residual_valid == 0u);
  /* NULL handles are refused, not dereferenced */
  CHECK(hstmon_step(NULL, &s) == 0u);
  CHECK(hstmon_reset_rest(NULL, &u) == HSTMON_INVALID_INPUTS);
  CHECK(hstmon_health(NULL) == 0u);
}

int main(void) {
  test_create();
  test_steady_state_zero_residuals();
  test_bad_inputs_flagged();
  test_nan_measurement_flagged();
  if (failures != 0) {
    fprintf(stderr, "test_c_api: %d check(s) failed\n", failures);
    return 1;
  }
  printf("test_c_api: all checks passed (monitor %u bytes)\n", (unsigned)hstmon_monitor_size());
  return 0;
}
