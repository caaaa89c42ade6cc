/* Instruction counting on QEMU with SysTick. With `-icount shift=0` QEMU's virtual clock
 * advances exactly 1 ns per executed instruction, and SysTick (processor clock source)
 * counts that clock at the board's 25 MHz; cycles_calibrate() measures the ratio with a
 * loop of a known number of instructions, so the result is in instructions, not ticks.
 * On real silicon SysTick counts core cycles instead. Range: 2^24 SysTick counts per
 * measurement (≈ 6.7e8 instructions under QEMU). */
#ifndef HSTMON_MPS2_CYCLES_H
#define HSTMON_MPS2_CYCLES_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Starts SysTick free-running from 0xFFFFFF (no interrupt). */
void cycles_start(void);
/** Current SysTick count (counts down). */
uint32_t cycles_now(void);
/** Counts elapsed from `from` to `to` (mod 2^24). */
uint32_t cycles_elapsed(uint32_t from, uint32_t to);
/** Runs a loop of exactly 2·n + 2 instructions and returns the SysTick counts it took. */
uint32_t cycles_known_loop(uint32_t n);

#ifdef __cplusplus
}
#endif

#endif
