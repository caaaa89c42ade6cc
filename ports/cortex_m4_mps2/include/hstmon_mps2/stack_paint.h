/* Stack depth by painting, for the footprint images: fill the unused stack with a
 * pattern, run the code under test, then find the lowest word it overwrote. The depth of
 * the code is the caller's stack pointer minus stack_low_water(). */
#ifndef HSTMON_MPS2_STACK_PAINT_H
#define HSTMON_MPS2_STACK_PAINT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Fills the stack from its limit (linker symbol __stack_limit__) up to 16 words below
 *  this function's own frame with a pattern. Out of line, so its frame is below the
 *  caller's. */
void stack_paint(void);
/** Lowest stack address written since stack_paint() [byte address]. */
uintptr_t stack_low_water(void);

#ifdef __cplusplus
}
#endif

#endif
