/* C test of the circuit C API (hstmon_circuit_c.h), compiled as C11, built for the paper's
 * HST (paper_circuit + paper_signatures). It replays a log of that circuit as a C
 * program on a controller would — columns found by the names the API gives, converted to
 * SI with its unit scales, one hstmon_circuit_step() per row — and checks what the same
 * log gives through `hstmon replay --circuit` and the firmware image: no event before the
 * fault, then a detection and an isolation whose best candidate is the expected fault.
 * Also: counts and names come from the circuit; a monitor lives in a buffer the caller
 * owns (a small or misaligned one is refused, two are independent); NULL and NaN never
 * crash or propagate.
 *   test_circuit_c_api LOG.csv EXPECTED_FAULT FAULT_TIME_S
 * Exit status 0 = pass. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_check.h"
#include "hstmon_circuit_c.h"

int failures = 0;

#define MAX_COLS 32
#define MAX_ROWS 20000

static double data[MAX_ROWS][MAX_COLS];
static char names[MAX_COLS][32];

/* Reads a CSV with '#' comment lines and one header row "name[unit],…"; names are kept
 * without their unit. Returns the row count, or -1. */
static int read_csv(const char* path, int* cols) {
  static char line[4096];
  int rows = 0;
  int have_header = 0;
  FILE* f = fopen(path, "r");
  if (f == NULL) return -1;
  *cols = 0;
  while (fgets(line, sizeof line, f) != NULL) {
    char* p = line;
    int c = 0;
    if (line[0] == '#' || line[0] == '\n') continue;
    if (!have_header) {
      char* tok = strtok(line, ",\r\n");
      while (tok != NULL && c < MAX_COLS) {
        size_t n = strcspn(tok, "[");
        if (n >= sizeof names[0]) n = sizeof names[0] - 1;
        memcpy(names[c], tok, n);
        names[c][n] = '\0';
        ++c;
        tok = strtok(NULL, ",\r\n");
      }
      *cols = c;
      have_header = 1;
      continue;
    }
    if (rows >= MAX_ROWS) break;
    for (c = 0; c < *cols; ++c) {
      char* end = NULL;
      data[rows][c] = strtod(p, &end);
      if (end == p) {
        fclose(f);
        return -1;
      }
      p = end + (*end == ',' ? 1 : 0);
    }
    ++rows;
  }
  fclose(f);
  return rows;
}

static int column(const char* name, int cols) {
  int c;
  for (c = 0; c < cols; ++c) {
    if (strcmp(names[c], name) == 0) return c;
  }
  return -1;
}

static void test_describes_the_circuit(void) {
  float u[HSTMON_CIRCUIT_MAX_INPUTS];
  int i;
  CHECK(strcmp(hstmon_circuit_name(), "paper_circuit") == 0);
  CHECK(hstmon_circuit_channels() == 4 && hstmon_circuit_inputs() == 2);
  CHECK(hstmon_circuit_faults() > 0);
  CHECK(fabsf(hstmon_circuit_tick() - 0.005f) < 1e-9f);
  CHECK(strcmp(hstmon_circuit_channel_column(1), "p_mi") == 0);
  CHECK(strcmp(hstmon_circuit_input_column(0), "a_dcv") == 0);
  CHECK(hstmon_circuit_channel_column(4) == NULL && hstmon_circuit_input_column(-1) == NULL);
  CHECK(hstmon_circuit_channel_unit_scale(1) == 1e5);       /* bar */
  CHECK(fabs(hstmon_circuit_input_unit_scale(0) - 1e-6) < 1e-18); /* mm² */
  CHECK(hstmon_circuit_channel_unit_scale(9) == 0.0);
  hstmon_circuit_nominal_inputs(u);
  for (i = 0; i < hstmon_circuit_inputs(); ++i) CHECK(u[i] > 0.0f);
}

/* The monitors live in buffers the caller owns (two: each is independent of the other). */
static hstmon_circuit_monitor_storage g_buf[2];

static void test_bad_calls_never_crash(void) {
  hstmon_circuit_report r;
  hstmon_circuit_sample s;
  hstmon_event e;
  hstmon_circuit_monitor* m = (hstmon_circuit_monitor*)&r; /* must be set to NULL */
  memset(&s, 0, sizeof s);
  hstmon_circuit_nominal_inputs(s.u);
  CHECK(hstmon_circuit_monitor_size() > 0u && hstmon_circuit_monitor_size() <= sizeof g_buf[0]);
  CHECK(hstmon_circuit_create(g_buf[0].bytes, sizeof g_buf[0], NULL, &m, NULL) == HSTMON_INVALID_CONFIG && m == NULL);
  m = (hstmon_circuit_monitor*)&r;
  CHECK(hstmon_circuit_create(NULL, sizeof g_buf[0], &s, &m, NULL) == HSTMON_INVALID_CONFIG && m == NULL);
  m = (hstmon_circuit_monitor*)&r;
  /* Too small by one byte, or misaligned: refused. */
  CHECK(hstmon_circuit_create(g_buf[0].bytes, hstmon_circuit_monitor_size() - 1u, &s, &m, NULL) ==
            HSTMON_INVALID_CONFIG &&
        m == NULL);
  CHECK(hstmon_circuit_create(g_buf[0].bytes + 1, sizeof g_buf[0] - 1u, &s, &m, NULL) == HSTMON_INVALID_CONFIG &&
        m == NULL);
  CHECK(hstmon_circuit_step(NULL, NULL) == 0u);
  hstmon_circuit_read(NULL, &r);
  CHECK(hstmon_circuit_match_status(NULL) == HSTMON_MATCH_NOMINAL);
  CHECK(hstmon_circuit_pop_event(NULL, &e) == 0);
  CHECK(hstmon_circuit_candidates(NULL, NULL, 0) == 0);
  CHECK(hstmon_circuit_restart(NULL, &s, NULL) == HSTMON_INVALID_CONFIG);
}

