/* SysTick-based counting (see cycles.h). */
#include "hstmon_mps2/cycles.h"

#define SYST_CSR (*(volatile uint32_t*)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t*)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t*)0xE000E018u)

void cycles_start(void) {
  SYST_CSR = 0u;
  SYST_RVR = 0x00FFFFFFu;
  SYST_CVR = 0u;     /* any write clears; reloads from RVR */
  SYST_CSR = 0x5u;   /* ENABLE | CLKSOURCE = processor clock, no interrupt */
}

uint32_t cycles_now(void) { return SYST_CVR & 0x00FFFFFFu; }

uint32_t cycles_elapsed(uint32_t from, uint32_t to) { return (from - to) & 0x00FFFFFFu; }

uint32_t cycles_known_loop(uint32_t n) {
  const uint32_t a = cycles_now();
  /* 2 instructions per iteration (subs, bne), + mov + the final read: fixed and known. */
  __asm volatile(
      "1: subs %0, %0, #1\n\t"
      "bne 1b\n\t"
      : "+r"(n)
      :
      : "cc");
  const uint32_t b = cycles_now();
  return cycles_elapsed(a, b);
}
