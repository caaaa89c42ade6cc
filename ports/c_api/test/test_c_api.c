/* C test of the hstmon C API, compiled as C11: the header must be plain C, and the
 * monitor must behave through it as through the C++ core (steady state gives zero
 * residuals and a nominal diagnosis, bad inputs and NaN are flagged and never propagate,
 * a large Ppp deviation is detected and gets a candidate set, a NaN sensor is isolated as
 * that sensor). Exit status 0 = pass. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "c_check.h"
#include "hstmon_c.h"

int failures = 0;

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

/* Sensor-like scatter around base: ±50 Pa, ±0.05 rad/s alternating (a constant value
 * would be flagged as a stuck sensor after stuck_time = 0.1 s, 100 samples at 1 ms). */
static const float kDither[HSTMON_CHANNELS] = {50.0f, -50.0f, 50.0f, 0.05f};
static void dither(hstmon_sample* s, const float* base, int k) {
  int i;
  for (i = 0; i < HSTMON_CHANNELS; ++i) s->y[i] = base[i] + ((k & 1) ? kDither[i] : -kDither[i]);
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
  float base[HSTMON_CHANNELS];
  int k, i;
  hstmon_default_inputs(&u);
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  s = sample_at_estimate(m, &u);
  memcpy(base, s.y, sizeof base);
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
  /* the exact same value 1000 times is a stuck sensor: flagged, only sensor rows left */
  CHECK(hstmon_match_status(m) != HSTMON_MATCH_NOMINAL);
  /* with sensor scatter the diagnosis stays nominal, residuals stay at the scatter */
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  for (k = 0; k < 1000; ++k) {
    s.t_s = (float)k * 1e-3f;
    dither(&s, base, k);
    CHECK(hstmon_step(m, &s) == 0u);
  }
  hstmon_read(m, &r);
  for (i = 0; i < HSTMON_CHANNELS; ++i) CHECK(fabsf(r.residual[i]) <= 1.01f * fabsf(kDither[i]) + 1e-5f * fabsf(base[i]));
  /* the diagnosis: nothing happened */
  CHECK(hstmon_match_status(m) == HSTMON_MATCH_NOMINAL);
  CHECK(hstmon_candidates(m, NULL, 0) == 0);
  {
    hstmon_event e;
    CHECK(hstmon_pop_event(m, &e) == 0);
  }
  CHECK(strcmp(hstmon_match_name(HSTMON_MATCH_NOMINAL), "nominal") == 0);
  CHECK(strcmp(hstmon_event_name(HSTMON_EVENT_CLEARED), "cleared") == 0);
}

/* Ppp measured 10 bar above the model for 0.3 s: the CUSUM alarms on Ppp, the matcher
 * detects an episode with candidates (hypotheses whose Ppp rises), then decides. */
static void test_ppp_jump_detected(void) {
  hstmon_monitor* m = make_monitor();
  hstmon_inputs u;
  hstmon_sample s;
  hstmon_event e;
  hstmon_candidate c[HSTMON_MAX_FAULTS];
  float base[HSTMON_CHANNELS];
  int k, n, events = 0, detected = 0, decided = 0, total;
  float t_detected = -1.0f;
  hstmon_default_inputs(&u);
  CHECK(hstmon_reset_steady(m, &u) == HSTMON_OK);
  s = sample_at_estimate(m, &u);
  memcpy(base, s.y, sizeof base);
  for (k = 0; k < 100; ++k) { /* 0.1 s nominal: the baseline */
    s.t_s = (float)k * 1e-3f;
    dither(&s, base, k);
    CHECK(hstmon_step(m, &s) == 0u);
  }
  CHECK(hstmon_match_status(m) == HSTMON_MATCH_NOMINAL);
  base[HSTMON_CH_PPP] += 10e5f; /* +10 bar: ≫ the model bound (≈ 5 bar) + CUSUM threshold */
  for (k = 100; k < 400; ++k) {
    s.t_s = (float)k * 1e-3f;
    dither(&s, base, k);
    CHECK(hstmon_step(m, &s) == 0u); /* a diagnosis is no health problem of the observer */
    while (hstmon_pop_event(m, &e)) {
      ++events;
      if (e.kind == HSTMON_EVENT_DETECTED) {
        ++detected;
        t_detected = e.t_s;
        CHECK(e.consistent >= 1 && e.count == 1 && e.candidate[0].name != NULL);
        CHECK(e.candidate[0].score >= -1.0f && e.candidate[0].score <= 1.0f);
      } else if (e.kind != HSTMON_EVENT_CLEARED) {
        ++decided;
        CHECK(e.t_s > t_detected && t_detected >= 0.1f);
      }
    }
  }
  CHECK(detected == 1 && events >= 1 && decided >= 1);
  CHECK(hstmon_events_dropped(m) == 0u); /* popped every tick: nothing lost */
  CHECK(hstmon_match_status(m) != HSTMON_MATCH_NOMINAL);
  total = hstmon_candidates(m, c, HSTMON_MAX_FAULTS);
  CHECK(total >= 1 || hstmon_match_status(m) == HSTMON_MATCH_UNEXPLAINED);
  for (n = 0; n < total && n < HSTMON_MAX_FAULTS; ++n) {
    CHECK(c[n].name != NULL && strlen(c[n].name) > 0);
    if (n > 0) CHECK(c[n].score <= c[n - 1].score); /* best first */
  }
  CHECK(hstmon_candidates(m, c, 1) == total); /* the total, whatever max */
  printf("test_c_api: Ppp +10 bar: detected at %.3f s, status %s, %d candidate(s)%s%s\n", (double)t_detected,
         hstmon_match_name(hstmon_match_status(m)), total, total > 0 ? ", best " : "", total > 0 ? c[0].name : "");
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
#if defined(HSTMON_C_THESIS_ENGINE)
  /* The engine finds the stall with the PRV shut (w_m = 0); the specialisation has none. */
  CHECK(hstmon_reset_steady(m, &bad) == HSTMON_OK);
#else
  CHECK(hstmon_reset_steady(m, &bad) == HSTMON_NO_STEADY_STATE);
#endif
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
  {
    /* the sensor check flags Ppp: only its sensor row remains, isolated at once */
    hstmon_candidate c[2];
    hstmon_event e;
    CHECK(hstmon_match_status(m) == HSTMON_MATCH_ISOLATED);
    CHECK(hstmon_candidates(m, c, 2) == 1 && strcmp(c[0].name, "sensor_p_pp") == 0);
    CHECK(hstmon_pop_event(m, &e) == 1 && e.kind == HSTMON_EVENT_DETECTED);
    CHECK(hstmon_pop_event(m, &e) == 1 && e.kind == HSTMON_EVENT_ISOLATED && e.count == 1 &&
          strcmp(e.candidate[0].name, "sensor_p_pp") == 0);
    CHECK(hstmon_pop_event(m, &e) == 0);
  }
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
  CHECK(hstmon_match_status(NULL) == HSTMON_MATCH_NOMINAL);
  CHECK(hstmon_candidates(NULL, NULL, 0) == 0);
  CHECK(hstmon_pop_event(NULL, NULL) == 0);
}

