/* Semihosting calls (Arm "Semihosting for AArch32 and AArch64", v2): r0 = operation,
 * r1 = parameter, BKPT 0xAB on M-profile. */
#include "hstmon_mps2/semihosting.h"

#include <stdint.h>

enum {
  SYS_WRITEC = 0x03,
  SYS_WRITE0 = 0x04,
  SYS_EXIT = 0x18, /* angel_SWIreason_ReportException */
  SYS_EXIT_EXTENDED = 0x20,
  ADP_Stopped_ApplicationExit = 0x20026,
  ADP_Stopped_RunTimeErrorUnknown = 0x20023
};

static uintptr_t semihost_call(uintptr_t op, uintptr_t arg) {
  register uintptr_t r0 __asm("r0") = op;
  register uintptr_t r1 __asm("r1") = arg;
  __asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

void semihost_write0(const char* s) { (void)semihost_call(SYS_WRITE0, (uintptr_t)s); }

void semihost_writec(char c) { (void)semihost_call(SYS_WRITEC, (uintptr_t)&c); }

void semihost_exit(int code) {
  if (code == 0) {
    (void)semihost_call(SYS_EXIT, ADP_Stopped_ApplicationExit);
  } else {
    /* On AArch32, SYS_EXIT takes only a reason; the extended call carries the code. */
    const uintptr_t block[2] = {ADP_Stopped_ApplicationExit, (uintptr_t)(uint32_t)code};
    (void)semihost_call(SYS_EXIT_EXTENDED, (uintptr_t)block);
    (void)semihost_call(SYS_EXIT, ADP_Stopped_RunTimeErrorUnknown);
  }
  for (;;) {
  }
}