static void replay(const char* path, const char* expect, double t_fault) {
  int cols = 0;
  const int rows = read_csv(path, &cols);
  const int n_ch = hstmon_circuit_channels();
  const int n_in = hstmon_circuit_inputs();
  int ch_col[HSTMON_CIRCUIT_MAX_CHANNELS], in_col[HSTMON_CIRCUIT_MAX_INPUTS];
  int t_col, k, i;
  hstmon_circuit_sample s, last;
  hstmon_circuit_monitor* m = NULL;
  hstmon_circuit_monitor* second = NULL;
  hstmon_circuit_report r;
  hstmon_event e;
  uint8_t start = 99;
  int early = 0, detected = 0, isolated = 0;
  double t_iso = -1.0;
  CHECK(rows > 100);
  if (rows <= 100) return;
  t_col = column("t", cols);
  CHECK(t_col >= 0);
  for (i = 0; i < n_ch; ++i) CHECK((ch_col[i] = column(hstmon_circuit_channel_column(i), cols)) >= 0);
  for (i = 0; i < n_in; ++i) CHECK((in_col[i] = column(hstmon_circuit_input_column(i), cols)) >= 0);
  if (failures > 0) return;
  for (k = 0; k < rows; ++k) {
    memset(&s, 0, sizeof s);
    s.t_s = (float)data[k][t_col];
    for (i = 0; i < n_in; ++i) s.u[i] = (float)(data[k][in_col[i]] * hstmon_circuit_input_unit_scale(i));
    for (i = 0; i < n_ch; ++i) s.y[i] = (float)(data[k][ch_col[i]] * hstmon_circuit_channel_unit_scale(i));
    s.valid = (uint8_t)((1u << n_ch) - 1u);
    if (k == 0) {
      CHECK(hstmon_circuit_create(g_buf[0].bytes, sizeof g_buf[0], &s, &m, &start) == HSTMON_OK &&
            m == (hstmon_circuit_monitor*)(void*)g_buf[0].bytes);
      CHECK(start <= HSTMON_START_STEADY);
      if (m == NULL) return;
    }
    CHECK(hstmon_circuit_step(m, &s) == 0u);
    while (hstmon_circuit_pop_event(m, &e)) {
      const char* best = e.count > 0 ? e.candidate[0].name : "-";
      printf("t=%.3f %s best=%s consistent=%u\n", (double)e.t_s, hstmon_event_name(e.kind), best,
             (unsigned)e.consistent);
      if ((double)e.t_s < t_fault) ++early;
      if (e.kind == HSTMON_EVENT_DETECTED) ++detected;
      if (e.kind == HSTMON_EVENT_ISOLATED && isolated == 0) {
        isolated = strcmp(best, expect) == 0 ? 1 : -1;
        t_iso = (double)e.t_s;
      }
    }
  }
  printf("rows %d, start %u, isolated %s at %.3f s\n", rows, (unsigned)start, isolated > 0 ? expect : "-", t_iso);
  CHECK(early == 0);
  CHECK(detected >= 1);
  CHECK(isolated == 1);
  CHECK(hstmon_circuit_events_dropped(m) == 0u);
  hstmon_circuit_read(m, &r);
  CHECK(r.ticks == (uint64_t)rows && r.health == 0u && r.residual_valid == (uint8_t)((1u << n_ch) - 1u));
  for (i = n_ch; i < HSTMON_CIRCUIT_MAX_CHANNELS; ++i) CHECK(r.residual[i] == 0.0f);

  /* A NaN reading is flagged, never propagated; a tick without a sample advances. */
  last = s;
  s.y[0] = NAN;
  CHECK((hstmon_circuit_step(m, &s) & HSTMON_HEALTH_MEAS_NON_FINITE) != 0u);
  (void)hstmon_circuit_step(m, NULL);
  hstmon_circuit_read(m, &r);
  for (i = 0; i < n_ch; ++i) CHECK(isfinite(r.estimate[i]));

  /* A second monitor in its own buffer leaves the first alone; a restart starts afresh. */
  CHECK(hstmon_circuit_create(g_buf[1].bytes, sizeof g_buf[1], &last, &second, NULL) == HSTMON_OK && second != NULL);
  if (second != NULL) {
    (void)hstmon_circuit_step(second, &last);
    hstmon_circuit_read(m, &r);
    CHECK(r.ticks == (uint64_t)rows + 2u);
    CHECK(hstmon_circuit_restart(second, &last, &start) == HSTMON_OK);
    hstmon_circuit_read(second, &r);
    CHECK(r.ticks == 0u);
  }
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: test_circuit_c_api LOG.csv EXPECTED_FAULT FAULT_TIME_S\n");
    return 2;
  }
  test_describes_the_circuit();
  test_bad_calls_never_crash();
  replay(argv[1], argv[2], atof(argv[3]));
  if (failures != 0) {
    fprintf(stderr, "%d check(s) failed\n", failures);
    return 1;
  }
  printf("test_circuit_c_api: all checks passed\n");
  return 0;
}
