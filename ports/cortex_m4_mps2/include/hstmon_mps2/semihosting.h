/* Semihosting on Cortex-M (BKPT 0xAB): console output and exit through the debugger or
 * QEMU (-semihosting-config enable=on,target=native). Blocking; never allocates.
 * Without a debugger attached a BKPT halts a real part: semihosting is for QEMU and
 * bench boards only. */
#ifndef HSTMON_MPS2_SEMIHOSTING_H
#define HSTMON_MPS2_SEMIHOSTING_H

#ifdef __cplusplus
extern "C" {
#endif

/** Writes a NUL-terminated string to the host console (SYS_WRITE0). */
void semihost_write0(const char* s);
/** Writes one character (SYS_WRITEC). */
void semihost_writec(char c);
/** Ends the program: code 0 → SYS_EXIT with ADP_Stopped_ApplicationExit (QEMU exits 0);
 *  otherwise SYS_EXIT_EXTENDED with the code (QEMU exits with it), falling back to
 *  SYS_EXIT with ADP_Stopped_RunTimeErrorUnknown (QEMU exits 1). Never returns. */
void semihost_exit(int code) __attribute__((noreturn));

#ifdef __cplusplus
}
#endif

#endif
