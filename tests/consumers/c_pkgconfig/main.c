/* A C program built against the installed C API with nothing but pkg-config:
 *   cc main.c $(pkg-config --cflags --libs hstmon-c)
 * A monitor started at the steady state and fed its own estimate stays nominal
 * (../common/steady_ticks.h). */
#include <stdio.h>

#include "../common/steady_ticks.h"

static hstmon_monitor_storage storage;

int main(void) {
  hstmon_monitor* m = NULL;
  const char* failed = consumer_steady_ticks(&storage, &m);
  if (failed != NULL) {
    printf("consumer: %s\n", failed);
    return 1;
  }
  printf("consumer: %d ticks, health %u, diagnosis %s\n", kConsumerTicks, (unsigned)hstmon_health(m),
         hstmon_match_name(hstmon_match_status(m)));
  return 0;
}
