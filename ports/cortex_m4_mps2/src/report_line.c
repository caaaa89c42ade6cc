/* The footprint images' JSON line (hstmon_mps2/report_line.h). */
#include "hstmon_mps2/report_line.h"

#include "hstmon_mps2/cycles.h"
#include "hstmon_mps2/semihosting.h"

static char line[768];
static unsigned pos;

static void put(const char* s) {
  while (*s != '\0' && pos + 1u < sizeof line) line[pos++] = *s++;
  line[pos] = '\0';
}

void report_begin(const char* type) {
  pos = 0u;
  put("{\"type\":\"");
  put(type);
  put("\"");
}

void report_uint(const char* key, uint32_t v) {
  char tmp[12];
  int n = 0;
  put(",\"");
  put(key);
  put("\":");
  do {
    tmp[n++] = (char)('0' + (int)(v % 10u));
    v /= 10u;
  } while (v != 0u);
  while (n > 0) {
    const char c[2] = {tmp[--n], '\0'};
    put(c);
  }
}

uint32_t report_calibration(uint32_t n) {
  const uint32_t c1 = cycles_known_loop(n);
  const uint32_t c2 = cycles_known_loop(2u * n);
  report_uint("calib_instructions", 2u * n);
  report_uint("calib_counts", c2 - c1);
  return c2 - c1;
}

void report_end(void) {
  put("}\n");
  semihost_write0(line);
}
