/* Cortex-M4F startup for QEMU mps2-an386: vector table, reset (copy .data, zero .bss,
 * enable the FPU, run static constructors, call main) and fault handlers. No C library
 * start files (-nostartfiles): nothing here registers atexit handlers or touches a heap. */
#include <stdint.h>

#include "hstmon_mps2/semihosting.h"

extern uint32_t __data_load__[], __data_start__[], __data_end__[];
extern uint32_t __bss_start__[], __bss_end__[];
extern uint32_t __stack_top__[];
typedef void (*init_fn)(void);
extern init_fn __preinit_array_start[], __preinit_array_end[];
extern init_fn __init_array_start[], __init_array_end[];

int main(void);
void Reset_Handler(void);
void Default_Handler(void);
void HardFault_Handler(void);

/* CPACR: full access to coprocessors 10 and 11 (the FPU). Must precede any FP instruction. */
#define SCB_CPACR (*(volatile uint32_t*)0xE000ED88u)

__attribute__((noreturn)) void Reset_Handler(void) {
  SCB_CPACR |= (0xFu << 20);
  __asm volatile("dsb\n\tisb" ::: "memory");
  /* Word loops, volatile so the compiler emits them rather than calls into libc before
   * .data/.bss exist. */
  volatile uint32_t* src = __data_load__;
  for (volatile uint32_t* dst = __data_start__; dst < __data_end__;) *dst++ = *src++;
  for (volatile uint32_t* dst = __bss_start__; dst < __bss_end__;) *dst++ = 0u;
  for (init_fn* f = __preinit_array_start; f < __preinit_array_end; ++f) (*f)();
  for (init_fn* f = __init_array_start; f < __init_array_end; ++f) (*f)();
  semihost_exit(main());
}

void Default_Handler(void) {
  semihost_write0("hstmon fw: unexpected exception\n");
  semihost_exit(3);
}

void HardFault_Handler(void) {
  semihost_write0("hstmon fw: HardFault\n");
  semihost_exit(4);
}

/* Vector table: initial SP, then the 15 system exceptions; external interrupts unused.
 * A union, because ISO C has no conversion between function and object pointers. */
typedef union {
  uint32_t* sp;
  void (*handler)(void);
} vector_entry;

__attribute__((section(".isr_vector"), used)) static const vector_entry vectors[16] = {
    {.sp = __stack_top__},              /* initial main stack pointer */
    {.handler = Reset_Handler},         /* reset */
    {.handler = Default_Handler},       /* NMI */
    {.handler = HardFault_Handler},     /* HardFault */
    {.handler = Default_Handler},       /* MemManage */
    {.handler = Default_Handler},       /* BusFault */
    {.handler = Default_Handler},       /* UsageFault */
    {0}, {0}, {0}, {0},                 /* reserved */
    {.handler = Default_Handler},       /* SVCall */
    {.handler = Default_Handler},       /* DebugMonitor */
    {0},                                /* reserved */
    {.handler = Default_Handler},       /* PendSV */
    {.handler = Default_Handler},       /* SysTick (not enabled as an interrupt) */
};

/* errno for the C library's math wrappers: the matcher's acosf (newlib's wrapper sets
 * errno on a domain error, which cannot happen — the argument is clamped to [-1, 1]).
 * Defining __errno here keeps newlib's errno.o out, and with it its 96-byte reentrancy
 * structure (impure_data) and _impure_ptr: one int of RAM instead of ≈ 100 bytes. */
int* __errno(void);
static int fw_errno;
int* __errno(void) { return &fw_errno; }
