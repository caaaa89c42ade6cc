/* The one JSON line a footprint image prints: {"type":"…","key":N,…}, unsigned fields
 * only, built in a static buffer (768 bytes; longer lines are cut) and written over
 * semihosting. One line at a time. */
#ifndef HSTMON_MPS2_REPORT_LINE_H
#define HSTMON_MPS2_REPORT_LINE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Starts the line: {"type":"<type>". */
void report_begin(const char* type);
/** Appends ,"<key>":<v> (decimal). */
void report_uint(const char* key, uint32_t v);
/** Appends the SysTick calibration: ,"calib_instructions":2n,"calib_counts":C, where C is
 *  what a loop of 2n+2 instructions took minus one of n+1 (cycles_known_loop); the
 *  difference removes the fixed cost of the call and reads. instructions per count =
 *  2n / C, as a ratio (scripts/footprint.sh converts the counts with it).
 *  @return C */
uint32_t report_calibration(uint32_t n);
/** Closes the line with }\n and writes it (semihost_write0). */
void report_end(void);

#ifdef __cplusplus
}
#endif

#endif
