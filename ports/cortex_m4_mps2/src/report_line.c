/* The footprint images' JSON line (hstmon_mps2/report_line.h). */
#include "hstmon_mps2/report_line.h"

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

void report_end(void) {
  put("}\n");
  semihost_write0(line);
}
