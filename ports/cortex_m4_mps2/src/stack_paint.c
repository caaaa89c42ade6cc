/* Stack depth by painting (hstmon_mps2/stack_paint.h). */
#include "hstmon_mps2/stack_paint.h"

extern uint32_t __stack_limit__[];
#define STACK_PAINT 0xA5A5A5A5u

__attribute__((noinline)) void stack_paint(void) {
  uint32_t* sp;
  __asm volatile("mov %0, sp" : "=r"(sp));
  for (volatile uint32_t* p = __stack_limit__; p < sp - 16; ++p) *p = STACK_PAINT;
}

uintptr_t stack_low_water(void) {
  const uint32_t* p = __stack_limit__;
  while (*p == STACK_PAINT) ++p;
  return (uintptr_t)p;
}
