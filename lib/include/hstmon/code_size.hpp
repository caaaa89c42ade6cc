#pragma once
/// @file code_size.hpp
/// Inlining policy by target. On microcontrollers (Arm M-profile) flash is the scarce
/// resource: a helper called from every RK4 stage is kept out of line there (one copy,
/// a call per use), while hosts and application processors inline it for speed. The
/// arithmetic is identical either way, so results do not depend on the choice.
/// Override with -DHSTMON_FLASH_LEAN=0 or 1.

#ifndef HSTMON_FLASH_LEAN
#if defined(__ARM_ARCH_PROFILE) && (__ARM_ARCH_PROFILE == 'M')
#define HSTMON_FLASH_LEAN 1
#else
#define HSTMON_FLASH_LEAN 0
#endif
#endif

/// Marks a function to keep out of line where HSTMON_FLASH_LEAN is 1 (GCC, Clang).
#if HSTMON_FLASH_LEAN && defined(__GNUC__)
#define HSTMON_LEAN_NOINLINE __attribute__((noinline))
#else
#define HSTMON_LEAN_NOINLINE
#endif