/* Names of every status and event kind, and "?" for any other int — C lets a caller
 * pass one (an uninitialised variable, a corrupted message); it must be range-checked as a
 * number, not loaded as the enum type (UBSan: invalid enum load). */
static void test_names_of_any_int(void) {
  static const char* const kMatch[] = {"nominal", "detected", "isolated", "ambiguous", "unexplained"};
  static const char* const kEvent[] = {"detected", "isolated", "ambiguous", "unexplained", "cleared"};
  static const int kOutside[] = {-1, 5, 7, 8, 99, 255, 256, INT_MAX, INT_MIN};
  int i;
  for (i = HSTMON_MATCH_NOMINAL; i <= HSTMON_MATCH_UNEXPLAINED; ++i) CHECK(strcmp(hstmon_match_name(i), kMatch[i]) == 0);
  for (i = HSTMON_EVENT_DETECTED; i <= HSTMON_EVENT_CLEARED; ++i) CHECK(strcmp(hstmon_event_name(i), kEvent[i]) == 0);
  CHECK(strcmp(hstmon_match_name(HSTMON_MATCH_ISOLATED), "isolated") == 0); /* the enum converts */
  for (i = 0; i < (int)(sizeof kOutside / sizeof kOutside[0]); ++i) {
    CHECK(strcmp(hstmon_match_name(kOutside[i]), "?") == 0);
    CHECK(strcmp(hstmon_event_name(kOutside[i]), "?") == 0);
  }
}

/* A log that begins with the machine at rest while the supply is already on: the monitor
 * starts from the measured states, and the start-up that follows is not a fault. */
static void test_reset_measured_start_from_rest(void) {
  hstmon_monitor* m = make_monitor();
  hstmon_sample s;
  hstmon_event e;
  uint8_t start = 99;
  int k;
  memset(&s, 0, sizeof s);
  hstmon_default_inputs(&s.u);
  s.y[HSTMON_CH_PPP] = s.u.p_bp; /* at rest: Ppp at the booster, pressures at 0 bar */
  s.valid = 0x0F;
  CHECK(hstmon_reset_measured(NULL, &s, &start) == HSTMON_INVALID_INPUTS);
  CHECK(hstmon_reset_measured(m, NULL, &start) == HSTMON_INVALID_INPUTS);
  CHECK(hstmon_reset_measured(m, &s, &start) == HSTMON_OK && start == HSTMON_START_MEASURED);
  CHECK(hstmon_reset_measured(m, &s, NULL) == HSTMON_OK);
  /* the first sample (0 bar at the motor while the model says 35 bar) is not judged */
  CHECK(hstmon_step(m, &s) == 0u);
  CHECK(hstmon_match_status(m) == HSTMON_MATCH_NOMINAL);
  /* the machine then follows the model: nothing is raised */
  for (k = 1; k < 500; ++k) {
    int i;
    s = sample_at_estimate(m, &s.u);
    for (i = 0; i < HSTMON_CHANNELS; ++i) s.y[i] += (k & 1) ? kDither[i] : -kDither[i];
    s.t_s = (float)k * 1e-3f;
    (void)hstmon_step(m, &s);
  }
  CHECK(hstmon_match_status(m) == HSTMON_MATCH_NOMINAL);
  CHECK(hstmon_pop_event(m, &e) == 0);
}

int main(void) {
  test_create();
  test_names_of_any_int();
  test_steady_state_zero_residuals();
  test_ppp_jump_detected();
  test_bad_inputs_flagged();
  test_nan_measurement_flagged();
  test_reset_measured_start_from_rest();
  if (failures != 0) {
    fprintf(stderr, "test_c_api: %d check(s) failed\n", failures);
    return 1;
  }
  printf("test_c_api: all checks passed (monitor %u bytes)\n", (unsigned)hstmon_monitor_size());
  return 0;
}
